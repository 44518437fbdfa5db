"""Cycle jumping against direct simulation (docs/cycles.md, "Validation"), for any cyclic experiment whose runs
write cycles.csv (cycle, t, settlement; with jumping also settlementJumped) and crushes (t): each run of a study
simulated directly is paired with the run of the same seed and cycles made with jumping, and compared on the
cycles of the first crushes, the crushes and the settlement after the last cycle, and their CPU; a jumping run
longer than the direct runs of its seed is compared with the longest of them over the cycles both cover; the long
runs (jumping only) give settlement and crushes against log N. Reads the studies with ballast.study.data. No YADE."""
import numpy as np
import pandas as pd

from .pairs import bySeed, common
from .settlement import total
from ..study.data import StudyRuns

FIRST = 3   # the first crushes compared, by their cycle
# the tolerances, each relative to the direct run's value or absolute, whichever is larger (docs/cycles.md)
TOL_CYCLE = (0.10, 2)          # ([-], [cycles]) the cycle of each of the first crushes
TOL_CRUSHES = (0.20, 2)        # ([-], [crushes]) the crushes after the last cycle
TOL_SETTLEMENT = (0.25, 5e-5)  # ([-], [m]) the settlement after the last cycle (the jumped cycles' included)


def crushCycles(run):
    """The cycle (in the count, jumped cycles included) of every crush of the run: the n-th simulated cycle is the
    n-th row of cycles.csv, ending at its t [s]."""
    cyc, cr = run.cycles, run.crushes
    if cr is None or len(cr) == 0:
        return np.zeros(0, int)
    n = np.searchsorted(cyc.t.to_numpy(), cr.t.to_numpy(), side='left')     # rows ended before the crush
    counted = cyc.cycle.to_numpy()
    # after the last row: the cycle the run stopped in (a sleeper on the floor)
    return np.array([counted[k] if k < len(counted) else int(counted[-1]) + 1 for k in n], dtype=int)


def _settlement(run):
    """The settlement after the last cycle [m], the jumped cycles' worked out again from cycles.csv (as the code
    of today extrapolates them, whatever code made the run)."""
    c = run.cycles
    return float(total(c).iloc[-1])


def _within(a, b, tol):
    rel, absolute = tol
    return bool(abs(a - b) <= max(rel * abs(b), absolute))


def _runs(path, reference=None):
    """The runs of the study at path, and the direct runs of the study at reference (a variant of jumping
    compared with the direct runs another study made)."""
    if reference is not None:
        ref = _runs(reference)
        return pd.concat([_runs(path), ref[~ref.jump]], ignore_index=True)
    study = StudyRuns(path)
    rows = []
    for run in study.runs:
        p = run.params
        rows.append({'runId': run.runId, 'seed': int(p['seed']), 'cycles': int(p['cycles']), 'jump': bool(p['jump']),
                     'run': run})
    return pd.DataFrame(rows)


def _agreement(row, cd, cj):
    """The first FIRST crush cycles cd (direct) and cj (jumping) into row, each with whether it agrees, and whether
    the crushes and the settlement agree (row's crushesDirect, crushesJump, settlementDirect, settlementJump)."""
    for k in range(FIRST):
        a = int(cd[k]) if k < len(cd) else None
        b = int(cj[k]) if k < len(cj) else None
        row['crush%dDirect' % (k + 1)], row['crush%dJump' % (k + 1)] = a, b
        row['crush%dAgrees' % (k + 1)] = (a is None and b is None) or (
            a is not None and b is not None and _within(b, a, TOL_CYCLE))
    row['crushesAgree'] = _within(row['crushesJump'], row['crushesDirect'], TOL_CRUSHES)
    row['settlementAgrees'] = _within(row['settlementJump'], row['settlementDirect'], TOL_SETTLEMENT)
    row['cpuRatio'] = row['cpuJump'] / row['cpuDirect']
    return row


def compare(path, reference=None):
    """Per seed and cycle count run both ways: a DataFrame with, for direct (d) and jumping (j), the cycles
    simulated, the CPU [s], the first FIRST crush cycles, the crushes and the settlement [m] after the last cycle,
    and whether each agrees within its tolerance. reference: a study whose direct runs are compared with the
    jumping runs of path."""
    runs = _runs(path, reference)
    key = ['seed', 'cycles']
    direct = bySeed(runs[~runs.jump], 'compare: the direct runs of %s' % path, key)
    jumping = bySeed(runs[runs.jump], 'compare: the jumping runs of %s' % path, key)
    out = []
    for seed, cycles in common(direct, jumping):
        d, j = direct.loc[(seed, cycles), 'run'], jumping.loc[(seed, cycles), 'run']
        row = {'seed': seed, 'cycles': cycles, 'simulatedDirect': len(d.cycles), 'simulatedJump': len(j.cycles),
               'cpuDirect': d.summary['cpuSeconds'], 'cpuJump': j.summary['cpuSeconds'],
               'crushesDirect': int(d.summary['nCrushed']), 'crushesJump': int(j.summary['nCrushed']),
               'settlementDirect': _settlement(d), 'settlementJump': _settlement(j)}
        out.append(_agreement(row, crushCycles(d), crushCycles(j)))
    return pd.DataFrame(out)


def covered(path, reference=None):
    """Every jumping run longer than the longest direct run of its seed, compared with that run over the cycles
    both cover (1 to the direct run's last cycle N_d): the first FIRST crush cycles, the crushes up to N_d, the
    settlement at N_d (at settledAt, the jumping run's last simulated cycle up to N_d, its jumped cycles' included),
    each with whether it agrees; the CPU of the whole jumping run against the direct run's (cpuRatio)."""
    runs = _runs(path, reference)
    out = []
    for seed, g in runs.groupby('seed'):
        direct = g[~g.jump]
        if not len(direct):
            continue
        d = direct.loc[direct.cycles.idxmax()]
        dr = d.run
        Nd = int(dr.cycles.cycle.iloc[-1])
        cd = crushCycles(dr)
        for _, j in g[g.jump & (g.cycles > d.cycles)].sort_values('cycles').iterrows():
            jr = j.run
            c = jr.cycles
            settled = total(c)
            upTo = c.cycle.to_numpy() <= Nd
            cj = crushCycles(jr)
            cj = cj[cj <= Nd]
            row = {'seed': seed, 'runId': j.runId, 'cycles': int(jr.summary['cycles']), 'covered': Nd,
                   'settledAt': int(c.cycle[upTo].iloc[-1]) if upTo.any() else None,
                   'simulatedDirect': len(dr.cycles), 'simulatedJump': len(c),
                   'cpuDirect': dr.summary['cpuSeconds'], 'cpuJump': jr.summary['cpuSeconds'],
                   'crushesDirect': int(np.sum(cd <= Nd)), 'crushesJump': len(cj),
                   'settlementDirect': _settlement(dr),
                   'settlementJump': float(settled[upTo].iloc[-1]) if upTo.any() else float('nan')}
            out.append(_agreement(row, cd[cd <= Nd], cj))
    return pd.DataFrame(out)


def longRuns(path, atLeast=1000):
    """The jumping runs of at least `atLeast` cycles: cycles, simulated, jumps, CPU [s], crushes, settlement [m]
    (the jumped cycles' included) and its extrapolated part (both as the code of today extrapolates them)."""
    runs = _runs(path)
    out = []
    for _, r in runs[runs.jump & (runs.cycles >= atLeast)].iterrows():
        s = r.run.summary
        out.append({'runId': r.runId, 'seed': r.seed, 'cycles': int(s['cycles']), 'simulated': s['cyclesSimulated'],
                    'jumps': s['jumps'], 'cpuSeconds': s['cpuSeconds'], 'crushes': int(s['nCrushed']),
                    'settlement': _settlement(r.run),
                    'settlementJumped': _settlement(r.run) - float(r.run.cycles.settlement.iloc[-1]),
                    'stoppedBy': s.get('stoppedBy')})
    return pd.DataFrame(out)


def figure(path, out, reference=None):
    """Settlement (jumped cycles' included), crushes and the largest fatigue damage (where cycles.csv has it)
    against log N: every run, direct solid, jumping dashed (dotted beyond 1 000 cycles), one colour per seed (the
    direct runs of reference too)."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    from ..runfiles import saveFigure
    runs = _runs(path, reference)
    fig, (ax, bx, cx) = plt.subplots(3, 1, figsize=(7, 9.6), sharex=True)
    seeds = sorted(runs.seed.unique())
    for _, r in runs.sort_values(['seed', 'cycles', 'jump']).iterrows():
        c = r.run.cycles
        colour = 'C%d' % (seeds.index(r.seed) % 10)
        style = '-' if not r.jump else ('--' if r.cycles <= 1000 else ':')
        label = 'seed %d, %s, %d cycles' % (r.seed, 'jumping' if r.jump else 'direct', r.cycles)
        ax.semilogx(c.cycle, 1e3 * total(c), style, color=colour, lw=1.2 if not r.jump else 1.0, label=label)
        cc = crushCycles(r.run)
        if len(cc):
            n = np.sort(cc)
            bx.step(np.concatenate([[1], n]), np.arange(len(n) + 1), style, color=colour, where='post', lw=1.0)
        if 'maxDamage' in c:
            cx.semilogx(c.cycle, c.maxDamage, style, color=colour, lw=1.0)
    ax.set_ylabel('permanent settlement [mm]\n(jumped cycles extrapolated)')
    bx.set_ylabel('crushes so far')
    cx.set_ylabel('largest fatigue damage D [-]')
    cx.set_xlabel('load cycles N')
    for a in (ax, bx, cx):
        a.grid(True, which='both', alpha=0.3)
    ax.legend(fontsize=6, ncol=2)
    ax.set_title('Cycle jumping against direct simulation: %s' % path.rstrip('/').split('/')[-1], fontsize=9)
    fig.tight_layout()
    saveFigure(fig, out)
    plt.close(fig)


def verdict(table):
    """How many pairs agree on each compared quantity (of those compared), of compare's or covered's table."""
    cols = ['crush%dAgrees' % (k + 1) for k in range(FIRST)] + ['crushesAgree', 'settlementAgrees']
    return {c: '%d of %d' % (int(table[c].sum()), len(table)) for c in cols} if len(table) else {}
