"""Calibration from measured single-particle strengths (docs/calibration.md): a CSV of grains (diameter,
force at failure), the criterion's stress of each at failure by the closed form of a sphere between
platens (closedform), and the model's ft0, m and Weibull modulus fitted to every grain at once by
maximum likelihood (strengths.sizeLawFit: sigma_i Weibull with scale ft0 r_i^-m). Written as JSON and as
a one-row yade-batch table that the oedometer and the study tables read. No YADE."""
import json
import math
import os

import numpy as np
import pandas as pd

from ...engineparams import CRUSH
from ...params import ParamError, validate
from .closedform import STRESS_PER_F_OVER_D2, criterionStress
from .strengths import sizeLawFit

# accepted columns and their factor to SI units
DIAMETER_COLUMNS = {'diameter': 1.0, 'diameter_m': 1.0, 'diameter_mm': 1e-3}
FORCE_COLUMNS = {'force': 1.0, 'force_N': 1.0, 'force_kN': 1e3}


# the crushing engine's largest Weibull modulus (params.CRUSH): a fit above it is taken as no scatter
KMAX_SCATTER = 50.0


class CalibrationError(ValueError):
    """A measured-strengths file that cannot be read; the message names the file and the row."""


def _column(frame, path, choices, what):
    found = [c for c in choices if c in frame.columns]
    if len(found) != 1:
        raise CalibrationError('%s: expected one %s column, one of %s; the columns are %s' % (
            path, what, ', '.join(choices), ', '.join(map(str, frame.columns)) or 'none'))
    return found[0]


def readMeasured(path):
    """(diameters [m], forces [N]) of a CSV with a header: a diameter column (diameter or diameter_m [m],
    diameter_mm [mm]) and a force column (force or force_N [N], force_kN [kN]), one row per grain; other
    columns are ignored. A missing file, a missing column, or a row whose value is not a finite number > 0
    raises CalibrationError naming the file and the row (its line in the file)."""
    try:
        frame = pd.read_csv(path, dtype=str, skipinitialspace=True)
    except FileNotFoundError:
        raise CalibrationError('%s: no such file' % path) from None
    except (pd.errors.ParserError, pd.errors.EmptyDataError, UnicodeDecodeError) as e:
        raise CalibrationError('%s: not a CSV with a header row: %s' % (path, str(e).splitlines()[0])) from None
    dc, fc = _column(frame, path, DIAMETER_COLUMNS, 'diameter'), _column(frame, path, FORCE_COLUMNS, 'force')
    if len(frame) < 3:
        raise CalibrationError('%s: %d grain(s); a fit needs at least 3' % (path, len(frame)))
    values = {}
    for col, scale in ((dc, DIAMETER_COLUMNS[dc]), (fc, FORCE_COLUMNS[fc])):
        out = []
        for k, cell in enumerate(frame[col]):
            try:
                v = float(cell)
            except (TypeError, ValueError):
                v = math.nan
            if not (math.isfinite(v) and v > 0):
                raise CalibrationError('%s:%d: %s = %r is not allowed: expected a finite number > 0' % (
                    path, k + 2, col, cell))
            out.append(v * scale)
        values[col] = np.array(out)
    return values[dc], values[fc]


def calibrate(d, force, criterion):
    """The fitted model for `criterion`: {criterion, n, ft0 [Pa m^m], m, weibullModulus (0: no scatter), each
    with its 95 % interval}. ParamError where a fitted value is outside what the crushing engine allows."""
    criterion = validate('calibration', {'criterion': CRUSH['criterion']}, 'criterion', criterion)
    fit = sizeLawFit(np.asarray(d) / 2, criterionStress(criterion, force, d))
    k = fit['k']
    if k > KMAX_SCATTER:  # less scatter than the engine's largest Weibull modulus represents: none
        k = math.inf
    out = {'criterion': criterion, 'n': fit['n'], 'ft0': fit['s0'], 'ft0Low': fit['s0Low'], 'ft0High': fit['s0High'],
           'm': fit['b'], 'mLow': fit['bLow'], 'mHigh': fit['bHigh'],
           'weibullModulus': 0.0 if math.isinf(k) else k, 'weibullModulusLow': 0.0 if math.isinf(k) else fit['kLow'],
           'weibullModulusHigh': 0.0 if math.isinf(k) else fit['kHigh'],
           'stressPerForceOverD2': STRESS_PER_F_OVER_D2[criterion]}
    for name in ('ft0', 'm', 'weibullModulus'):
        try:
            validate('calibration', CRUSH, name, out[name])
        except ParamError as e:
            raise ParamError(name, '%s (the fit of %d grains; the model cannot take it)' % (e, fit['n'])) from None
    return out


def modelParameters(fit):
    """The fitted values as parameters of the oedometer and of this test."""
    return {k: fit[k] for k in ('ft0', 'm', 'weibullModulus', 'criterion')}


def write(fit, out):
    """calibration.json (the fit) and calibration.table (one row the study tables and yade-batch read)."""
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, 'calibration.json'), 'w') as fh:
        json.dump(fit, fh, indent=1)
    p = modelParameters(fit)
    with open(os.path.join(out, 'calibration.table'), 'w') as fh:
        fh.write('# ft0, m and the Weibull modulus fitted to %d single-particle strengths (%s)\n' % (fit['n'],
                                                                                                fit['criterion']))
        fh.write('description ft0 m weibullModulus criterion\n')
        fh.write("calibrated %.9g %.9g %.9g '%s'\n" % (p['ft0'], p['m'], p['weibullModulus'], p['criterion']))
    return [os.path.join(out, f) for f in ('calibration.json', 'calibration.table')]


def commandLine(fit):
    """The options that give the oedometer (or this test) the fitted model."""
    p = modelParameters(fit)
    return '--ft0 %.6g --m %.6g --weibullModulus %.6g --criterion %s' % (p['ft0'], p['m'], p['weibullModulus'],
                                                                       p['criterion'])
