"""What the single-particle test leaves (docs/calibration.md): strengths.csv (a row per grain),
curves.csv (every grain's F-displacement curve up to its crush), summary.json (the statistics),
weibull.png (ln ln(1/P_s) against ln(F/d^2) per size class) and size.png (the characteristic F/d^2
against the diameter, log axes)."""
import json
import math
import os
import time

import numpy as np
import pandas as pd

from ...runfiles import plainLogTicks, saveFigure, strictJson, writeAtomic
from . import strengths

UNLOADED = 0.1   # [-] a grain not crushed whose force never passed this share of its closed-form force carried no load

STRENGTH_COLUMNS = ['grain', 'diameter', 'sizeClass', 'crushed', 'force', 'forceBottom', 'displacement',
                    'forceOverD2', 'criterionStress', 'strength', 'expectedForce', 'time']


def table(exp):
    """strengths.csv as a DataFrame: per grain its diameter [m], size class, whether it crushed, the force on
    its top and bottom platens [N] and the platens' displacement [m] at the crush (or at maxStrain), F/d^2
    [Pa], the criterion's stress and the strength at the crush [Pa] (the engine's event), the closed-form
    force of the characteristic strength [N] and the loading time of the crush [s]."""
    p, t = exp.p, exp.tester
    d = np.array(t.d)
    cls, _ = strengths.classes(d, min(d.min(), p['dMin']), max(d.max(), p['dMax']), p['classes'])
    # a grain that is not a sphere: the closed form at its height between the platens (a state of before has none)
    h = [t.h[k] if p['grain'] != 'sphere' and k < len(t.h) else None for k in range(len(d))]
    rows = [(k, d[k], int(cls[k]), r['crushed'], r['F'], r['Fbottom'], r['displacement'], r['F'] / d[k] ** 2,
             r['value'], r['strength'], float(p.expectedForce(d[k], h[k])), r['t']) for k, r in enumerate(t.result)]
    return pd.DataFrame(rows, columns=STRENGTH_COLUMNS)


def summary(exp, s=None):
    """Counts, the quasi-static check, the Weibull fit of F/d^2 per size class, the size law fitted to every
    grain (of F/d^2, and of the criterion's stress: that one recovers ft0, m and the Weibull modulus), the
    closed-form check of a deterministic strength, the cost and every parameter."""
    p = exp.p
    s = table(exp) if s is None else s
    c = s[s.crushed]
    wall, cpu = exp.seconds()
    lo, hi = min(s.diameter.min(), p['dMin']), max(s.diameter.max(), p['dMax'])
    _, edges = strengths.classes(s.diameter, lo, hi, p['classes'])
    classes = []
    for k in range(p['classes']):
        g = c[c.sizeClass == k]
        classes.append({'class': k, 'dLow': float(edges[k]), 'dHigh': float(edges[k + 1]), 'n': int(len(g)),
                        'dMean': float(g.diameter.mean()) if len(g) else None,
                        'weibull': strengths.weibullFit(g.forceOverD2) if len(g) else None})
    out = {'experiment': exp.NAME, 'runId': exp.runId,   # as every experiment's summary names itself
           'n': int(len(s)), 'nCrushed': int(len(c)), 'nNotCrushed': int(len(s) - len(c)),
           'criterion': p['criterion'],
           'forceOverD2Min': float(c.forceOverD2.min()) if len(c) else None,
           'forceOverD2Max': float(c.forceOverD2.max()) if len(c) else None,
           # quasi-static: the grain's inertia, |F_top - F_bottom| / F_top at the crush, a small share of the load
           'inertiaRatioMax': float(np.max(np.abs(c.force - c.forceBottom) / c.force)) if len(c) else None,
           'classes': classes}
    try:
        out['sizeLawForceOverD2'] = strengths.sizeLawFit(c.diameter / 2, c.forceOverD2)
        out['sizeLawCriterion'] = strengths.sizeLawFit(c.diameter / 2, c.criterionStress)
    except ValueError as e:
        out['sizeLawForceOverD2'] = out['sizeLawCriterion'] = None
        out['sizeLawNote'] = str(e)
    unloaded = unloadedGrains(exp, s)
    out['nUnloaded'] = len(unloaded)
    out['warnings'] = exp.warnings() + ([
        '%d grain(s) not crushed never carried %g of the force their strength crushes them at (grains %s): they '
        'slid or tipped out from between the platens (a shape with no flat side does), so their strengths are not '
        'measured' % (len(unloaded), UNLOADED, ', '.join(map(str, unloaded[:10])) + (' ...' if len(unloaded) > 10
                                                                                    else ''))] if unloaded else [])
    if p['weibullModulus'] == 0 and len(c):  # every grain at its characteristic strength: the closed form
        out['closedFormErrorMax'] = float(np.max(np.abs(c.force / c.expectedForce - 1)))
    out.update({'steps': int(sum(exp.phases.steps.values())), 'wallSeconds': wall, 'cpuSeconds': cpu,
                'cpuSecondsPerGrain': cpu / max(len(s), 1), 'params': dict(p),
                'created': time.strftime('%Y-%m-%dT%H:%M:%S')})
    return out


def unloadedGrains(exp, s):
    """The grains of the strengths table s that did not crush and whose force on the top platen over their whole
    curve stayed below UNLOADED of their closed-form force (expectedForce): they carried no load."""
    curves = pd.DataFrame(exp.tester.curves, columns=['grain', 'time', 'displacement', 'force'])
    peak = curves.groupby('grain').force.max()
    top = peak.reindex(s.grain).fillna(0.0).to_numpy()
    return [int(g) for g in s.grain[(~s.crushed.to_numpy(bool)) & (top < UNLOADED * s.expectedForce.to_numpy())]]


def write(exp, summary, s):
    """Every file written atomically (a killed test leaves whole files or none), summary.json last; s: the
    strengths table the summary was made from (table)."""
    out = exp.out
    writeAtomic(os.path.join(out, 'strengths.csv'), s.to_csv(index=False, float_format='%.9g'))
    writeAtomic(os.path.join(out, 'curves.csv'), pd.DataFrame(
        exp.tester.curves, columns=['grain', 'time', 'displacement', 'force']).to_csv(index=False, float_format='%.9g'))
    figures(exp, s, summary)
    writeAtomic(os.path.join(out, 'summary.json'), json.dumps(strictJson(summary), indent=1))


def figures(exp, s, summary):
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    c = s[s.crushed]
    fig, ax = plt.subplots(figsize=(9.5, 5))
    for cl in summary['classes']:
        g = c[c.sizeClass == cl['class']]
        if len(g) == 0:
            continue
        sig, ps = strengths.survival(g.forceOverD2)
        label = '%.1f-%.1f mm (%d)' % (1e3 * cl['dLow'], 1e3 * cl['dHigh'], len(g))
        line, = ax.plot(np.log(sig / 1e6), np.log(np.log(1 / ps)), 'o', ms=4, label=label)
        w = cl['weibull']
        if w and math.isfinite(w['modulus']):
            x = np.linspace(np.log(sig.min() / 1e6), np.log(sig.max() / 1e6), 20)
            ax.plot(x, w['modulus'] * (x - np.log(w['scale'] / 1e6)), '-', color=line.get_color(), lw=0.8,
                    label='  k = %.2f [%.2f, %.2f], $\\sigma_0$ = %.1f MPa' % (w['modulus'], w['modulusLow'],
                                                                          w['modulusHigh'], w['scale'] / 1e6))
    ax.set_xlabel('ln($F/d^2$ [MPa])')
    ax.set_ylabel('ln ln(1/$P_s$)')
    ax.set_title('single-particle crushing %s: %d grains, %s,\n$f_{t0}$ = %g Pa m, m = %g, Weibull modulus %g' % (
        exp.runId, len(s), exp.p['criterion'], exp.p['ft0'], exp.p['m'], exp.p['weibullModulus']), fontsize=8)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc='upper left', bbox_to_anchor=(1.02, 1.0), borderaxespad=0)   # beside, not on the points
    fig.tight_layout()
    saveFigure(fig, os.path.join(exp.out, 'weibull.png'))
    fig, ax = plt.subplots(figsize=(6, 4.5))
    ax.loglog(1e3 * c.diameter, c.forceOverD2 / 1e6, '.', color='0.6', label='each grain')
    fit = [cl for cl in summary['classes'] if cl['weibull']]
    if fit:
        d = np.array([1e3 * cl['dMean'] for cl in fit])
        s0 = np.array([cl['weibull']['scale'] for cl in fit]) / 1e6
        err = np.array([[cl['weibull']['scale'] - cl['weibull']['scaleLow'], cl['weibull']['scaleHigh'] - cl['weibull']['scale']]
                        for cl in fit]).T / 1e6
        ax.errorbar(d, s0, yerr=err, fmt='s', color='C0', label='$\\sigma_0$ per class (95 %)')
    law = summary.get('sizeLawForceOverD2')
    if law:
        r = np.linspace(c.diameter.min(), c.diameter.max(), 20) / 2
        ax.loglog(2e3 * r, law['s0'] * r ** -law['b'] / 1e6, 'k--', lw=0.8,
                  label='$\\sigma_0 \\propto d^{-b}$, b = %.2f [%.2f, %.2f]' % (law['b'], law['bLow'], law['bHigh']))
    ax.set_xlabel('diameter d [mm]')
    ax.set_ylabel('$F/d^2$ at the crush [MPa]')
    plainLogTicks(ax, 'xy')   # within a decade matplotlib labels only a few minor ticks (30, 40, 80-100 MPa)
    ax.grid(alpha=0.3, which='both')
    ax.legend(fontsize=8)
    fig.tight_layout()
    saveFigure(fig, os.path.join(exp.out, 'size.png'))
