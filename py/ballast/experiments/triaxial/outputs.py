"""What the triaxial test writes (docs/triaxial.md, "Outputs"), in <results>/<run id>/:

* cycles.csv    a row per cycle, the shared schema (experiments.cyclic; settlement: the top platen's permanent
                travel [m], resilient: its resilient travel [m]) then axialStrain, volumetricStrain (permanent, at the
                cycle's end, compression positive), resilientStrain, resilientModulus [Pa], qGrainsMin and qGrainsMax
                (the deviator the grains carry on the top platen at its lowest and highest [Pa])
* samples.csv   `samples` rows a cycle: the stress path (q applied and carried, the mean stress p [Pa]), the strains,
                the specimen's height [m] and volume [m^3], crushes and abrasions so far
* grading.csv   percentage passing each sieve after cycles 0, 1, 2, 5, 10, ... and the last, with B_g, B_r and BBI
* summary.json  the run: strains, the specimen (porosity in the mould and consolidated), crushes, the mass ledger, CPU
* strains.png   permanent axial and volumetric strain against N (log N), the measured curves of `reference` over them
* triaxial.pvd  with vtk: the grains, the contacts and the membrane every vtk cycles and at the end (ParaView)

A monotonic compression (monotonic 1) writes instead monotonic.csv (a row per sample: monotonic.COLUMNS), monotonic.png,
grading.csv (before and after) and summary.json (the peak, its friction and dilatancy angles).
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
from ..vtk import dataArray, unstructuredGrid, writeContactsVtu, writePvd
from ..breakage import engines, massLost
from ...settlementlaws import settlementJumped
from .recorder import Recorder

OWN_COLUMNS = ('axialStrain', 'volumetricStrain', 'resilientStrain', 'resilientModulus', 'qGrainsMin', 'qGrainsMax')


STRAINS = ('axialStrain', 'volumetricStrain')   # permanent strains: with cycle jumping, extrapolated as the settlement


def cycleTable(exp):
    """cycles.csv as a DataFrame (the shared schema, then OWN_COLUMNS; with cycle jumping then axialStrainJumped and
    volumetricStrainJumped, each strain's extrapolation over the jumped cycles as settlementJumped's: b ln(N / n),
    b of its log law fitted to the simulated cycles without the steps of those that changed the bed)."""
    frame = cyclic.table([dict(zip(Recorder.CYCLE_COLUMNS, row)) for row in exp.recorder.cycles], OWN_COLUMNS,
                         exp.jumper, exp.stepChoice)
    if exp.jumper is not None:
        for q in STRAINS:
            frame[q + 'Jumped'] = settlementJumped(frame.cycle, frame[q], cyclic.changed(frame))
    return frame


def writeCycles(exp):
    cyclic.write(os.path.join(exp.out, 'cycles.csv'), cycleTable(exp))


def summary(exp):
    p, rec = exp.p, exp.recorder
    cyc = cycleTable(exp)
    n = len(cyc)
    x, r, m = grains.arrays()
    lost = massLost()
    wall, cpu = exp.seconds()

    def last(column):
        return float(cyc[column].iloc[-1]) if n else 0.0
    return {
        'experiment': exp.NAME, 'runId': exp.runId, 'params': dict(p), 'warnings': exp.warnings(), 'cycles': n,
        'axialStrain': last('axialStrain'), 'volumetricStrain': last('volumetricStrain'),
        'resilientStrain': last('resilientStrain'), 'resilientModulus': last('resilientModulus'),
        'settlement': last('settlement'), 'resilient': last('resilient'),
        'axialStrainFirstCycle': float(cyc.axialStrain.iloc[0]) if n else 0.0,
        'nCrushed': int(sum(e.nCrushed for e in engines() if isinstance(e, BallastCrushEngine))),
        'nAbraded': int(sum(e.nAbraded for e in engines() if isinstance(e, BallastAbrasionEngine))),
        'maxDamage': float(cyc.maxDamage.max()) if n else 0.0,
        'maxStressRatio': float(cyc.maxStressRatio.max()) if n else math.nan,
        'nGrainsInitial': exp.initial['nGrainsInitial'], 'nGrains': len(r), 'porosityMould': exp.porosity,
        'consolidated': exp.consolidated, 'specimenFile': exp.specimenFile, 'loadPeriod': rec.period,
        'massInitial': exp.initial['massInitial'], 'massGrains': float(np.sum(m)), 'massLost': lost,
        'massLedgerError': float(np.sum(m)) + lost - exp.initial['massInitial'],
        'gradings': [{k: g[k] for k in ('cycle', 'Bg', 'Br', 'BBI')} for g in exp.gradings],
        'dt': O.dt, 'steps': O.iter, 'wallSeconds': wall, 'cpuSeconds': cpu,
        'cpuSecondsPerCycle': float(np.nanmedian(cyc.cpuSeconds)) if n and cyc.cpuSeconds.notna().any() else math.nan,
        # the steps the cycles took (their median, as cpuSecondsPerCycle), not the period over the last step
        'stepsPerCycle': (float(np.nanmedian(cyc.stepsPerCycle)) if n and cyc.stepsPerCycle.notna().any()
                          else rec.period / O.dt), **cyclic.jumpSummary(cyc, exp.jumper),
        # failed: cycling stopped in that cycle (cycles.csv holds the whole cycles before it)
        **({'stoppedBy': 'failure', 'failedInCycle': exp.failed, 'axialStrainAtStop': float(rec.samples[-1][5]),
            'volumetricStrainAtStop': float(rec.samples[-1][6])} if exp.failed is not None else {})}


def gradingTable(exp):
    """grading.csv: a row per grading taken (its cycle, B_g, B_r, BBI, the percentage passing each sieve)."""
    return pd.DataFrame([dict({'cycle': x['cycle'], 'Bg': x['Bg'], 'Br': x['Br'], 'BBI': x['BBI']},
                              **{'P%g' % a: v for a, v in zip(gr.SIEVES_MM, x['passing'])}) for x in exp.gradings])


def write(exp):
    """Every output file; returns the summary."""
    out = exp.out
    s = summary(exp)
    cyc = cycleTable(exp)
    for name, df in (('cycles.csv', cyc), ('grading.csv', gradingTable(exp))):
        writeAtomic(os.path.join(out, name), df.to_csv(index=False, float_format='%.9g'))
    writeAtomic(os.path.join(out, 'summary.json'), json.dumps(strictJson(s), indent=1) + '\n')
    figure(cyc, os.path.join(out, 'strains.png'), exp.p.references(),
           failed=(exp.failed, s.get('axialStrainAtStop')) if exp.failed is not None else None)
    if exp.frames:
        writePvd(os.path.join(out, 'triaxial.pvd'), exp.frames)
    return s


def writeFrame(exp):
    """VTK files of the grains, the contacts and the membrane now (named by the step); a frame of triaxial.pvd,
    written again with it (a killed run keeps its series). The membrane is a quad mesh through its cells' centres at
    its radius there (point data: that radius [m])."""
    out = os.path.join(exp.out, 'vtk')
    os.makedirs(out, exist_ok=True)
    x, r, ids = grains.vtk()
    n = len(r)
    names = ['%s-%09d.vtu' % (part, O.iter) for part in ('grains', 'contacts', 'membrane')]
    unstructuredGrid(os.path.join(out, names[0]), x, np.arange(n), np.arange(1, n + 1), np.ones(n, dtype=int),
                     dataArray('radius', r) + dataArray('mass', grains.kind().masses(ids)))
    writeContactsVtu(os.path.join(out, names[1]))
    rho, z0, z1 = exp.membrane.surface()
    nZ, nT = rho.shape
    theta = (np.arange(nT) + 0.5) * 2 * np.pi / nT
    z = z0 + (np.arange(nZ) + 0.5) * (z1 - z0) / nZ
    pts = np.column_stack([(rho * np.cos(theta)).ravel(), (rho * np.sin(theta)).ravel(), np.repeat(z, nT)])
    k, j = np.meshgrid(np.arange(nZ - 1), np.arange(nT), indexing='ij')   # a quad between rows k, k+1, columns j, j+1
    a, b = k * nT + j, k * nT + (j + 1) % nT
    quads = np.column_stack([a.ravel(), b.ravel(), (b + nT).ravel(), (a + nT).ravel()])
    unstructuredGrid(os.path.join(out, names[2]), pts, quads.ravel(), 4 * np.arange(1, len(quads) + 1),
                     np.full(len(quads), 9), dataArray('radius', rho.ravel()))   # VTK_QUAD
    exp.frames.append([O.time - exp.recorder.t0] + ['vtk/' + k for k in names])
    writePvd(os.path.join(exp.out, 'triaxial.pvd'), exp.frames)


def figure(cycles, path, references=(), failed=None):
    """strains.png: the permanent axial and volumetric strain [%] against N (log N), each measured curve of
    `references` ((kind, N, strain) as strains.readReference gives) over its own; failed: (the cycle the specimen
    failed in, the axial strain at the stop [-]), said in the title, or None."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, 1, figsize=(6.4, 6.4), sharex=True)
    N = cycles.cycle.to_numpy()
    for ax, kind, column in ((axes[0], 'axial', 'axialStrain'), (axes[1], 'volumetric', 'volumetricStrain')):
        ax.semilogx(N, 100 * cycles[column].to_numpy(), 'o-', ms=3, label='simulated')
        if column + 'Jumped' in cycles and cycles[column + 'Jumped'].any():   # cycle jumping: the total
            ax.semilogx(N, 100 * (cycles[column] + cycles[column + 'Jumped']).to_numpy(), 'x:', ms=3,
                        label='with the jumped cycles extrapolated')
        for k, (refKind, Nr, er) in enumerate(r for r in references if r[0] == kind):
            ax.semilogx(Nr, 100 * er, 's--', ms=3, color='k', label='measured' if k == 0 else None)
        ax.set_ylabel('%s strain [%%]%s' % (kind, ' (compression +)' if kind == 'volumetric' else ''))
        plainLogTicks(ax)
        ax.grid(True, which='both', alpha=0.3)
        ax.legend(loc='upper left')
    axes[1].set_xlabel('load cycles N')
    fig.suptitle('Permanent strains of the triaxial specimen' + (
        '\n(failed in cycle %d: axial strain %.1f %% at the stop)' % (failed[0], 100 * failed[1]) if failed else ''))
    return saveFigure(fig, path)


def monotonicSummary(exp):
    """summary.json of a monotonic compression: the peak (monotonic.peak), the specimen, crushes, the mass ledger, CPU."""
    from . import monotonic
    p, c = exp.p, exp.compression
    x, r, m = grains.arrays()
    lost = massLost()
    wall, cpu = exp.seconds()
    rows = c['rows']
    return {
        'experiment': exp.NAME, 'runId': exp.runId, 'params': dict(p), 'warnings': exp.warnings(), 'test': 'monotonic',
        **(monotonic.peak(rows) if rows else {}), 'rows': len(rows),
        'inertialMax': float(np.nanmax([row[8] for row in rows])) if rows else math.nan,
        'nCrushed': int(sum(e.nCrushed for e in engines() if isinstance(e, BallastCrushEngine))),
        'nAbraded': int(sum(e.nAbraded for e in engines() if isinstance(e, BallastAbrasionEngine))),
        'nGrainsInitial': exp.initial['nGrainsInitial'], 'nGrains': len(r), 'porosityMould': exp.porosity,
        'consolidated': exp.consolidated, 'specimenFile': exp.specimenFile,
        'massInitial': exp.initial['massInitial'], 'massGrains': float(np.sum(m)), 'massLost': lost,
        'massLedgerError': float(np.sum(m)) + lost - exp.initial['massInitial'],
        'gradings': [{k: g[k] for k in ('cycle', 'Bg', 'Br', 'BBI')} for g in exp.gradings],
        'dt': O.dt, 'steps': O.iter, 'wallSeconds': wall, 'cpuSeconds': cpu}


def writeMonotonic(exp):
    """monotonic.csv, monotonic.png, grading.csv (before and after: cycle 0 and 1) and summary.json; returns the
    summary."""
    from . import monotonic
    out = exp.out
    s = monotonicSummary(exp)
    frame = pd.DataFrame(exp.compression['rows'], columns=list(monotonic.COLUMNS))
    for name, df in (('monotonic.csv', frame), ('grading.csv', gradingTable(exp))):
        writeAtomic(os.path.join(out, name), df.to_csv(index=False, float_format='%.9g'))
    writeAtomic(os.path.join(out, 'summary.json'), json.dumps(strictJson(s), indent=1) + '\n')
    monotonic.figure(exp.compression['rows'], os.path.join(out, 'monotonic.png'),
                     'Drained monotonic compression, p\' = %g kPa, %g /s: %s' % (
                         exp.p['confining'] / 1e3, exp.p['strainRate'], exp.runId))
    return s
