"""What the per-check log and the crushes of an oedometer run say (docs/studies.md, "Fig. 4 at the
paper's size" and "The force network before the first crush, against f"): the checks that crushed,
how far above their strength the grains were when they crushed, the applied force at the first crush
(the onset) and the largest sigma/f_t at half the peak load (the force network before any crush).
The oedometer's declaration merges :func:`checkStats` into every summary a study reads (its
``derived``); runs.csv and stats.csv carry them. NumPy, no YADE.
"""
import math

import numpy as np

from ...runfiles import column
from .loadcurve import halfLoadTime, loadCurve, peakTime

HALF_LOAD_GAP = 0.05  # [-] the widest gap in applied force, over Fmax, halfLoadRatio interpolates across
CHECK_STATS = ('crushingChecks', 'crushesPerCrushingCheck', 'ratioAtCrushMax', 'ratioAtCrushMean',
               'forceAtFirstCrush', 'stressRatioAtHalfLoad', 'crushesAfterPeak')  # checkStats' keys


def checkStats(run):
    """Of a run (ballast.study.data.Run: a run folder or a record, whose checks.csv keeps every check
    that crushed): from the per-check log the checks that crushed and the grains each crushed on
    average; from the crushes the largest and the mean sigma/f_t of the grains when they crushed (how
    far above their strength rare checks find grains; the log's maxStressRatio also counts fragments
    below r_min, which never crush); with the run's parameters (f, Fmax, Fmin) the applied force when
    the first grain crushed (eq. 8 at its time: quasi-static loading gives a seed the same onset at
    every frequency), the crushes after the peak of the applied force (t > 1/(2f): what delta at the
    peak does not see), and stressRatioAtHalfLoad (halfLoadRatio). {} without a log."""
    c = run.checks
    if c is None or 'crushes' not in c:
        return {}
    crushed = column(c, 'crushes')
    hit = crushed[crushed > 0]
    n = int(hit.size)
    out = dict.fromkeys(CHECK_STATS)
    out.update(crushingChecks=n, crushesPerCrushingCheck=float(np.mean(hit)) if n else None)
    crushes = run.crushes
    times = column(crushes, 't') if crushes is not None else np.array([])
    ratios = column(crushes, 'ratio') if crushes is not None else np.array([])
    first = float(np.min(times)) if ratios.size else math.inf  # the first crush's time [s]
    params = run.params
    loading = params and all(k in params for k in ('f', 'Fmax'))
    if loading:
        load = (float(params['Fmax']), float(params.get('Fmin', 0.0)), float(params['f']))
        out['stressRatioAtHalfLoad'] = halfLoadRatio(c, *load, firstCrush=first)
    if params and 'f' in params and crushes is not None:
        out['crushesAfterPeak'] = int(np.sum(times > peakTime(float(params['f']))))
    if ratios.size:
        out.update(ratioAtCrushMax=float(np.max(ratios)), ratioAtCrushMean=float(np.mean(ratios)))
        if loading:
            out['forceAtFirstCrush'] = loadCurve(*load, first)
    return out


def halfLoadRatio(checks, Fmax, Fmin, f, firstCrush):
    """The largest sigma/f_t of a grain when the applied force first passes Fmax/2 (eq. 8: at t = 1/(4f)),
    from the per-check log `checks` (columns t, maxStressRatio: a DataFrame or a dict of arrays),
    interpolated in the applied force between the checks on either side. Before any crush it measures
    the force network alone: how unevenly the sample carries the same load (a record keeps both
    checks, the declaration's recordTimes). None if a grain crushed before the later of the two checks,
    if the log has no check on one side, or if the two are more than HALF_LOAD_GAP Fmax apart: the ratio
    grows less than in proportion to the load, and a long chord falls short of it (by 0.02-0.07 with
    checks 0.01-0.04 s apart at 4 Hz)."""
    t = np.asarray(checks['t'], dtype=float)
    half = halfLoadTime(f)
    before, after = np.flatnonzero(t <= half), np.flatnonzero(t >= half)
    if not before.size or not after.size or firstCrush < t[after[0]]:
        return None
    i, j = before[-1], after[0]
    r = np.asarray(checks['maxStressRatio'], dtype=float)
    if i == j:
        return float(r[i])
    Fi, Fj = loadCurve(Fmax, Fmin, f, t[[i, j]])
    if Fj - Fi > HALF_LOAD_GAP * Fmax:
        return None
    return float(r[i] + (r[j] - r[i]) * (Fmax / 2 - Fi) / (Fj - Fi))
