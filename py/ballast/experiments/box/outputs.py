"""What the box test writes (docs/box.md, "Outputs"), in <results>/<run id>/:

* cycles.csv     a row per cycle: permanent settlement at its end [m], largest settlement in it, resilient
                 deflection, work of the load over it [J], crushes, abrasions, the largest fatigue damage; with
                 jump, a row per simulated cycle, with the cycles jumped before it and the settlement extrapolated
                 over them [m] (settlementJumped: the total is settlement + settlementJumped)
* jumps.csv      with jump: every jump (cycle, cycles jumped, what bounded it, the largest damage rate, the
                 settlement law a + b ln N fitted to the simulated cycles and the settlement it extrapolated,
                 the states saved before and after)
* samples.csv    `samples` rows a cycle, appended as they are taken: applied load and the grains' force on the
                 sleeper [N], settlement [m], tilt [rad], crushes and abrasions so far (a run that goes on
                 from a state: from there)
* grading.csv    percentage passing each sieve (grading.SIEVES_MM) after cycles 0, 1, 2, 5, 10, 20, ... and
                 the last, with Marsal's B_g, Hardin's B_r and Indraratna's BBI against cycle 0
* crushes.csv    every crush: time, cycle, position, radius, depth below the sleeper's underside, zone
* zones.csv      crushes by zone (under the sleeper, beside it, at the walls) and depth band
* summary.json   the run: settlement, resilient deflection, crushes, where they were, the mass ledger, CPU
* settlement.png settlement and resilient deflection against N (log N); breakage.png the crushes over the
                 box's section with the sleeper; grading.png the gradings
* boxes.pvd      with vtk: grains, contacts and the sleeper and box every vtk cycles and at the end (ParaView)
"""
import json
import math
import os

import numpy as np
import pandas as pd
from yade import O

from ... import grading as gr
from ...engines import BallastAbrasionEngine, BallastCrushEngine
from ...runfiles import plainLogTicks, saveFigure, strictJson, writeAtomic
from .. import cyclic, grains
from ..breakage import engines, massLost
from ..vtk import dataArray, unstructuredGrid, writeContactsVtu, writePvd
from . import zones


def crushes(exp):
    """Every crush as a DataFrame: t [s] since cycling began, cycle, x, y, z [m], radius [m], depth [m] below the
    sleeper's underside at the start, zone."""
    rec, p = exp.recorder, exp.p
    ev = [e for eng in O.engines if isinstance(eng, BallastCrushEngine) for e in eng.events]
    t = np.array([e['t'] - rec.t0 for e in ev])
    xyz = np.array([e['pos'] for e in ev]).reshape(-1, 3)
    # the cycle in the count: the n-th simulated cycle is the n-th row of cycles.csv (later: n + the cycles jumped)
    closed = [int(c[0]) for c in rec.cycles]
    simulated = np.floor(t / rec.period).astype(int) + 1 if len(ev) else np.zeros(0, int)
    cycle = [closed[n - 1] if n <= len(closed) else n + rec.jumped for n in simulated]
    df = pd.DataFrame({'t': t, 'cycle': cycle, 'id': [e['id'] for e in ev],
                       'x': xyz[:, 0], 'y': xyz[:, 1], 'z': xyz[:, 2], 'radius': [e['radius'] for e in ev],
                       'depth': exp.initial['zBase'] - xyz[:, 2]})
    df['zone'] = zones.zoneOf(df.x, df.y, **p.geometry())
    return df


OWN_COLUMNS = ('settlementPeak', 'work', 'tilt')   # cycles.csv beyond the shared ones: the deepest settlement [m],
#                                                   the work of the load [J] over the cycle, the sleeper's tilt [rad]


def cycleTable(exp):
    """cycles.csv as a DataFrame (the shared schema, experiments.cyclic, then OWN_COLUMNS)."""
    rec = exp.recorder
    frame = cyclic.table([dict(zip(rec.CYCLE_COLUMNS, row)) for row in rec.cycles], OWN_COLUMNS, exp.jumper,
                         exp.stepChoice)
    frame['complete'] = (frame.cycle != rec.partial).astype(int)   # 0: the cycle the sleeper on the floor cut short
    return frame


def summary(exp):
    p, rec = exp.p, exp.recorder
    cyc = cycleTable(exp)
    c = crushes(exp)
    first = exp.initial['nGrainsInitial']
    original = len(set(exp.initial['ids']) & {int(i) for i in c.id})   # grains of the bed at the start that crushed
    x, r, m = grains.arrays()
    lost = massLost()
    wall, cpu = exp.seconds()
    n = len(cyc)
    where = zones.localCharacter(c.x, c.y, c.z, exp.initial['zBase'], original, first, p.geometry())
    return {
        'experiment': exp.NAME, 'runId': exp.runId, 'params': dict(p), 'cycles': n,
        'settlement': float(cyc.settlement.iloc[-1]) if n else 0.0,
        'resilient': float(cyc.resilient.iloc[-1]) if n else 0.0,
        'settlementFirstCycle': float(cyc.settlement.iloc[0]) if n else 0.0,
        'nCrushed': int(sum(e.nCrushed for e in engines() if isinstance(e, BallastCrushEngine))),
        'nAbraded': int(sum(e.nAbraded for e in engines() if isinstance(e, BallastAbrasionEngine))),
        'maxDamage': float(cyc.maxDamage.max()) if n else 0.0,
        'maxStressRatio': float(cyc.maxStressRatio.max()) if n else math.nan,
        'workPerCycleMean': float(cyc.work.mean()) if n else 0.0,
        'nGrainsInitial': first, 'nGrains': len(r), 'porosity': exp.porosity, 'bedTop': exp.bedTop,
        'nEscaped': exp.nEscaped, 'nCrib': exp.nCrib, 'bedFile': exp.bedFile, 'loadSource': p.history().source, 'loadPeriod': rec.period,
        'seatLoad': p.history().seat, 'peakLoad': p.history().peak,
        'massInitial': exp.initial['massInitial'], 'massGrains': float(np.sum(m)), 'massLost': lost,
        'massLedgerError': float(np.sum(m)) + lost - exp.initial['massInitial'],
        'local': where, 'zones': zones.table(c.x, c.y, c.z, exp.initial['zBase'], p.geometry()),
        'gradings': [{k: g[k] for k in ('cycle', 'Bg', 'Br', 'BBI')} for g in exp.gradings],
        'dt': O.dt, 'steps': O.iter, 'wallSeconds': wall, 'cpuSeconds': cpu,
        'cpuSecondsPerCycle': float(np.nanmedian(cyc.cpuSeconds)) if n and cyc.cpuSeconds.notna().any() else math.nan,
        # the steps the cycles took (their median, as cpuSecondsPerCycle), not the period over the last step
        'stepsPerCycle': (float(np.nanmedian(cyc.stepsPerCycle)) if n and cyc.stepsPerCycle.notna().any()
                          else rec.period / O.dt), **cyclic.jumpSummary(cyc, exp.jumper),
        'warnings': exp.warnings() + list(exp.rangeWarnings),   # its parameters', then where the run went
        **({'stoppedBy': 'sleeperOnFloor'} if exp.onFloor else {}),
        # cut short on the floor: the whole cycles before it; settlement and counts are those at the stop
        **({'cycles': int(rec.partial) - 1, 'stoppedInCycle': int(rec.partial)} if rec.partial else {})}


def cutSamples(exp, t):
    """samples.csv back to its rows taken before `t` [s since cycling began]: a killed run resumed from a state saved
    at t takes the later ones again."""
    path = os.path.join(exp.out, 'samples.csv')
    if os.path.exists(path):
        with open(path) as fh:
            lines = fh.readlines()
        writeAtomic(path, ''.join(lines[:1] + [l for l in lines[1:] if float(l.split(',', 1)[0]) < t]))


def writeCycles(exp):
    cyclic.write(os.path.join(exp.out, 'cycles.csv'), cycleTable(exp))


def write(exp):
    """Every output file; returns the summary."""
    out = exp.out
    s = summary(exp)
    files = {'cycles.csv': cycleTable(exp), 'crushes.csv': crushes(exp)}
    g = pd.DataFrame([dict({'cycle': x['cycle'], 'Bg': x['Bg'], 'Br': x['Br'], 'BBI': x['BBI']},
                           **{'P%g' % a: v for a, v in zip(gr.SIEVES_MM, x['passing'])}) for x in exp.gradings])
    files['grading.csv'] = g
    z = s['zones']
    files['zones.csv'] = pd.DataFrame([{'depthTop': a, 'depthBottom': b, **{n: z[n][k] for n in zones.ZONES}}
                                       for k, (a, b) in enumerate(z['bands'])])
    for name, df in files.items():
        writeAtomic(os.path.join(out, name), df.to_csv(index=False, float_format='%.9g'))
    writeAtomic(os.path.join(out, 'summary.json'), json.dumps(strictJson(s), indent=1) + '\n')  # no crush: local measures null
    figures(exp, files)
    if exp.frames:
        writePvd(os.path.join(out, 'boxes.pvd'), exp.frames)
    return s


def figures(exp, files):
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    from matplotlib.ticker import MaxNLocator
    out, p = exp.out, exp.p
    cyc = files['cycles.csv']
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    if len(cyc):
        ax.semilogx(cyc.cycle, 1e3 * cyc.settlement, 'o-', ms=3, label='permanent settlement (at the seating load)')
        ax.semilogx(cyc.cycle, 1e3 * cyc.resilient, 's--', ms=3, label='resilient deflection')
        if 'settlementJumped' in cyc and cyc.settlementJumped.any():
            ax.semilogx(cyc.cycle, 1e3 * (cyc.settlement + cyc.settlementJumped), 'x:', ms=3,
                        label='with the jumped cycles\' settlement extrapolated (a + b ln n)')
    ax.set_xlabel('load cycles N')
    if len(cyc):
        plainLogTicks(ax)
    ax.set_ylabel('sleeper displacement [mm]')
    ax.set_title('Box test: %.3g-%.3g kN, %s' % (p.history().seat / 1e3, p.history().peak / 1e3, exp.runId), fontsize=9)
    ax.grid(True, which='both', alpha=0.3)
    ax.legend(fontsize=8)
    saveFigure(fig, os.path.join(out, 'settlement.png'))
    c = files['crushes.csv']
    fig, ax = plt.subplots(figsize=(7.0, 3.8))
    L, w, zb = p['boxLength'], p['sleeperWidth'], exp.initial['zBase']
    ax.plot([-L / 2, -L / 2, L / 2, L / 2], [zb + 0.05, 0, 0, zb + 0.05], 'k-', lw=1)
    ax.add_patch(plt.Rectangle((-w / 2, zb), w, p['sleeperHeight'] / 2, color='0.6'))
    if len(c):
        sc = ax.scatter(c.x, c.z, s=8 + 0.4 * (1e3 * c.radius) ** 1.5, c=c.cycle, cmap='viridis', edgecolors='k', lw=0.3)
        bar = fig.colorbar(sc, ax=ax, label='cycle')
        bar.ax.yaxis.set_major_locator(MaxNLocator(integer=True))   # cycles are whole (not 1.25)
    ax.set_aspect('equal')
    ax.set_xlabel('x along the track [m]')
    ax.set_ylabel('z [m]')
    ax.set_title('Where the grains broke: %d crushes (side view, all y)' % len(c), fontsize=9)
    saveFigure(fig, os.path.join(out, 'breakage.png'))
    g = files['grading.csv']
    fig, ax = plt.subplots(figsize=(6.0, 4.2))
    for _, row in g.iterrows():
        n = int(row.cycle)
        ax.semilogx(gr.SIEVES_MM, [row['P%g' % a] for a in gr.SIEVES_MM], '-o', ms=2,
                    label='before loading' if n == 0 else 'after %d cycle%s' % (n, '' if n == 1 else 's'))
    ax.set_xlabel('sieve [mm]')
    ax.set_ylabel('passing [% by mass]')
    if p['lostAsFines']:   # the volume a replacement or abrasion removes is counted as dust passing every sieve
        ax.set_title('the lost volume is counted as fines: it passes every sieve, the finest (%g mm) included'
                     % gr.SIEVES_MM[0], fontsize=8)
    ax.grid(True, which='both', alpha=0.3)
    ax.legend(fontsize=7)
    saveFigure(fig, os.path.join(out, 'grading.png'))


def writeFrame(exp):
    """VTK files of the grains, the contacts and the sleeper and box now (named by the step); a frame of boxes.pvd,
    written again with it (a killed run keeps its series)."""
    out = os.path.join(exp.out, 'vtk')
    os.makedirs(out, exist_ok=True)
    x, r, ids = grains.vtk()
    m = grains.kind().masses(ids)
    n = len(r)
    names = ['%s-%09d.vtu' % (part, O.iter) for part in ('grains', 'contacts', 'sleeper')]
    unstructuredGrid(os.path.join(out, names[0]), x, np.arange(n), np.arange(1, n + 1), np.ones(n, dtype=int),
                  dataArray('radius', r) + dataArray('mass', m))
    writeContactsVtu(os.path.join(out, names[1]))
    b = O.bodies[exp.rig.sleeper]
    e = b.shape.extents
    corners = [b.state.pos + b.state.ori * np.multiply(e, s) for s in
               [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1), (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)]]
    L, W = exp.p['boxLength'] / 2, exp.p['boxWidth'] / 2
    floor = [(-L, -W, 0), (L, -W, 0), (L, W, 0), (-L, W, 0)]
    pts = np.array([tuple(c) for c in corners] + floor)
    unstructuredGrid(os.path.join(out, names[2]), pts, list(range(12)), [8, 12], [12, 9])   # VTK_HEXAHEDRON, VTK_QUAD
    exp.frames.append([O.time - exp.recorder.t0] + ['vtk/' + k for k in names])
    writePvd(os.path.join(exp.out, 'boxes.pvd'), exp.frames)
