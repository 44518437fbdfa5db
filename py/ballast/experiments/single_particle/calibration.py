"""Calibration from measured single-particle strengths (docs/calibration.md): a CSV of grains (diameter,
force at failure), the criterion's stress of each at failure by the closed form of a sphere between
platens (closedform), and the model's ft0, m and Weibull modulus fitted to every grain at once by
maximum likelihood (strengths.sizeLawFit: sigma_i Weibull with scale ft0 r_i^-m). Written as JSON and as
a one-row yade-batch table that the oedometer and the study tables read. No YADE."""
import csv
import io
import json
import math
import os

import numpy as np

from ... import textfile
from ...engineparams import CRUSH
from ...params import ParamError, validate
from .closedform import STRESS_PER_F_OVER_D2, criterionStress
from .parameters import DIAMETERS  # the sizes of ballast grains and their fragments [m]
from .strengths import NO_SCATTER, sizeLawFit

# accepted columns and their factor to SI units
DIAMETER_COLUMNS = {'diameter': 1.0, 'diameter_m': 1.0, 'diameter_mm': 1e-3}
FORCE_COLUMNS = {'force': 1.0, 'force_N': 1.0, 'force_kN': 1e3}


class CalibrationError(ValueError):
    """A measured-strengths file that cannot be read; the message names the file and the row."""


# a column that names each grain: read past, never used
ID_COLUMNS = ('grain',)
# the criterion stress of a grain at failure [Pa]: rock's tensile strength is 1-30 MPa; outside this band the
# forces are not in the units their column names
STRESS_RANGE = (1e5, 1e9)


def _header(path, names):
    """The columns of the header (its line 1): each named, known, once; ours the diameter's and the force's."""
    names = [n.strip() for n in names]
    known = list(DIAMETER_COLUMNS) + list(FORCE_COLUMNS) + list(ID_COLUMNS)
    for k, n in enumerate(names):
        if not n:
            raise CalibrationError('%s:1: column %d has no name: name it (%s) or remove it' % (
                path, k + 1, ', '.join(known)))
        if n not in known:
            raise CalibrationError('%s:1: column %r is not allowed: the columns are a diameter (%s), a force (%s) '
                                   'and optionally %s' % (path, n, ', '.join(DIAMETER_COLUMNS),
                                                          ', '.join(FORCE_COLUMNS), ', '.join(ID_COLUMNS)))
        if names.index(n) != k:
            raise CalibrationError('%s:1: column %r appears twice' % (path, n))
    for choices, what in ((DIAMETER_COLUMNS, 'diameter'), (FORCE_COLUMNS, 'force')):
        found = [n for n in names if n in choices]
        if len(found) != 1:
            raise CalibrationError('%s:1: expected one %s column, one of %s; the columns are %s' % (
                path, what, ', '.join(choices), ', '.join(names) or 'none'))
    return names


def readMeasured(path):
    """(diameters [m], forces [N]) of a CSV with a header: a diameter column (diameter or diameter_m [m],
    diameter_mm [mm]), a force column (force or force_N [N], force_kN [kN]) and optionally a grain column
    (an identifier, not read), one row per grain and nothing else. Raises CalibrationError naming the file
    and the line: a missing file, an unnamed, unknown or repeated column, a row with another number of
    fields than the header (a trailing comma, an unnamed column), a value that is not a finite number > 0,
    a diameter outside the sizes of ballast grains or a strength outside rock's (the wrong unit, with a
    hint)."""
    try:
        rows = [(n, r) for n, r in _numbered(csv.reader(io.StringIO(textfile.read(path), newline=''),
                                                         skipinitialspace=True)) if any(c.strip() for c in r)]
    except FileNotFoundError:
        raise CalibrationError('%s: no such file' % path) from None
    except IsADirectoryError:
        raise CalibrationError('%s: a folder, not a CSV file' % path) from None
    except textfile.NotText as e:
        raise CalibrationError('%s (a CSV text file is expected)' % e) from None
    except csv.Error as e:
        raise CalibrationError('%s: not a CSV text file: %s' % (path, str(e).splitlines()[0])) from None
    if not rows:
        raise CalibrationError('%s: empty: expected a header row (diameter,force) and a row per grain' % path)
    names = _header(path, rows[0][1])
    dc = next(n for n in names if n in DIAMETER_COLUMNS)
    fc = next(n for n in names if n in FORCE_COLUMNS)
    d, force = [], []
    for line, r in rows[1:]:
        if len(r) != len(names):
            raise CalibrationError('%s:%d: %d fields, the header has %d (%s)%s' % (
                path, line, len(r), len(names), ','.join(names),
                ': a trailing comma?' if len(r) == len(names) + 1 and not r[-1].strip() else ''))
        for col, scale, out in ((dc, DIAMETER_COLUMNS[dc], d), (fc, FORCE_COLUMNS[fc], force)):
            cell = r[names.index(col)].strip()
            try:
                v = float(cell)
            except ValueError:
                v = math.nan
            if not (math.isfinite(v) and v > 0):
                raise CalibrationError('%s:%d: %s = %r is not allowed: expected a finite number > 0' % (
                    path, line, col, cell))
            out.append((v * scale, line, cell))
    if len(d) < 3:
        raise CalibrationError('%s: %d grain(s); a fit needs at least 3' % (path, len(d)))
    lo, hi = DIAMETERS
    for (v, line, cell) in d:
        if not lo <= v <= hi:
            raise CalibrationError('%s:%d: %s = %s is %.3g m, outside %g-%g m, the sizes of ballast grains and their '
                                   'fragments: %s' % (path, line, dc, cell, v, lo, hi, 'in mm? name the column '
                                                      'diameter_mm' if dc != 'diameter_mm' else 'in m? name the column diameter'))
    for (dv, _, _), (fv, line, cell) in zip(d, force):
        sigma = STRESS_PER_F_OVER_D2['vonMises'] * fv / dv ** 2
        if not STRESS_RANGE[0] <= sigma <= STRESS_RANGE[1]:
            raise CalibrationError('%s:%d: %s = %s on a %.3g mm grain is a stress at failure of %.3g Pa, outside %g-%g '
                                   'Pa, the strengths of rock: %s' % (
                                       path, line, fc, cell, 1e3 * dv, sigma, STRESS_RANGE[0], STRESS_RANGE[1],
                                       'in kN? name the column force_kN' if fc != 'force_kN' else 'in N? name the column force'))
    return np.array([v for v, _, _ in d]), np.array([v for v, _, _ in force])


def _numbered(reader):
    """(line of the file where a row starts, row) for each row of a csv.reader."""
    start = 1
    for row in reader:
        yield start, row
        start = reader.line_num + 1


def calibrate(d, force, criterion, rRef=None):
    """The fitted model for `criterion`: {criterion, n, ft0 [Pa m^m], m, weibullModulus (0: no scatter), each
    with its 95 % interval; rRef [m] and ftRef [Pa], the characteristic strength ft0 / rRef^m at the grains'
    size with its interval}. ft0 is the strength at r = 1 m, far outside the grains, where the uncertainty of
    m makes its interval wide; at rRef (default: the geometric mean of the measured radii, where the fit is
    best determined) the interval says what the data say. ParamError where a fitted value is outside what the
    crushing engine allows."""
    criterion = validate('calibration', {'criterion': CRUSH['criterion']}, 'criterion', criterion)
    r, sigma = np.asarray(d) / 2, criterionStress(criterion, force, d)
    fit = sizeLawFit(r, sigma)
    rRef = float(np.exp(np.mean(np.log(r)))) if rRef is None else float(rRef)
    atRef = sizeLawFit(r / rRef, sigma)  # the same law with r in units of rRef: its s0 is the strength at rRef
    k = fit['k']
    if k > NO_SCATTER:  # less scatter than the engine's largest Weibull modulus represents: none
        k = math.inf
    out = {'criterion': criterion, 'n': fit['n'], 'ft0': fit['s0'], 'ft0Low': fit['s0Low'], 'ft0High': fit['s0High'],
           'm': fit['b'], 'mLow': fit['bLow'], 'mHigh': fit['bHigh'],
           'weibullModulus': 0.0 if math.isinf(k) else k, 'weibullModulusLow': 0.0 if math.isinf(k) else fit['kLow'],
           'weibullModulusHigh': 0.0 if math.isinf(k) else fit['kHigh'],
           'rRef': rRef, 'ftRef': atRef['s0'], 'ftRefLow': atRef['s0Low'], 'ftRefHigh': atRef['s0High'],
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
