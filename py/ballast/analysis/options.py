"""The fast options of issue 25 against the paper's settings (docs/performance.md, "Validation"): for
each option, the runs of a study with it and the runs of a reference study with the paper's settings,
matched by seed (the same stored packing, so the pairs differ by the option only; the reference is the
paper's rows of the same study, or an older study's records): the response (delta
at the applied peak of eq. 8, what Fig. 5 reads), the crushes, the share of realizations that
avalanche, a paired and a two-sample test, the paired mean difference with its 95 % interval, and the
CPU ratio per seed. Needs no YADE."""
import json
import os

import numpy as np
import pandas as pd
from scipy import stats

from ..study.data import StudyRuns
from .effects import meanInterval
from .pairs import bySeed, common

AVALANCHE = 0.005   # [m] delta at the applied peak above which a realization avalanched (docs/studies.md: quiet
#                     realizations stay below 1 mm, avalanches settle 9-80 mm)


PAPER = {'timeStep': 'pwave', 'stopAt': 0.0, 'densityStep': 0.0}   # the fast options' values in the paper's settings
OPTIONS = {'stiffness': dict(PAPER, timeStep='stiffness'), 'peak': dict(PAPER, stopAt=0.5),
           'combined': dict(PAPER, timeStep='stiffness', stopAt=0.5), 'density': dict(PAPER, densityStep=2e-6),
           'densitypeak': dict(PAPER, densityStep=2e-6, stopAt=0.5),
           'density12peak': dict(PAPER, densityStep=1.2e-6, stopAt=0.5)}   # name -> the option's parameters (the table's)


def frame(path, **values):
    """The finished runs of a study (or its records) whose parameters equal `values` ({name: value})."""
    return select(StudyRuns(path).frame(), path, **values)


def select(runs, where='the runs', **values):
    """The rows of a runs frame (StudyRuns.frame) whose parameters equal `values`; a fast option's column
    that runs older than the option lack (or leave empty) holds the paper's value (PAPER)."""
    for name, value in values.items():
        col = runs.get('params.' + name)
        if col is None:
            if name not in PAPER:
                raise KeyError('%s: no parameter %r' % (where, name))
            col = pd.Series([PAPER[name]] * len(runs), index=runs.index, dtype=object)
        if name in PAPER:
            col = col.where(col.notna(), PAPER[name])
        runs = runs[np.isclose(col.astype(float), value)] if isinstance(value, float) else runs[col == value]
    return runs


def compare(option, reference, response='deltaAtAppliedPeak'):
    """The option's runs against the reference's, paired by seed (DataFrames of frame()): a dict with n (the
    seeds both have), seeds, per side the mean response [m], the mean crushes and the share avalanching,
    the paired differences' mean with its 95 % t interval and Cohen's d_z, Wilcoxon's signed-rank p (paired)
    and Mann-Whitney's p (two-sample), the seeds that changed between quiet and avalanche, and the median
    per-seed ratios option / reference of the CPU seconds and of the loading steps."""
    a, b = bySeed(option, 'compare: the option', 'params.seed'), bySeed(reference, 'compare: the reference', 'params.seed')
    seeds = common(a, b)
    if len(seeds) < 2:
        raise ValueError('compare: %d seed(s) in both studies; a comparison needs at least 2' % len(seeds))
    x, y = a.loc[seeds, response].to_numpy(float), b.loc[seeds, response].to_numpy(float)
    d = x - y
    n = len(seeds)
    sd = float(np.std(d, ddof=1))
    half = meanInterval(d)[1]
    same = bool(np.all(d == 0))
    out = {'n': n, 'seeds': [int(s) for s in seeds], 'response': response,
           'option': {'mean': float(np.mean(x)), 'crushes': float(a.loc[seeds, 'nCrushed'].mean()),
                      'avalanching': float(np.mean(x > AVALANCHE))},
           'reference': {'mean': float(np.mean(y)), 'crushes': float(b.loc[seeds, 'nCrushed'].mean()),
                         'avalanching': float(np.mean(y > AVALANCHE))},
           'meanDifference': float(np.mean(d)), 'meanDifferenceLow': float(np.mean(d) - half),
           'meanDifferenceHigh': float(np.mean(d) + half),
           'cohenDz': float(np.mean(d) / sd) if sd > 0 else 0.0,
           'pWilcoxon': 1.0 if same else float(stats.wilcoxon(x, y).pvalue),
           'pMannWhitney': float(stats.mannwhitneyu(x, y, alternative='two-sided').pvalue),
           'changedClass': [int(s) for s, xi, yi in zip(seeds, x, y) if (xi > AVALANCHE) != (yi > AVALANCHE)],
           **avalancheTests(x > AVALANCHE, y > AVALANCHE),
           'cpuRatioMedian': float(np.median(a.loc[seeds, 'cpuSeconds'].to_numpy(float) /
                                             b.loc[seeds, 'cpuSeconds'].to_numpy(float)))}
    if 'stepsByPhase.load' in a and 'stepsByPhase.load' in b:  # the machine-independent cost
        out['loadStepsRatioMedian'] = float(np.median(a.loc[seeds, 'stepsByPhase.load'].to_numpy(float) /
                                                      b.loc[seeds, 'stepsByPhase.load'].to_numpy(float)))
    return out


def avalancheTests(a, b):
    """Do two sides avalanche equally often? a, b: whether each seed avalanched (booleans, paired by position).
    Fisher's exact test of the two shares as independent samples (two-sided; right where the two sides' beds are
    not the same grains, e.g. two grain kinds of one seed), and McNemar's exact test of the pairs (the binomial
    test of the seeds that avalanched on one side only: right where a seed is one bed on both sides):
    {'pFisherAvalanching', 'pMcNemarAvalanching'}, 1.0 where the sides do not differ."""
    a, b = np.asarray(a, dtype=bool), np.asarray(b, dtype=bool)
    table = [[int(a.sum()), int((~a).sum())], [int(b.sum()), int((~b).sum())]]
    onlyA, onlyB = int(np.sum(a & ~b)), int(np.sum(b & ~a))
    return {'pFisherAvalanching': float(stats.fisher_exact(table).pvalue),
            'pMcNemarAvalanching': float(stats.binomtest(onlyA, onlyA + onlyB, 0.5).pvalue) if onlyA + onlyB else 1.0}


def markdown(result, reference="paper's settings"):
    """The comparisons ({option: compare()}) as the table of docs/performance.md: per option the means of
    delta at the applied peak [mm], the paired difference with its 95 % interval, Cohen's d_z, the two
    tests' p, the share avalanching, the seeds that changed class, and the loading-step and CPU ratios."""
    lines = ['| option | seeds | delta, mean [mm] (%s) | paired difference [mm], 95 %% | d_z | Wilcoxon p '
             '| Mann-Whitney p | avalanching (%s) | seeds that changed class | loading steps | CPU |' % (
                 reference, reference.replace(' settings', '')),
             '|' + '---|' * 11]
    for name, r in result.items():
        changed = r['changedClass']
        lines.append('| %s | %d | %.1f (%.1f) | %+.1f [%.1f, %.1f] | %.2f | %.2g | %.2g | %.0f %% (%.0f %%) | %s | x%.2f | x%.2f |' % (
            name, r['n'], 1e3 * r['option']['mean'], 1e3 * r['reference']['mean'], 1e3 * r['meanDifference'],
            1e3 * r['meanDifferenceLow'], 1e3 * r['meanDifferenceHigh'], r['cohenDz'], r['pWilcoxon'], r['pMannWhitney'],
            100 * r['option']['avalanching'], 100 * r['reference']['avalanching'],
            '%d of %d' % (len(changed), r['n']) if changed else 'none', r.get('loadStepsRatioMedian', float('nan')),
            r['cpuRatioMedian']))
    return '\n'.join(lines) + '\n'


def write(result, out, reference="paper's settings"):
    """The comparisons ({name: compare()}) as out/comparison.json and out/comparison.md (markdown's table); the
    folder made if missing."""
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, 'comparison.json'), 'w') as fh:
        json.dump(result, fh, indent=1)
    with open(os.path.join(out, 'comparison.md'), 'w') as fh:
        fh.write(markdown(result, reference))


def figure(pairs, path, reference="paper's settings"):
    """delta at the applied peak of each seed, the option against the paper's settings, one panel per
    option (pairs: {option: (option frame, reference frame)}), with the 1:1 line."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    from ..runfiles import saveFigure
    fig, axes = plt.subplots(1, len(pairs), figsize=(4.5 * len(pairs), 4.2), squeeze=False)
    for ax, (name, (a, b)) in zip(axes[0], pairs.items()):
        a, b = bySeed(a, name, 'params.seed'), bySeed(b, name + ': the reference', 'params.seed')
        seeds = common(a, b)
        x, y = 1e3 * b.loc[seeds, 'deltaAtAppliedPeak'], 1e3 * a.loc[seeds, 'deltaAtAppliedPeak']
        top = max(float(np.max(x)), float(np.max(y)), 1.0) * 1.05
        ax.plot([0, top], [0, top], 'k--', lw=0.8)
        ax.plot(x, y, 'o', ms=5)
        ax.set_xlabel('%s: $\\delta$ at the applied peak [mm]' % reference)
        ax.set_ylabel('%s: $\\delta$ [mm]' % name)
        ax.set_title('%s, %d seeds' % (name, len(seeds)), fontsize=9)
        ax.grid(alpha=0.3)
    fig.tight_layout()
    saveFigure(fig, path)
    return path
