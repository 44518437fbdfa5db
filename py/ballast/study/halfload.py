"""The force network at half the peak load against the loading rate (docs/studies.md, Fig. 4): each
realization is loaded by eq. 8 only up to t = 1/(4f), where the applied force passes Fmax/2, well below
the first crush (980 kN or more in the Fig. 4 runs), so a sweep over seeds, frequencies and damping
costs a quarter period per run instead of a cycle. Per run: the largest sigma/f_t of a grain there
(aggregate.halfLoadRatio of the per-check log), the grains' force on the plate, delta, and how far the
sample is from equilibrium (YADE's unbalanced force, the grains' rms speed). A sweep appends a CSV row
per finished run and skips the runs its CSV has: it resumes after a stop.
"""
import csv
import math
import os
import time

import numpy as np

from ..oedometer.loadcurve import halfLoadTime
from ..oedometer.parameters import check
from .aggregate import HALF_LOAD_GAP, fmt, halfLoadRatio

KEYS = ('seed', 'f', 'damping')  # what identifies a run of the sweep
COLUMNS = [('seed', '-'), ('f', 'Hz'), ('damping', '-'), ('stressRatioAtHalfLoad', '-'), ('Fapplied', 'N'), ('F', 'N'),
           ('delta', 'm'), ('unbalanced', '-'), ('vRms', 'm/s'), ('steps', '-'), ('cpuSeconds', 's')]
HEADER = ['%s [%s]' % c for c in COLUMNS]


def checkRun(params):
    """The oedometer's parameters checked (ParamError names a bad value), and the crushing period: the two
    checks around 1/(4f) must lie within HALF_LOAD_GAP Fmax of each other (eq. 8 rises by pi f Fmax Tc
    between them). Returns the full parameter dict."""
    p = check(params)
    if p['Tc'] * math.pi * p['f'] > HALF_LOAD_GAP:
        raise ValueError('halfLoad: Tc = %r s checks too rarely at f = %r Hz: the two checks around 1/(4f) must lie '
                         'within %g Fmax (Tc < %.3g s, or 0: every step)' % (
                             p['Tc'], p['f'], HALF_LOAD_GAP, HALF_LOAD_GAP / (math.pi * p['f'])))
    return p


def plan(seeds, fs, dampings, **params):
    """The runs of the sweep as parameter dicts, every one checked (checkRun) before any runs."""
    runs = [dict(params, seed=s, f=f, damping=d) for s in seeds for f in fs for d in dampings]
    for p in runs:
        checkRun(p)
    return runs


def halfLoad(**params):
    """Prepare a realization (its stored packing if there is one), load it past t = 1/(4f) to the next
    crush check (every Tc, or every step) and return its row (COLUMNS' names)."""
    from yade import O

    from ..oedometer import Oedometer
    p = checkRun(params)
    cpu0 = time.process_time()
    run = Oedometer(**params)
    run.prepare()
    run.startLoading()
    i0, t0 = O.iter, run.loading.t0
    tEnd = t0 + halfLoadTime(p['f']) + 1.5 * (p['Tc'] or O.dt)
    run.phases.run('load to Fmax/2', tEnd=tEnd, simSpan=tEnd - O.time, simStart=O.time)
    rows = np.array(run.outputs.checkRows, dtype=float)
    crushed = rows[rows[:, 2] > 0, 0]
    ratio = halfLoadRatio({'t': rows[:, 0], 'maxStressRatio': rows[:, 3]}, p['Fmax'], p['Fmin'], p['f'],
                          float(crushed[0]) if crushed.size else math.inf)
    return {'seed': p['seed'], 'f': p['f'], 'damping': p['damping'], 'stressRatioAtHalfLoad': ratio,
            'Fapplied': run.loading.applied(), 'F': run.loading.force(), 'delta': run.loading.delta(),
            'unbalanced': run.unbalanced(), 'vRms': run.vRms(), 'steps': O.iter - i0, 'cpuSeconds': time.process_time() - cpu0}


def done(path):
    """The KEYS of the runs the CSV at path has (empty if it does not exist)."""
    if not os.path.isfile(path):
        return set()
    c = read(path)
    return set(zip(*(c[k].tolist() for k in KEYS)))


def sweep(path, runs, say=print):
    """Run every run of `runs` (plan()) the CSV at path does not have yet, appending its row when it
    finishes. Returns the number run."""
    have = done(path)
    todo = [p for p in runs if tuple(float(p[k]) for k in KEYS) not in have]
    say('half-load sweep: %d runs, %d in %s already, %d to run' % (len(runs), len(runs) - len(todo), path, len(todo)))
    for k, p in enumerate(todo):
        row = halfLoad(**p)
        new = not os.path.isfile(path)
        with open(path, 'a', newline='') as fh:
            w = csv.writer(fh)
            if new:
                w.writerow(HEADER)
            w.writerow([fmt(row[c]) for c, _ in COLUMNS])
            fh.flush()
            os.fsync(fh.fileno())
        say('half-load sweep: %d/%d done: seed %d, f = %g Hz, damping %g: sigma/f_t %s, unbalanced %.3g (%.0f s)' % (
            k + 1, len(todo), p['seed'], p['f'], p['damping'],
            'none' if row['stressRatioAtHalfLoad'] is None else '%.4f' % row['stressRatioAtHalfLoad'], row['unbalanced'],
            row['cpuSeconds']))
    return len(todo)


def read(path):
    """The sweep's CSV as {column name: float array} (an empty cell, a run without the ratio, is NaN)."""
    with open(path, newline='') as fh:
        rows = list(csv.DictReader(fh))
    return {name: np.array([float(r['%s [%s]' % (name, unit)] or 'nan') for r in rows]) for name, unit in COLUMNS}


def summarize(path):
    """Per damping: the frequencies, the seeds, the matrices (a row per seed, a column per f, NaN where
    missing) of the ratio and of the unbalanced force, the ratio's mean, the medians of the unbalanced
    force and of the rms speed per f, and the within-seed test of
    the ratio across f (aggregate.withinSeeds, Page's trend along f) over the seeds that have every f
    (None with fewer than 3 frequencies or 2 such seeds). For every damping but the lowest, under
    riseAgainstBase: per seed, the rise of the ratio from the lowest to the highest f at the lowest
    damping minus its rise at this one; their mean, standard error and Wilcoxon's signed-rank p (does
    the damping change the rate effect?)."""
    from scipy import stats

    from .aggregate import withinSeeds
    c = read(path)
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
        diff = np.array([rise[base][k] - rise[d][k] for k in rise[base] if k in rise[d]])
        diff = diff[np.isfinite(diff)]
        if diff.size >= 2:
            s['riseAgainstBase'] = {'baseDamping': base, 'seeds': int(diff.size), 'meanDifference': float(diff.mean()),
                                    'sem': float(diff.std(ddof=1) / np.sqrt(diff.size)),
                                    'pWilcoxon': float(stats.wilcoxon(diff).pvalue) if np.any(diff != 0) else 1.0}
    return out


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
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return path
