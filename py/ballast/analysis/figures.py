"""The figures of a study (docs/studies.md, "Aggregating"), each drawn when the runs have what it shows:

    response.png     the response the experiment declares (the oedometer's displacement at peak force, Fig. 5 of
                     the paper; the box's settlement) against the parameter: one grey line per realization, mean +-
                     standard deviation as error bars
    fd_curves.png    runs with an F-delta curve (fd.csv): one panel per value of the studied parameter, a line per
                     seed (Fig. 4)
    checks.png       runs with a per-check log: grains crushed, sigma/f_t at a crush, the onset and the force
                     network at half the peak load, per value (ballast.experiments.oedometer.checkstats)

and the axis of a studied parameter the other analyses draw on. matplotlib (Agg), no YADE.
"""
import math
import os

import numpy as np

from ..study.aggregate import count, label, stats
from ..runfiles import column
from .effects import unitOf

LABELS = {'f': 'loading frequency f [Hz]', 'Tc': 'crushing period $T_c$ [s]', 'rMin': '$r_{min}$ [m]', 'ft0': '$f_{t0}$ [Pa m]',
          'gamma': r'reduction factor $\gamma$ [-]', 'pattern': 'replacement pattern'}


# results drawn and printed in a unit of their size: [m] in mm, [N] in kN, [Pa] in MPa
SHOWN = {'m': ('mm', 1e3), 'N': ('kN', 1e-3), 'Pa': ('MPa', 1e-6)}


def shown(unit):
    """(the unit a result declared in `unit` is drawn and printed in, the factor to it)."""
    return SHOWN.get(unit, (unit, 1.0))


def valueLabel(data, v):
    """'f = 8 Hz': a value of the studied parameter of `data` with its unit (from its declaration)."""
    params = data.declaration.params
    unit = params[data.param].unit if data.param in params else '-'
    return '%s = %s%s' % (data.param, label(v), '' if unit in ('-', '') else ' ' + unit)


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


def appliedForce(fd):
    """The paper's F of an F-delta curve (fd.csv as a DataFrame): the load applied (Fapplied, the plate
    load's), else the grains' force on the plate."""
    if 'Fapplied' in fd and np.isfinite(column(fd, 'Fapplied')).all():
        return column(fd, 'Fapplied')
    return column(fd, 'F')


def paramLabel(data):
    """The studied parameter's axis label: LABELS', else its name and declared unit."""
    params = data.declaration.params
    return LABELS.get(data.param) or '%s [%s]' % (data.param, params[data.param].unit if data.param in params else '-')


def plots(data, outDir, xlog='auto'):
    """The figures of `data` (ballast.study.data.StudyData) its runs have what for (see the module's doc), in
    outDir; returns their paths."""
    import matplotlib
    matplotlib.use('Agg')
    x, ticks, scale = axisPositions(data, xlog)
    out = [fdCurves(data, outDir), responsePlot(data, outDir, x, ticks, scale), checksPlot(data, outDir, x, ticks, scale)]
    return [p for p in out if p]


def fdCurves(data, outDir):
    """fd_curves.png (Fig. 4): F-delta of every run with an fd.csv, a panel per value (small multiples), a colour
    per seed; None if no run has one."""
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    if not any(r.fd is not None and 'delta' in r.fd for r in data.runs):
        return None
    name = os.path.basename(data.dir)
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
        for r in sorted([r for r in data.runs if r.value == v], key=lambda r: str(r.seed)):
            if r.fd is None or not len(r.fd):
                continue
            ax.plot(column(r.fd, 'delta') * 1e3, appliedForce(r.fd) / 1e3, color=seedColor[r.seed], lw=0.9,
                    label='seed %s' % r.seed)
        ax.set_title('%s (%s)' % (valueLabel(data, v), count(sum(r.value == v for r in data.runs), 'run')), fontsize=9)
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
    path = os.path.join(outDir, 'fd_curves.png')
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def responsePlot(data, outDir, x, ticks, scale):
    """response.png: the declared response against the parameter (the oedometer's: Fig. 5), in the unit the report
    prints it in; None without a response."""
    import matplotlib.pyplot as plt
    r = data.response
    if r is None:
        return None
    unit, k = shown(unitOf(data, r))
    fig, ax = plt.subplots(figsize=(8, 5))
    for s in data.seeds:
        rs = sorted([run for run in data.runs if run.seed == s and run.summary.get(r) is not None],
                    key=lambda run: data.values.index(run.value))
        ax.plot([x[run.value] for run in rs], [run.summary[r] * k for run in rs], '-o', color='0.7', lw=0.8, ms=2.5,
                zorder=1)  # markers: a realization with one value shows too
    st = stats(data)
    ax.errorbar([x[s['value']] for s in st], [s[r + '_mean'] * k for s in st],
                yerr=[0 if math.isnan(s[r + '_std']) else s[r + '_std'] * k for s in st],
                fmt='o', color='C0', ecolor='C0', capsize=4, lw=1.5, zorder=3, label='mean $\\pm$ standard deviation')
    ax.plot([], [], '-o', color='0.7', ms=2.5, label='one realization (seed)')
    paramAxis(ax, data.values, x, ticks, scale)
    ax.legend(fontsize=8)
    return save(fig, ax, paramLabel(data), '%s [%s]' % (r, unit), '%s: %s, %s' % (
        os.path.basename(data.dir), count(len(data.runs), 'run'), count(len(data.seeds), 'realization')),
        os.path.join(outDir, 'response.png'))


def checksPlot(data, outDir, x, ticks, scale):
    """checks.png: from the per-check logs, per value of the parameter, the grains crushed per run and the
    largest sigma/f_t of a grain when it crushed (how far above their strength rare checks find grains),
    a point per run, the mean as a bar; the applied force at the first crush and the largest sigma/f_t at
    half the peak load before any crush (halfLoadRatio), a line per seed (a quasi-static onset and force
    network are flat along it). None if no run has a log."""
    import matplotlib.pyplot as plt
    runs = [r for r in data.runs if r.summary.get('crushingChecks') is not None]
    if not runs:
        return None
    fig, axes = plt.subplots(1, 4, figsize=(20, 4.3))
    xs0 = sorted(x.values())
    # the runs of a value spread over +-0.15 of the spacing of the values (a factor on a log axis)
    step = (xs0[-1] / xs0[0]) ** (1 / max(len(xs0) - 1, 1)) if scale == 'log' else \
        (min(np.diff(xs0)) if len(xs0) > 1 else 1.0)
    for ax, key in ((axes[0], 'nCrushed'), (axes[1], 'ratioAtCrushMax')):
        for v in data.values:
            ys = np.array([r.summary[key] for r in runs if r.value == v and r.summary.get(key) is not None], float)
            if not ys.size:
                continue
            jitter = np.linspace(-0.15, 0.15, ys.size) if ys.size > 1 else np.zeros(1)
            xs = x[v] * step ** jitter if scale == 'log' else x[v] + jitter * step
            ax.plot(xs, ys, 'o', ms=3.5, color='0.45', alpha=0.8, zorder=2)
            ax.plot(x[v], ys.mean(), '_', ms=22, mew=2.5, color='C3', zorder=3)
        ax.plot([], [], 'o', ms=3.5, color='0.45', label='one run')
    axes[1].axhline(1.0, color='k', lw=0.8, ls=':')
    for ax, key, scale1 in ((axes[2], 'forceAtFirstCrush', 1e-3), (axes[3], 'stressRatioAtHalfLoad', 1.0)):
        got = [(r.seed, r.value, r.summary[key] * scale1) for r in runs if r.summary.get(key) is not None]
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
        ax.set_xlabel(paramLabel(data))
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle('%s: the per-check log of %s' % (os.path.basename(data.dir), count(len(runs), 'run')), fontsize=10)
    return writeFigure(fig, os.path.join(outDir, 'checks.png'))


def save(fig, ax, xlabel, ylabel, title, path):
    """Label, grid and write a figure; returns its path."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=10)
    ax.grid(alpha=0.3)
    return writeFigure(fig, path)


def writeFigure(fig, path, dpi=130):
    """A figure laid out (tight_layout), written to path at `dpi` and closed; returns path."""
    import matplotlib.pyplot as plt
    fig.tight_layout()
    fig.savefig(path, dpi=dpi)
    plt.close(fig)
    return path
