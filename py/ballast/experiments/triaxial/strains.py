"""Strains of a triaxial specimen from its boundary, and the measured curves they are held against (docs/triaxial.md,
"Outputs"): compression positive, as the laboratory reports them. Needs no YADE."""
import csv
import io
import math

import numpy as np

from ... import textfile

# what a measured curve's file holds: N, then one strain column (a fraction), as ../shared/data's files do
REFERENCE_COLUMNS = {'axial': 'axial_strain', 'volumetric': 'volumetric_strain'}


def axialStrain(H0, H):
    """Axial strain [-]: the specimen's shortening over its height at the start, (H0 - H) / H0."""
    return (H0 - H) / H0


def volumetricStrain(V0, V):
    """Volumetric strain [-]: the loss of volume over the volume at the start, (V0 - V) / V0 (compression
    positive)."""
    return (V0 - V) / V0


def resilientModulus(qRange, resilientAxialStrain):
    """The resilient modulus M_r = (q_max - q_min) / resilient axial strain [Pa]; NaN without resilient strain."""
    return qRange / resilientAxialStrain if resilientAxialStrain > 0 else math.nan


class CurveError(ValueError):
    """A measured curve's file that cannot be read as one, with the file and line named."""


def readReference(path):
    """A measured curve: (kind 'axial' or 'volumetric', N [cycles], strain [-]) from a CSV with a header `N,<column>`
    (REFERENCE_COLUMNS) and rows of numbers, N >= 1 and rising (equal N allowed, read in order), strains finite and
    within (-1, 1). CurveError naming the file and the line of the first fault."""
    try:
        rows = list(csv.reader(io.StringIO(textfile.read(path), newline='')))
    except OSError as e:
        raise CurveError('%s: cannot be read (%s)' % (path, e.strerror or e)) from None
    except textfile.NotText as e:
        raise CurveError(str(e)) from None
    if not rows:
        raise CurveError('%s: empty; expected a header N,%s or N,%s and rows of numbers' % (
            path, *REFERENCE_COLUMNS.values()))
    header = [h.strip() for h in rows[0]]
    kinds = {v: k for k, v in REFERENCE_COLUMNS.items()}
    if len(header) != 2 or header[0] != 'N' or header[1] not in kinds:
        raise CurveError('%s, line 1: header %r; expected N,%s or N,%s' % (
            path, ','.join(header), *REFERENCE_COLUMNS.values()))
    N, strain = [], []
    for k, row in enumerate(rows[1:], start=2):
        if not row or all(not c.strip() for c in row):
            continue
        if len(row) != 2:
            raise CurveError('%s, line %d: %d fields; expected 2 (N and %s)' % (path, k, len(row), header[1]))
        try:
            n, e = float(row[0]), float(row[1])
        except ValueError:
            raise CurveError('%s, line %d: %r is not two numbers' % (path, k, ','.join(row))) from None
        if not (math.isfinite(n) and n >= 1):
            raise CurveError('%s, line %d: N = %r; expected a cycle count from 1' % (path, k, row[0]))
        if N and n < N[-1]:
            raise CurveError('%s, line %d: N = %g after %g; expected N rising' % (path, k, n, N[-1]))
        if not (math.isfinite(e) and -1 < e < 1):
            raise CurveError('%s, line %d: %s = %r; expected a strain as a fraction, within (-1, 1)' % (
                path, k, header[1], row[1]))
        N.append(n)
        strain.append(e)
    if len(N) < 2:
        raise CurveError('%s: %d rows of numbers; a curve needs at least 2' % (path, len(N)))
    return kinds[header[1]], np.array(N), np.array(strain)


def atCycles(N, strain, at):
    """The curve (N, strain) read at the cycles `at` by linear interpolation in log N; NaN outside its range."""
    x = np.log(np.asarray(N, float))
    out = np.interp(np.log(np.asarray(at, float)), x, np.asarray(strain, float), left=math.nan, right=math.nan)
    return out
