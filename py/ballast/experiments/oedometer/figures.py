"""The oedometer's figures (docs/oedometer.md, "Output"): fd.png, grading.png, cycles.png. Written
atomically (ballast.runfiles.saveFigure), matplotlib's Agg backend (no display)."""
import os

import numpy as np

from ... import grading
from ...runfiles import plainLogTicks, saveFigure


def cyclesFigure(exp, table):
    """cycles.png: permanent settlement and B_g against the number of cycles (log axis), from cycles.csv's table."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    c = table
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.semilogx(c.cycle, c.settlement * 1e3, 'o-', color='C0', label='permanent settlement')
    if exp.jumper is not None and exp.jumper.jumps:   # the jumped cycles' settlement, extrapolated
        ax.semilogx(c.cycle, (c.settlement + c.settlementJumped) * 1e3, 'x:', color='C0',
                    label="with the jumped cycles' settlement (a + b ln n)")
        ax.legend(fontsize=8, loc='upper left')
    ax.set_xlabel('load cycles N')
    plainLogTicks(ax)
    ax.set_ylabel('settlement [mm]', color='C0')
    ax.grid(alpha=0.3, which='both')
    ax2 = ax.twinx()
    ax2.semilogx(c.cycle, c.Bg, 's--', color='C3', label='$B_g$')
    ax2.set_ylabel("Marsal's $B_g$ [%]", color='C3')
    ax.set_title('%s: %d cycles between %g and %g kN at %g Hz%s' % (
        exp.runId, int(c.cycle.iloc[-1]), exp.p['Fmin'] / 1e3, exp.p['Fmax'] / 1e3, exp.p['f'],
        ' (%d simulated)' % len(c) if len(c) != int(c.cycle.iloc[-1]) else ''), fontsize=9)
    fig.tight_layout()
    saveFigure(fig, os.path.join(exp.out, 'cycles.png'))

def gradingFigure(exp, summary, before, after):
    """grading.png: the grading before and after loading, with the boundary of maximum breakage (BBI)."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.semilogx(grading.SIEVES_MM, before, 'o-', label='before loading')
    ax.semilogx(grading.SIEVES_MM, after, 's-', label='after loading%s' % (
        ' (lost volume as fines)' if summary['lostAsFines'] else ''))
    ax.semilogx([grading.BBI_FINEST_MM, grading.topSize(before)], [0, 100], 'k--', lw=0.8,
                label='boundary of maximum breakage (BBI)')
    ax.set_xlabel('sieve size [mm]')
    ax.set_ylabel('passing by mass [%]')
    ax.set_ylim(0, 100)
    ax.set_title('grading %s: $B_g$ = %.1f %%, $B_r$ = %.3f, BBI = %.3f'
                 % (exp.runId, summary['Bg'], summary['Br'], summary['BBI']), fontsize=9)
    ax.grid(alpha=0.3, which='both')
    ax.legend(fontsize=8)
    fig.tight_layout()
    saveFigure(fig, os.path.join(exp.out, 'grading.png'))

def fdFigure(exp, rows, events):
    """fd.png: F-delta with the crushes marked, and F(t) against eq. 8."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    p = exp.p
    a = np.array(rows)
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(11, 4.5), gridspec_kw={'width_ratios': [3, 2]})
    ax.plot(a[:, 2] * 1e3, a[:, 1] / 1e3, '-', lw=0.8, color='C0', label='force of the grains on the plate')
    if np.isfinite(a[:, 5]).any():
        ax.plot(a[:, 2] * 1e3, a[:, 5] / 1e3, '-', lw=0.8, color='C1', alpha=0.7, label='applied force (eq. 8)')
    tc = np.array([e['t'] - exp.loading.t0 for e in events if e['kind'] == 'crush'])
    if len(tc):
        ax.plot(np.interp(tc, a[:, 0], a[:, 2]) * 1e3, np.interp(tc, a[:, 0], a[:, 1]) / 1e3, 'x', ms=4, color='C3',
                label='crushing (%d)' % len(tc))
    ax.set_xlabel('plate displacement $\\delta$ [mm]')
    ax.set_ylabel('force F [kN]')
    ax.set_title('oedometric test %s: seed %d, f = %g Hz, $T_c$ = %s, $f_{t0}$ = %g Pa m, pattern %s\n%s law, %s load%s' % (
        exp.runId, p['seed'], p['f'], ('%g s' % p['Tc']) if p['Tc'] > 0 else 'every step', p['ft0'], p['pattern'],
        p['law'], p['loadMode'], (', fatigue b = %g' % p['fatigueExponent']) if p['fatigue'] else ''), fontsize=8)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc='upper left')
    t = np.linspace(0, a[-1, 0], 400)
    ax2.plot(a[:, 0] * 1e3, a[:, 1] / 1e3, lw=0.8, label='grains on the plate')
    ax2.plot(t * 1e3, exp.loading.target(t) / 1e3, '--', color='k', lw=0.8, label='eq. 8')
    ax2.set_xlabel('loading time t [ms]')
    ax2.set_ylabel('force F [kN]')
    ax2.grid(alpha=0.3)
    ax2.legend(fontsize=8)
    fig.tight_layout()
    saveFigure(fig, os.path.join(exp.out, 'fd.png'))
