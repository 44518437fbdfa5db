"""Why the displacement depends on the crushing period (issue 14, item 3; docs/studies.md, "Why δ
depends on T_c: the variants"): the T_c study (the baseline, the paper's model) beside controlled
variants that each remove one candidate mechanism, compared per T_c. Reads study directories or their
records (ballast.study.data); NumPy, no YADE.

A run's variant is read from its parameters against the oedometer's defaults (its declaration):
'sequential' (maxPerCheck > 0: no batches of crushes at rare checks), 'damped' (another local damping
than the default: a shorter transient after each replacement), 'servo' (loadMode servo: the plate
cannot fall into the gap a crush leaves), or the baseline ('batch': the paper's). A mechanism is
explained when removing it removes the trend of the mean displacement with T_c and the other variants
keep it.
"""
import numpy as np

from ..experiments import declaration
from ..study.data import StudyData
from ..experiments.oedometer.checkstats import CHECK_STATS
from .figures import logPositions, paramAxis, writeFigure
from .pairs import common

BASELINE = 'batch (the paper)'


def variantOf(params):
    """The name of the variant a run's parameters make (see the module's doc); a parameter the run
    lacks has the oedometer's default."""
    default = {k: p.default for k, p in declaration('oedometer').params.items()}
    p = dict(default, **params)
    names = []
    if p['maxPerCheck'] > 0:
        names.append('sequential' if p['maxPerCheck'] == 1 else 'at most %d per check' % p['maxPerCheck'])
    if p['damping'] != default['damping']:
        names.append('damped (%g)' % p['damping'])
    if p['loadMode'] == 'servo':
        names.append('servo')
    return ' + '.join(names) or BASELINE


def collect(*studies):
    """One dict per finished run of the study folders: variant, Tc, seed, delta at the peak of the
    applied force [m], crushed grains, crushing checks, the largest sigma/f_t of a grain when it crushed,
    and the crushes after the peak of the applied force (t > 1/(2f): the crushing that delta at the peak
    does not see)."""
    out = []
    for path in studies:
        data = StudyData(path, param='Tc', experiment='oedometer')
        for r in data.runs:
            s = r.summary
            row = {'variant': variantOf(r.params), 'Tc': float(r.params['Tc']), 'seed': r.seed,
                   'delta': s[data.response], 'nCrushed': s['nCrushed']}
            row.update((k, s[k]) for k in CHECK_STATS if k in s)  # StudyData merged checkStats into the summary
            out.append(row)
    return out


def table(rows):
    """Per (variant, Tc): n, mean and sample standard deviation of delta, its standard error, the mean
    crushes, and over the runs that crushed (and have their crushes) the mean share of crushes after the
    peak and the mean of each run's largest sigma/f_t at a crush (NaN if none); sorted by variant (the
    baseline first) and Tc."""
    keys = sorted(set((r['variant'], r['Tc']) for r in rows), key=lambda k: (k[0] != BASELINE, k[0], k[1]))
    res = []
    for v, tc in keys:
        mine = [r for r in rows if (r['variant'], r['Tc']) == (v, tc)]
        d = np.array([r['delta'] for r in mine])
        n = len(d)
        std = float(np.std(d, ddof=1)) if n > 1 else float('nan')
        crushed = [r for r in mine if r['nCrushed'] and r.get('crushesAfterPeak') is not None]
        res.append({'variant': v, 'Tc': tc, 'n': n, 'delta_mean': float(np.mean(d)), 'delta_std': std,
                    'delta_sem': std / np.sqrt(n) if n > 1 else float('nan'),
                    'nCrushed_mean': float(np.mean([r['nCrushed'] for r in mine])),
                    'afterPeak_mean': float(np.mean([r['crushesAfterPeak'] / r['nCrushed'] for r in crushed]))
                    if crushed else float('nan'),
                    'ratioAtCrushMax_mean': float(np.mean([r['ratioAtCrushMax'] for r in crushed]))
                    if crushed and all(r.get('ratioAtCrushMax') is not None for r in crushed) else float('nan')})
    return res


def trends(rows):
    """Per variant, the change of delta from each T_c it has to the next larger one, on the seeds it shares
    with the baseline at both, beside the baseline's change over the same T_c and seeds: does the variant
    keep the trend? [{variant, Tc0, Tc1, n, change, sem, baselineChange, baselineSem, effect, effectSem}],
    effect = the mean of (the variant's change - the baseline's) per seed, with its standard error. The
    baseline's own rows compare it with itself (effect 0)."""
    def deltas(variant, tc):
        return {r['seed']: r['delta'] for r in rows if r['variant'] == variant and r['Tc'] == tc}

    def meanSem(x):
        n = len(x)
        return (float(np.mean(x)) if n else float('nan'),
                float(np.std(x, ddof=1) / np.sqrt(n)) if n > 1 else float('nan'))

    out = []
    for v in sorted(set(r['variant'] for r in rows), key=lambda x: (x != BASELINE, x)):
        tcs = sorted(set(r['Tc'] for r in rows if r['variant'] == v))
        for a, b in zip(tcs, tcs[1:]):
            va, vb, ba, bb = deltas(v, a), deltas(v, b), deltas(BASELINE, a), deltas(BASELINE, b)
            seeds = common(va, vb, ba, bb)
            mine = np.array([vb[s] - va[s] for s in seeds])
            base = np.array([bb[s] - ba[s] for s in seeds])
            row = {'variant': v, 'Tc0': a, 'Tc1': b, 'n': len(seeds)}
            row['change'], row['sem'] = meanSem(mine)
            row['baselineChange'], row['baselineSem'] = meanSem(base)
            row['effect'], row['effectSem'] = meanSem(mine - base)
            out.append(row)
    return out


def figure(rows, out):
    """delta at the peak of the applied force (mean +- standard deviation), the mean crushes and the mean
    of each run's largest sigma/f_t at a crush against T_c, a line per variant; T_c = 0 (every step) one
    step left of the smallest."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    st = table(rows)
    tcs = sorted(set(r['Tc'] for r in st))
    x, ticks = logPositions(tcs, 'every step')
    fig, (a1, a2, a3) = plt.subplots(1, 3, figsize=(15, 4.5))
    variants = list(dict.fromkeys(r['variant'] for r in st))
    for i, v in enumerate(variants):
        mine = [r for r in st if r['variant'] == v]
        xs = [x[r['Tc']] * (1 + 0.04 * (i - (len(variants) - 1) / 2)) for r in mine]  # side by side
        a1.errorbar(xs, [1e3 * r['delta_mean'] for r in mine], yerr=[1e3 * np.nan_to_num(r['delta_std']) for r in mine],
                    fmt='-o', capsize=3, color='C%d' % i, label='%s (n = %s)' % (v, '/'.join(str(r['n']) for r in mine)))
        a2.plot(xs, [r['nCrushed_mean'] for r in mine], '-o', color='C%d' % i, label=v)
        a3.plot(xs, [r['ratioAtCrushMax_mean'] for r in mine], '-o', color='C%d' % i, label=v)
    a3.axhline(1.0, color='k', lw=0.8, ls=':')
    for a, ylabel in ((a1, r'$\delta$ at the peak of the applied force [mm]'), (a2, 'grains crushed, mean [-]'),
                      (a3, r'largest $\sigma/f_t$ of a grain when it crushed, mean [-]')):
        paramAxis(a, tcs, x, ticks, 'log')
        a.set_xlabel('crushing period $T_c$ [s]')
        a.set_ylabel(ylabel)
        a.grid(alpha=0.3)
        a.legend(fontsize=7)
    fig.suptitle('what makes delta depend on $T_c$: the paper\'s model and variants that remove one mechanism each', fontsize=10)
    return writeFigure(fig, out, dpi=110)
