"""A study's finished runs as tables and the paper's figures.

    runs.csv         one line per finished run: the studied parameter, seed, the numbers of summary.json
                     and every parameter of the run
    stats.csv        one line per value of the studied parameter: number of runs, mean and standard
                     deviation (sample, n-1) of the displacement at peak force and of the other results
    test.json        does the parameter change the displacement at peak? Kruskal-Wallis across its
                     values, with the difference of two means the runs could have detected; under
                     "blocked" the same question asked within each realization (Friedman, seeds as blocks;
                     Page's trend test), under "onset" for the applied force at the first crush, under
                     "network" for the largest sigma/f_t at half the peak load before any crush
    fd_curves.png    F-delta curves, one panel per value of the studied parameter, a line per seed (Fig. 4)
    delta_peak.png   displacement at peak force against the parameter: one grey line per realization,
                     mean +- standard deviation as error bars (paper, Fig. 5)
The studied parameter is the column of the table that varies besides the seed (or the one named).
Runs not finished are left out and listed.
"""
import csv
import json
import math
import os

import numpy as np

from ..oedometer.loadcurve import halfLoadTime, loadCurve, peakTime
from ..oedometer.parameters import PARAMS
from .files import readSummary
from .options import StudyError
from .records import crushTable
from .table import cellValue

# Results of summary.json carried into the tables; (key, unit)
RESULTS = [('peakForce', 'N'), ('deltaAtPeak', 'm'), ('deltaAtAppliedPeak', 'm'), ('seatingDelta', 'm'), ('deltaMax', 'm'),
           ('deltaFinal', 'm'), ('nCrushed', '-'), ('Bg', '%'), ('Br', '-'), ('BBI', '-'),
           ('nAbraded', '-'), ('volumeLost', 'm^3'), ('massLost', 'kg'), ('massInitial', 'kg'), ('nGrainsInitial', '-'),
           ('porosity0', '-'), ('wallSeconds', 's'), ('cpuSeconds', 's'), ('steps', '-'),
           ('crushingChecks', '-'), ('crushesPerCrushingCheck', '-'), ('ratioAtCrushMax', '-'), ('ratioAtCrushMean', '-'),
           ('forceAtFirstCrush', 'N'), ('stressRatioAtHalfLoad', '-'), ('crushesAfterPeak', '-')]
STATS = ['deltaAtPeak', 'deltaAtAppliedPeak', 'deltaMax', 'peakForce', 'nCrushed', 'nAbraded', 'massLost', 'Bg', 'Br',
         'BBI', 'crushingChecks', 'crushesPerCrushingCheck', 'ratioAtCrushMax', 'forceAtFirstCrush', 'stressRatioAtHalfLoad',
         'wallSeconds', 'cpuSeconds']
LABELS = {'f': 'loading frequency f [Hz]', 'Tc': 'crushing period $T_c$ [s]', 'rMin': '$r_{min}$ [m]', 'ft0': '$f_{t0}$ [Pa m]',
          'gamma': r'reduction factor $\gamma$ [-]', 'pattern': 'replacement pattern'}


def label(v):
    return '%g' % v if isinstance(v, float) else str(v)


def valueLabel(param, v):
    """'f = 8 Hz': a value of a parameter with its unit (from its declaration)."""
    unit = PARAMS[param].unit if param in PARAMS else '-'
    return '%s = %s%s' % (param, label(v), '' if unit in ('-', '') else ' ' + unit)


def count(n, noun):
    """'1 run', '3 runs'."""
    return '%d %s%s' % (n, noun, '' if n == 1 else 's')


def fmt(v):
    """A CSV cell: floats in full (repr), missing and NaN empty."""
    if v is None or (isinstance(v, float) and math.isnan(v)):
        return ''
    return repr(v) if isinstance(v, float) else str(v)


def meanStd(xs):
    """Mean and sample standard deviation (n-1) of xs; NaN where undefined (std of one run)."""
    mean = float(np.mean(xs)) if xs else float('nan')
    return mean, float(np.std(xs, ddof=1)) if len(xs) > 1 else float('nan')


HALF_LOAD_GAP = 0.05  # [-] the widest gap in applied force, over Fmax, halfLoadRatio interpolates across
CHECK_STATS = ('crushingChecks', 'crushesPerCrushingCheck', 'ratioAtCrushMax', 'ratioAtCrushMean',
               'forceAtFirstCrush', 'stressRatioAtHalfLoad', 'crushesAfterPeak')  # checkStats' keys


def checkStats(runDir, params=None):
    """From the per-check log (checks.csv, or a record's: every check that crushed is in both): the checks
    that crushed and the grains each crushed on average; from the crushes (events.csv, or a record's
    crushes.csv) the largest and the mean sigma/f_t of the grains when they crushed (how far above their
    strength rare checks find grains; the log's maxStressRatio also counts fragments below r_min, which
    never crush); with the run's parameters (f, Fmax, Fmin) the applied force when the first grain
    crushed (the onset: quasi-static loading gives a seed the same onset at every frequency), the
    crushes after the peak of the applied force (t > 1/(2f): what delta at the peak does not see), and
    stressRatioAtHalfLoad (halfLoadRatio). {} without a log."""
    try:
        c = np.atleast_1d(np.genfromtxt(os.path.join(runDir, 'checks.csv'), delimiter=',', names=True))
    except (OSError, ValueError):
        return {}
    if c.dtype.names is None or 'nCrushed' not in c.dtype.names:
        return {}
    hit = c[c['nCrushed'] > 0] if c.size else c
    n = int(hit.size)
    out = dict.fromkeys(CHECK_STATS)
    out.update(crushingChecks=n, crushesPerCrushingCheck=float(np.mean(hit['nCrushed'])) if n else None)
    crushes = crushTable(runDir)
    ratios = crushes[2] if crushes is not None else np.array([])
    first = float(np.min(crushes[0])) if ratios.size else math.inf  # the first crush's time [s]
    loading = params and all(k in params for k in ('f', 'Fmax'))
    if loading:
        load = (float(params['Fmax']), float(params.get('Fmin', 0.0)), float(params['f']))
        out['stressRatioAtHalfLoad'] = halfLoadRatio(c, *load, firstCrush=first)
    if params and 'f' in params and crushes is not None:
        out['crushesAfterPeak'] = int(np.sum(crushes[0] > peakTime(float(params['f']))))
    if ratios.size:
        out.update(ratioAtCrushMax=float(np.max(ratios)), ratioAtCrushMean=float(np.mean(ratios)))
        if loading:
            out['forceAtFirstCrush'] = loadCurve(*load, first)
    return out


def halfLoadRatio(checks, Fmax, Fmin, f, firstCrush):
    """The largest sigma/f_t of a grain when the applied force first passes Fmax/2 (eq. 8: at t = 1/(4f)),
    from the per-check log `checks` (columns t, maxStressRatio), interpolated in the applied force between
    the checks on either side. Before any crush it measures the force network alone: how unevenly the
    sample carries the same load (a record keeps both checks, records.thinChecks). None if a grain
    crushed before the later of the two checks, if the log has no check on one side, or if the two are
    more than HALF_LOAD_GAP Fmax apart: the ratio grows less than in proportion to the load, and a long
    chord falls short of it (by 0.02-0.07 with checks 0.01-0.04 s apart at 4 Hz)."""
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


class StudyData:
    """The finished runs of the study directory `path` (written by Study.run), against the studied
    parameter `param` (default: the only column that varies besides the seed). runs: [{line, runId,
    value, seed, summary, dir}]; values, seeds: sorted; missing: run ids not finished."""

    def __init__(self, path, param=None):
        self.dir = os.path.abspath(path)
        if not os.path.isdir(self.dir):
            raise StudyError('STUDY: no such directory: %s' % path)
        info = os.path.join(self.dir, 'study.json')
        if not os.path.isfile(info):
            raise StudyError('STUDY: %s is not a study directory of scripts/study.py (no study.json)' % path)
        with open(info) as fh:
            self.info = json.load(fh)
        rows = self.info['rows']
        cols = [c for c in self.info['columns'] if c != 'description' and not c.startswith('!')]
        varying = [c for c in cols if c != 'seed' and len(set(r['row'][c] for r in rows)) > 1]
        if param is not None:
            if param not in cols:
                raise StudyError('--param: %r is not a column of the study table (columns: %s)' % (param, ', '.join(cols)))
            self.param = param
        elif len(varying) == 1:
            self.param = varying[0]
        elif not varying:
            raise StudyError('STUDY: no column but the seed varies in %s; nothing to aggregate against' % self.info['table'])
        else:
            raise StudyError('--param: the table varies %s; say which one is studied' % ', '.join(varying))
        self.runs, self.missing = [], []
        for r in rows:
            d = os.path.join(self.dir, 'runs', r['runId'])
            s, _ = readSummary(d)
            if s is None:
                self.missing.append(r['runId'])
                continue
            params = s.get('params') or {}
            # the values as the run read them; from the cell for a summary without them
            value, seed = (params[k] if k in params else cellValue(k, r['row'].get(k)) for k in (self.param, 'seed'))
            s = dict(s, **checkStats(d, params))
            self.runs.append({'line': r['line'], 'runId': r['runId'], 'value': value, 'seed': seed, 'summary': s, 'dir': d})
        if not self.runs:
            raise StudyError('STUDY: no finished run in %s (run it with scripts/study.py run first)' % path)
        vals = [r['value'] for r in self.runs]
        self.numeric = all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in vals)
        self.values = sorted(set(vals), key=(lambda v: v) if self.numeric else (lambda v: (isinstance(v, str), str(v).zfill(8))))
        self.seeds = sorted(set(r['seed'] for r in self.runs), key=lambda s: (str(type(s)), s))
        # the paper's "displacement at peak force": at the peak of the applied force (t = T/2) where every run
        # records it; runs of older versions only have delta at the peak of the measured force
        self.peak = 'deltaAtAppliedPeak' if all(r['summary'].get('deltaAtAppliedPeak') is not None
                                               for r in self.runs) else 'deltaAtPeak'

    def stats(self):
        """[{value, n, <result>_mean, <result>_std}] per value of the parameter, for the STATS results."""
        out = []
        for v in self.values:
            rs = [r for r in self.runs if r['value'] == v]
            st = {'value': v, 'n': len(rs)}
            for k in STATS:
                st[k + '_mean'], st[k + '_std'] = meanStd([float(r['summary'][k]) for r in rs if r['summary'].get(k) is not None])
            out.append(st)
        return out

    def codeVersions(self):
        """The code sha1s (row.json) the finished runs were made with; None for runs without one."""
        shas = set()
        for r in self.runs:
            try:
                with open(os.path.join(r['dir'], 'row.json')) as fh:
                    shas.add(json.load(fh).get('codeSha1'))
            except (OSError, ValueError):
                shas.add(None)
        return shas


def writeCsv(data, outDir):
    """runs.csv and stats.csv in outDir; returns their paths."""
    runsCsv = os.path.join(outDir, 'runs.csv')
    with open(runsCsv, 'w', newline='') as fh:
        w = csv.writer(fh)
        # every parameter of every run, as the run read it, after the results
        names = sorted(set(k for r in data.runs for k in (r['summary'].get('params') or {})) - {data.param, 'seed'})
        w.writerow(['line', 'runId', data.param, 'seed'] + ['%s [%s]' % kv for kv in RESULTS] + [
            '%s [%s]' % (k, PARAMS[k].unit if k in PARAMS else '-') for k in names])
        for r in sorted(data.runs, key=lambda r: r['line']):
            params = r['summary'].get('params') or {}
            w.writerow([r['line'], r['runId'], label(r['value']), r['seed']] + [fmt(r['summary'].get(k)) for k, _ in RESULTS] +
                       [fmt(params.get(k)) for k in names])
    statsCsv = os.path.join(outDir, 'stats.csv')
    units = dict(RESULTS)
    with open(statsCsv, 'w', newline='') as fh:
        w = csv.writer(fh)
        w.writerow([data.param, 'n'] + sum([['%s_mean [%s]' % (k, units[k]), '%s_std [%s]' % (k, units[k])] for k in STATS], []))
        for st in data.stats():
            w.writerow([label(st['value']), st['n']] + sum([[fmt(st[k + '_mean']), fmt(st[k + '_std'])] for k in STATS], []))
    return runsCsv, statsCsv


def axisPositions(data, xlog):
    """x of each parameter value, tick labels and scale. Categories for names (pattern); for numbers
    spanning decades a log axis (xlog 'auto', or 'yes'; 'no' never), with 0 (Tc = 0: every step)
    put one step left of the smallest."""
    vals = data.values
    if not data.numeric:
        return {v: i for i, v in enumerate(vals)}, [label(v) for v in vals], 'linear'
    pos = [v for v in vals if v > 0]
    useLog = xlog == 'yes' or (xlog == 'auto' and len(pos) >= 3 and max(pos) / min(pos) >= 20 and all(v >= 0 for v in vals))
    if not useLog:
        return {v: v for v in vals}, None, 'linear'
    x, ticks = logPositions(vals, 'every step' if data.param == 'Tc' else '0')
    return x, ticks, 'log'


def logPositions(values, zero):
    """x of each value (>= 0) on a log axis, 0 put one mean step left of the smallest positive value,
    and the tick labels (`zero` for 0)."""
    pos = [v for v in values if v > 0]
    ratio = (max(pos) / min(pos))**(1 / (len(pos) - 1)) if len(pos) > 1 else 10.0
    return {v: (v if v > 0 else min(pos) / ratio) for v in values}, [(zero if v == 0 else '%.3g' % v) for v in values]


def paramAxis(ax, values, x, ticks, scale):
    """The studied parameter's axis (axisPositions): scale, a tick per value with its label."""
    ax.set_xscale(scale)
    if ticks is not None:
        ax.set_xticks([x[v] for v in values])
        ax.set_xticklabels(ticks, rotation=45 if scale == 'log' else 0, ha='right' if scale == 'log' else 'center', fontsize=8)
        ax.minorticks_off()


def plots(data, outDir, xlog='auto'):
    """fd_curves.png (Fig. 4), delta_peak.png (Fig. 5) and, when the runs have a per-check log, checks.png in
    outDir; returns their paths."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    name = os.path.basename(data.dir)

    # Fig. 4: F-delta of every run, a panel per value (small multiples), a colour per seed
    nv = len(data.values)
    ncol = min(nv, 3)
    nrow = -(-nv // ncol)
    legendRows = -(-len(data.seeds) // 10) if len(data.seeds) <= 20 else 0
    top = 0.35 + 0.22 * legendRows  # [in] above the panels: the title, then the legend's rows
    height = 3.3 * nrow + 0.3 + top
    fig, axes = plt.subplots(nrow, ncol, figsize=(4.2 * ncol, height), sharex=True, sharey=True, squeeze=False)
    seedColor = {s: plt.get_cmap('tab10' if len(data.seeds) <= 10 else 'tab20')(i % 20) for i, s in enumerate(data.seeds)}
    for k, v in enumerate(data.values):
        ax = axes[k // ncol][k % ncol]
        for r in sorted([r for r in data.runs if r['value'] == v], key=lambda r: str(r['seed'])):
            try:
                a = np.loadtxt(os.path.join(r['dir'], 'fd.csv'), delimiter=',', skiprows=1, ndmin=2)
            except (OSError, ValueError):
                continue
            # the paper's F is the load applied (column 6 of the plate load's fd.csv); else the grains' force
            F = a[:, 5] if a.shape[1] > 5 and np.isfinite(a[:, 5]).all() else a[:, 1]
            ax.plot(a[:, 2] * 1e3, F / 1e3, color=seedColor[r['seed']], lw=0.9, label='seed %s' % r['seed'])
        ax.set_title('%s (%s)' % (valueLabel(data.param, v), count(sum(r['value'] == v for r in data.runs), 'run')), fontsize=9)
        ax.grid(alpha=0.3)
        if k % ncol == 0:
            ax.set_ylabel('applied force F [kN]')
        if k // ncol == nrow - 1 or k + ncol >= nv:
            ax.set_xlabel(r'plate displacement $\delta$ [mm]')
            ax.tick_params(labelbottom=True)
    for k in range(nv, nrow * ncol):
        axes[k // ncol][k % ncol].set_visible(False)
    fig.suptitle('%s: %s, %s' % (name, count(len(data.runs), 'run'), count(len(data.seeds), 'realization')), fontsize=10,
                 y=1 - 0.05 / height, va='top')
    if legendRows:
        fig.legend(handles=[Line2D([], [], color=seedColor[s], lw=1.5, label='seed %s' % s) for s in data.seeds],
                   loc='upper center', bbox_to_anchor=(0.5, 1 - 0.33 / height), ncol=min(len(data.seeds), 10),
                   fontsize=7, frameon=False)
    fig.tight_layout(rect=(0, 0, 1, 1 - top / height))
    fd = os.path.join(outDir, 'fd_curves.png')
    fig.savefig(fd, dpi=110)
    plt.close(fig)

    # Fig. 5: displacement at peak force against the parameter
    x, ticks, scale = axisPositions(data, xlog)
    fig, ax = plt.subplots(figsize=(8, 5))
    for s in data.seeds:
        rs = sorted([r for r in data.runs if r['seed'] == s], key=lambda r: data.values.index(r['value']))
        ax.plot([x[r['value']] for r in rs], [r['summary'][data.peak] * 1e3 for r in rs], '-o', color='0.7', lw=0.8, ms=2.5,
                zorder=1)  # markers: a realization with one value shows too
    st = data.stats()
    ax.errorbar([x[s['value']] for s in st], [s[data.peak + '_mean'] * 1e3 for s in st],
                yerr=[0 if math.isnan(s[data.peak + '_std']) else s[data.peak + '_std'] * 1e3 for s in st],
                fmt='o', color='C0', ecolor='C0', capsize=4, lw=1.5, zorder=3, label='mean $\\pm$ standard deviation')
    ax.plot([], [], '-o', color='0.7', ms=2.5, label='one realization (seed)')
    paramAxis(ax, data.values, x, ticks, scale)
    ax.legend(fontsize=8)
    dp = save(fig, ax, LABELS.get(data.param, data.param), r'displacement at peak %sforce $\delta$ [mm]' % (
              'applied ' if data.peak == 'deltaAtAppliedPeak' else ''),
              '%s: %s, %s' % (name, count(len(data.runs), 'run'), count(len(data.seeds), 'realization')), os.path.join(outDir, 'delta_peak.png'))
    ck = checksPlot(data, outDir, x, ticks, scale)
    return [fd, dp] + ([ck] if ck else [])


def checksPlot(data, outDir, x, ticks, scale):
    """checks.png: from the per-check logs, per value of the parameter, the grains crushed per run and the
    largest sigma/f_t of a grain when it crushed (how far above their strength rare checks find grains),
    a point per run, the mean as a bar; the applied force at the first crush and the largest sigma/f_t at
    half the peak load before any crush (halfLoadRatio), a line per seed (a quasi-static onset and force
    network are flat along it). None if no run has a log."""
    import matplotlib.pyplot as plt
    runs = [r for r in data.runs if r['summary'].get('crushingChecks') is not None]
    if not runs:
        return None
    fig, axes = plt.subplots(1, 4, figsize=(20, 4.3))
    xs0 = sorted(x.values())
    # the runs of a value spread over +-0.15 of the spacing of the values (a factor on a log axis)
    step = (xs0[-1] / xs0[0]) ** (1 / max(len(xs0) - 1, 1)) if scale == 'log' else \
        (min(np.diff(xs0)) if len(xs0) > 1 else 1.0)
    for ax, key in ((axes[0], 'nCrushed'), (axes[1], 'ratioAtCrushMax')):
        for v in data.values:
            ys = np.array([r['summary'][key] for r in runs if r['value'] == v and r['summary'].get(key) is not None], float)
            if not ys.size:
                continue
            jitter = np.linspace(-0.15, 0.15, ys.size) if ys.size > 1 else np.zeros(1)
            xs = x[v] * step ** jitter if scale == 'log' else x[v] + jitter * step
            ax.plot(xs, ys, 'o', ms=3.5, color='0.45', alpha=0.8, zorder=2)
            ax.plot(x[v], ys.mean(), '_', ms=22, mew=2.5, color='C3', zorder=3)
        ax.plot([], [], 'o', ms=3.5, color='0.45', label='one run')
    axes[1].axhline(1.0, color='k', lw=0.8, ls=':')
    for ax, key, scale1 in ((axes[2], 'forceAtFirstCrush', 1e-3), (axes[3], 'stressRatioAtHalfLoad', 1.0)):
        got = [(r['seed'], r['value'], r['summary'][key] * scale1) for r in runs if r['summary'].get(key) is not None]
        for seed in data.seeds:
            line = sorted((x[v], y) for s, v, y in got if s == seed)
            if line:
                ax.plot(*zip(*line), '-o', ms=3, lw=0.8, color='0.6', zorder=2)
        for v in data.values:
            ys = [y for _, w, y in got if w == v]
            if ys:
                ax.plot(x[v], np.mean(ys), '_', ms=22, mew=2.5, color='C3', zorder=3)
        ax.plot([], [], '-o', ms=3, lw=0.8, color='0.6', label='one seed')
    for ax, ylabel in zip(axes, ('grains crushed in the run', r'largest $\sigma/f_t$ of a grain when it crushed',
                                 'applied force at the first crush [kN]',
                                 r'largest $\sigma/f_t$ at $F = F_{max}/2$, no grain crushed yet')):
        ax.plot([], [], '_', ms=14, mew=2.5, color='C3', label='mean')
        paramAxis(ax, data.values, x, ticks, scale)
        ax.set_xlabel(LABELS.get(data.param, data.param))
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle('%s: the per-check log of %s' % (os.path.basename(data.dir), count(len(runs), 'run')), fontsize=10)
    fig.tight_layout()
    path = os.path.join(outDir, 'checks.png')
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return path


def effectTest(data, alpha=0.05, power=0.8):
    """Does the studied parameter change the displacement at peak? The Kruskal-Wallis H test across
    its values (scipy.stats.kruskal; ties corrected) and the smallest difference of two means the
    runs could have detected: a two-sided test at `alpha` finds it with probability `power` given the
    pooled standard deviation s and the smallest group n, (z_(1-alpha/2) + z_power) s sqrt(2/n).
    None with fewer than two values of two runs each."""
    from scipy import stats
    groups = [np.array([r['summary'][data.peak] for r in data.runs if r['value'] == v]) for v in data.values]
    groups = [g for g in groups if len(g) >= 2]
    if len(groups) < 2:
        return None
    try:
        H, p = stats.kruskal(*groups)
    except ValueError:  # every displacement the same: no evidence of any effect
        H, p = 0.0, 1.0
    dof = sum(len(g) - 1 for g in groups)
    pooled = float(np.sqrt(sum((len(g) - 1) * np.var(g, ddof=1) for g in groups) / dof))
    n = min(len(g) for g in groups)
    z = stats.norm.ppf(1 - alpha / 2) + stats.norm.ppf(power)
    return {'test': 'Kruskal-Wallis', 'quantity': data.peak, 'parameter': data.param, 'groups': len(groups),
            'runs': int(sum(len(g) for g in groups)), 'H': float(H), 'p': float(p), 'alpha': alpha, 'power': power,
            'pooledStd [m]': pooled, 'smallestGroup': n, 'detectableDifference [m]': float(z * pooled * np.sqrt(2 / n))}


def blockedTest(data, quantity=None, unit='m', alpha=0.05, power=0.8):
    """The effect test within realizations: a seed is one packing run at every value of the parameter,
    so the seeds are blocks. For `quantity` (default the displacement at peak), over the values where a
    run has it and the seeds that have it at all of them: withinSeeds. None with fewer than 3 values
    or 2 complete seeds."""
    quantity = quantity or data.peak
    got = {(r['seed'], r['value']): r['summary'][quantity] for r in data.runs if r['summary'].get(quantity) is not None}
    values = [v for v in data.values if any(w == v for _, w in got)]
    seeds = [s for s in data.seeds if all((s, v) in got for v in values)]
    if len(values) < 3 or len(seeds) < 2:
        return None
    out = withinSeeds(np.array([[got[s, v] for v in values] for s in seeds], dtype=float), data.numeric, unit, alpha, power)
    return dict({'test': 'Friedman', 'quantity': quantity, 'blocks': 'seed', 'valuesTested': values}, **out)


def withinSeeds(y, numeric, unit, alpha=0.05, power=0.8):
    """Friedman's chi-square test across the columns of y (a row per seed, a column per value of the
    parameter; scipy.stats.friedmanchisquare) and the difference of two means it could have detected:
    as effectTest's, with the residual standard deviation of the two-way layout (seed + value) in place
    of the pooled one, s_r = sqrt(sum r_ij^2 / ((b - 1)(k - 1))), r_ij = y_ij - row mean - column mean
    + grand mean, and b seeds. For a numeric parameter (columns in its order) also Page's test of a
    monotonic trend along it (scipy.stats.page_trend_test, for a rise and for a fall; pTrend is twice the
    smaller p, the two-sided p)."""
    from scipy import stats
    b, k = y.shape
    if np.all(y == y[:, :1]):  # no seed tells its values apart: no evidence of any effect (scipy divides by 0)
        chi2, p = 0.0, 1.0
    else:
        chi2, p = stats.friedmanchisquare(*y.T)
    res = y - y.mean(axis=1, keepdims=True) - y.mean(axis=0, keepdims=True) + y.mean()
    sr = float(np.sqrt((res**2).sum() / ((b - 1) * (k - 1))))
    z = stats.norm.ppf(1 - alpha / 2) + stats.norm.ppf(power)
    out = {'seeds': b, 'values': k, 'chi2': float(chi2), 'p': float(p), 'residualStd [%s]' % unit: sr,
           'detectableDifference [%s]' % unit: float(z * sr * np.sqrt(2 / b))}
    if numeric:
        rise = stats.page_trend_test(y)
        fall = stats.page_trend_test(y, predicted_ranks=list(range(k, 0, -1)))
        out.update(trend='rise' if rise.pvalue <= fall.pvalue else 'fall', pageL=float(max(rise.statistic, fall.statistic)),
                   pTrend=float(min(1.0, 2 * min(rise.pvalue, fall.pvalue))))
    return out


def save(fig, ax, xlabel, ylabel, title, path):
    """Label, grid and write a figure; returns its path."""
    import matplotlib.pyplot as plt
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=10)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return path


def aggregate(path, param=None, outDir=None, xlog='auto', figures=True):
    """Aggregate the study directory `path` into outDir (default <path>/aggregate): the CSV tables,
    the figures unless figures=False, and a report on standard output."""
    outDir = outDir or os.path.join(path, 'aggregate')
    if os.path.exists(outDir) and not os.path.isdir(outDir):
        raise StudyError('--out: %s exists and is not a directory' % outDir)
    data = StudyData(path, param)
    os.makedirs(outDir, exist_ok=True)
    runsCsv, statsCsv = writeCsv(data, outDir)
    print('%s: %s of %d rows; studied parameter %s (%s), %s' % (
        data.dir, count(len(data.runs), 'finished run'), len(data.info['rows']), data.param,
        count(len(data.values), 'value'), count(len(data.seeds), 'realization')))
    shas = data.codeVersions()
    if len(shas) > 1:
        print('warning: the runs were made by %d versions of the code (sha1 %s; None: runs without a code sha1)' % (
            len(shas), ', '.join(sorted(str(x)[:10] for x in shas))))
    if data.missing:
        print('not finished (left out): %d: %s%s' % (len(data.missing), ', '.join(data.missing[:8]),
                                                     ' ...' if len(data.missing) > 8 else ''))
    print('%-12s %3s  %22s  %22s  %16s  %20s' % (data.param, 'n', 'delta at peak [mm]', 'delta max [mm]', 'crushed',
                                                  'F at 1st crush [kN]'))
    for st in data.stats():
        print('%-12s %3d  %10.2f +- %8.2f  %10.2f +- %8.2f  %6.1f +- %5.1f  %8.0f +- %7.0f' % (
            label(st['value']), st['n'], st[data.peak + '_mean'] * 1e3, st[data.peak + '_std'] * 1e3, st['deltaMax_mean'] * 1e3,
            st['deltaMax_std'] * 1e3, st['nCrushed_mean'], st['nCrushed_std'], st['forceAtFirstCrush_mean'] / 1e3,
            st['forceAtFirstCrush_std'] / 1e3))
    test = effectTest(data)
    if test is not None:
        blocked = blockedTest(data, alpha=test['alpha'], power=test['power'])
        onset = blockedTest(data, 'forceAtFirstCrush', 'N', test['alpha'], test['power'])
        network = blockedTest(data, 'stressRatioAtHalfLoad', '-', test['alpha'], test['power'])
        with open(os.path.join(outDir, 'test.json'), 'w') as fh:
            json.dump(dict(test, blocked=blocked, onset=onset, network=network), fh, indent=1)
        print('Kruskal-Wallis across %s: H = %.3g, p = %.3g (%d groups, %d runs); a difference of two means of %.1f mm '
              'would have been found with probability %g at the %g level' % (
                  data.param, test['H'], test['p'], test['groups'], test['runs'], test['detectableDifference [m]'] * 1e3,
                  test['power'], test['alpha']))
        def trend(t):
            return '; Page trend: %s, p = %.3g' % (t['trend'], t['pTrend']) if 'trend' in t else ''
        if blocked is not None:
            print('Friedman across %s within seeds: chi2 = %.3g, p = %.3g (%d seeds complete); detectable difference %.1f mm%s' % (
                data.param, blocked['chi2'], blocked['p'], blocked['seeds'], blocked['detectableDifference [m]'] * 1e3, trend(blocked)))
        for what, t in (('applied force at the first crush', onset), ('largest sigma/f_t at Fmax/2 before a crush', network)):
            if t is not None:
                print('%s, within seeds: Friedman p = %.3g (%d seeds)%s' % (what, t['p'], t['seeds'], trend(t)))
    print('tables: %s, %s' % (runsCsv, statsCsv))
    if figures:
        print('figures: %s' % ', '.join(plots(data, outDir, xlog)))
    return data
