"""The force network at half the peak load against the loading rate (docs/studies.md, "The force
network before the first crush, against f"; Fig. 4): each realization is loaded by eq. 8 only up to
t = 1/(4f), where the applied force passes Fmax/2, well below the first crush (980 kN or more in the
Fig. 4 runs), so a sweep over seeds, frequencies and damping costs a quarter period per run instead of
a cycle. The sweep is a study (studies/halfload.table: the oedometer with stopAt = STOP_AT, run by
scripts/study.py). Per run, read from the study: the largest sigma/f_t of a grain there
(checks.halfLoadRatio of the per-check log), the grains' force on the plate, delta, and how far the
sample is from equilibrium (YADE's unbalanced force, the grains' rms speed): the columns of the
sweep's CSV. The CSV the sweep wrote before it was a study (docs/studies/halfload/runs.csv) is read
as well.
"""
import csv
import math
import os

import numpy as np

from ..experiments.oedometer.loadcurve import halfLoadTime
from ..study.aggregate import fmt
from ..runfiles import column
from ..study.data import StudyRuns, readTable
from ..experiments.oedometer.checkstats import HALF_LOAD_GAP
from .figures import writeFigure
from .pairs import common

STOP_AT = halfLoadTime(1.0)  # [load periods] the oedometer's stopAt of the sweep: eq. 8 passes Fmax/2 at T/4
COLUMNS = [('seed', '-'), ('f', 'Hz'), ('damping', '-'), ('stressRatioAtHalfLoad', '-'), ('Fapplied', 'N'), ('F', 'N'),
           ('delta', 'm'), ('unbalanced', '-'), ('vRms', 'm/s'), ('steps', '-'), ('cpuSeconds', 's')]
HEADER = ['%s [%s]' % c for c in COLUMNS]
# the columns a run's summary.json holds under another name: the state where the loading stopped, the CPU time
FROM_SUMMARY = {'Fapplied': 'appliedFinal', 'F': 'forceFinal', 'delta': 'deltaFinal', 'unbalanced': 'unbalancedFinal',
                'vRms': 'vRmsFinal', 'cpuSeconds': 'cpuSeconds'}


def checkRun(params, name):
    """The half-load sweep's conditions on a run's parameters (`name` says which run): stopped at Fmax/2
    (stopAt = STOP_AT), and checked often enough there: the two checks around 1/(4f) must lie within
    HALF_LOAD_GAP Fmax of each other (eq. 8 rises by pi f Fmax Tc between them). ValueError otherwise."""
    if params.get('stopAt') != STOP_AT:
        raise ValueError("run %s: stopAt = %r, not the half-load sweep's %g (studies/halfload.table)" % (
            name, params.get('stopAt'), STOP_AT))
    if params['Tc'] * math.pi * params['f'] > HALF_LOAD_GAP:
        raise ValueError('run %s: Tc = %r s checks too rarely at f = %r Hz: the two checks around 1/(4f) must lie '
                         'within %g Fmax (Tc < %.3g s, or 0: every step)' % (
                             name, params['Tc'], params['f'], HALF_LOAD_GAP, HALF_LOAD_GAP / (math.pi * params['f'])))


def runRow(run):
    """The sweep's row (COLUMNS' names) of a finished run of a study (ballast.study.data.Run, its summary
    with the oedometer's derived results merged in, as StudyRuns reads it). ValueError for a run that
    is not the sweep's (checkRun) or whose summary lacks the state at its end (a run of an oedometer
    before the Final entries)."""
    s, p, name = run.summary, run.params, run.runId or run.dir
    checkRun(p, name)
    missing = [k for k in FROM_SUMMARY.values() if k not in s]
    if missing:
        raise ValueError('run %s: its summary.json has no %s (made by an older oedometer)' % (name, ', '.join(missing)))
    row = {'seed': p['seed'], 'f': p['f'], 'damping': p['damping'], 'stressRatioAtHalfLoad': s.get('stressRatioAtHalfLoad'),
           'steps': s['stepsByPhase']['load']}
    row.update((col, s[key]) for col, key in FROM_SUMMARY.items())
    return row


def read(path):
    """The sweep as a DataFrame of floats, a row per run, the COLUMNS (a run without the ratio: NaN).
    path: a study folder (a study directory or its records: every finished run, in table order) or the
    sweep's CSV (HEADER; an empty cell is NaN)."""
    import pandas
    if os.path.isdir(path):
        rows = [runRow(r) for r in StudyRuns(path, experiment='oedometer').runs]
        return pandas.DataFrame({name: np.array([np.nan if r[name] is None else r[name] for r in rows], dtype=float)
                                 for name, _ in COLUMNS})
    c = readTable(path)
    return pandas.DataFrame({name: column(c, '%s [%s]' % (name, unit)) for name, unit in COLUMNS})


def write(runs, path):
    """The sweep's CSV (HEADER, cells by aggregate.fmt; the seed and the steps as integers) of the
    DataFrame `runs` (read) at path; returns path."""
    whole = ('seed', 'steps')
    with open(path, 'w', newline='') as fh:
        w = csv.writer(fh)
        w.writerow(HEADER)
        for r in runs.itertuples(index=False):
            w.writerow([fmt(int(v) if name in whole and np.isfinite(v) else float(v)) for (name, _), v in zip(COLUMNS, r)])
    return path


def summarize(runs):
    """Of the sweep `runs` (a DataFrame of read(), or a path read() takes), per damping: the
    frequencies, the seeds, the matrices (a row per seed, a column per f, NaN where missing) of the
    ratio and of the unbalanced force, the ratio's mean, the medians of the unbalanced force and of the
    rms speed per f, and the within-seed test of the ratio across f (effects.withinSeeds, Page's trend
    along f) over the seeds that have every f (None with fewer than 3 frequencies or 2 such seeds). For
    every damping but the lowest, under riseAgainstBase: per seed, the rise of the ratio from the lowest
    to the highest f at the lowest damping minus its rise at this one; their mean, standard error and
    Wilcoxon's signed-rank p (does the damping change the rate effect?)."""
    from scipy import stats

    from .effects import withinSeeds
    c = read(runs) if isinstance(runs, str) else runs
    out = {}
    for d in np.unique(c['damping']):
        mine = c['damping'] == d
        fs, seeds = np.unique(c['f'][mine]), np.unique(c['seed'][mine])
        m = {q: np.full((len(seeds), len(fs)), np.nan) for q in ('stressRatioAtHalfLoad', 'unbalanced', 'vRms')}
        for k in np.flatnonzero(mine):
            for q in m:
                m[q][np.searchsorted(seeds, c['seed'][k]), np.searchsorted(fs, c['f'][k])] = c[q][k]
        full = ~np.isnan(m['stressRatioAtHalfLoad']).any(axis=1)
        test = withinSeeds(m['stressRatioAtHalfLoad'][full], True, '-') if len(fs) >= 3 and full.sum() >= 2 else None
        out[float(d)] = {'f': fs, 'seeds': seeds.astype(int), 'ratio': m['stressRatioAtHalfLoad'], 'unbalanced': m['unbalanced'],
                         'ratioMean': np.nanmean(m['stressRatioAtHalfLoad'], axis=0),
                         'unbalancedMedian': np.nanmedian(m['unbalanced'], axis=0),
                         'vRmsMedian': np.nanmedian(m['vRms'], axis=0), 'test': test}
    base = min(out) if out else None
    rise = {d: dict(zip(s['seeds'], s['ratio'][:, -1] - s['ratio'][:, 0])) for d, s in out.items()}  # per seed, lowest to highest f
    for d, s in out.items():
        if d == base or out[base]['f'][0] != s['f'][0] or out[base]['f'][-1] != s['f'][-1]:
            continue
        diff = np.array([rise[base][k] - rise[d][k] for k in common(rise[base], rise[d])])
        diff = diff[np.isfinite(diff)]
        if diff.size >= 2:
            s['riseAgainstBase'] = {'baseDamping': base, 'seeds': int(diff.size), 'meanDifference': float(diff.mean()),
                                    'sem': float(diff.std(ddof=1) / np.sqrt(diff.size)),
                                    'pWilcoxon': float(stats.wilcoxon(diff).pvalue) if np.any(diff != 0) else 1.0}
    return out


def tests(summary):
    """test.json of the sweep: per damping ('%g'), the within-seed test (empty without one), the
    frequencies, the ratio's mean, the medians of the unbalanced force and of the rms speed, and
    riseAgainstBase (None at the lowest damping)."""
    return {'%g' % d: dict(s['test'] or {}, f=s['f'].tolist(), ratioMean=s['ratioMean'].tolist(),
                           unbalancedMedian=s['unbalancedMedian'].tolist(), vRmsMedian=s['vRmsMedian'].tolist(),
                           riseAgainstBase=s.get('riseAgainstBase')) for d, s in summary.items()}


def figure(summary, path):
    """Per damping (a column of panels): the largest sigma/f_t at Fmax/2 against f, a line per seed and
    the mean, and the unbalanced force there, on log axes of f."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, len(summary), figsize=(5.2 * len(summary), 7.5), squeeze=False, sharex=True)
    for col, (d, s) in enumerate(sorted(summary.items())):
        top, bottom = axes[0][col], axes[1][col]
        for row in range(len(s['seeds'])):
            top.plot(s['f'], s['ratio'][row], '-o', ms=3, lw=0.8, color='0.6')
            bottom.plot(s['f'], s['unbalanced'][row], '-o', ms=3, lw=0.8, color='0.6')
        top.plot(s['f'], s['ratioMean'], '_', ms=22, mew=2.5, color='C3', label='mean')
        top.plot([], [], '-o', ms=3, lw=0.8, color='0.6', label='one seed')
        t = s['test']
        top.set_title('damping %g, %d seeds%s' % (d, len(s['seeds']), '' if t is None else
                                                  '\nPage trend over %d seeds: %s, p = %.2g' % (t['seeds'], t['trend'], t['pTrend'])),
                      fontsize=10)
        top.set_ylabel(r'largest $\sigma/f_t$ at $F = F_{max}/2$ [-]')
        bottom.set_ylabel('unbalanced force at $F_{max}/2$ [-]')
        bottom.set_yscale('log')
        bottom.set_xlabel('loading frequency f [Hz]')
        for ax in (top, bottom):
            ax.set_xscale('log')
            ax.set_xticks(s['f'])
            ax.set_xticklabels(['%g' % f for f in s['f']])
            ax.minorticks_off()
            ax.grid(alpha=0.3)
        top.legend(fontsize=8)
    return writeFigure(fig, path)
