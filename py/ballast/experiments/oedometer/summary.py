"""What the oedometer's summary.json holds (docs/oedometer.md, "Output"): the peak force and the displacements,
crushes, the mass ledger, the grading's indices, timings, the packing, the inertial number, cycle jumping and
every parameter; read from the run's F-delta rows, the engines and the scene at the end."""
import os

import numpy as np
from yade import O

from ... import grading
from .. import cyclic, grains


def summary(exp):
    """What summary.json holds: peak force and displacements, crushes, the mass ledger, timings,
    the packing and every parameter."""
    p = exp.p
    wall, cpu = exp.seconds()
    a = np.array(exp.outputs.rows)
    k = int(np.argmax(a[:, 1]))
    r, m = grains.arrays()[1:]
    engs = exp.degradingEngines()
    loaded = a[:, 0] >= 0.05 * exp.T
    target = exp.loading.target(a[:, 0])
    steps = exp.phases.steps
    half = min(p.peakTime(), a[-1, 0])  # eq. 8 peaks at T/2
    F5 = np.where(np.isfinite(a[:, 5]), a[:, 5], a[:, 1]) >= 0.05 * p['Fmax']
    before, after = exp.grading()
    cycles = float(a[-1, 0] / exp.T) + exp.cyclesJumped()
    s = {
        'runId': exp.runId,
        'warnings': exp.warnings() + exp.containmentWarnings(),
        'peakForce': float(a[k, 1]),  # = peakGrainForce (the name older records have)
        'peakGrainForce': float(a[k, 1]),
        'peakAppliedForce': float(np.nanmax(a[:, 5])) if np.isfinite(a[:, 5]).any() else None,
        'deltaAtPeak': float(a[k, 2]),
        'deltaAtAppliedPeak': float(np.interp(half, a[:, 0], a[:, 2])),
        'forceAtAppliedPeak': float(np.interp(half, a[:, 0], a[:, 1])),
        'seatingDelta': float(a[np.argmax(F5), 2]) if F5.any() else None,
        'deltaMax': float(np.max(a[:, 2])),
        'deltaFinal': float(a[-1, 2]),
        'nCrushed': exp.counter('crush', 'nCrushed'),
        'nAbraded': exp.counter('abrasion', 'nAbraded'),
        'nFatigueCrushed': exp.counter('crush', 'nFatigueCrushed'),
        'volumeLost': float(sum(e.volumeLost for e in engs)),
        'massInitial': exp.initial['massInitial'],
        'massFinal': float(np.sum(m)),
        'massLost': float(sum(e.massLost for e in engs)),
        'dustPercent': 100.0 * float(sum(e.massLost for e in engs)) / exp.initial['massInitial'],
        'wallSeconds': wall,
        'cpuSeconds': cpu,  # = wall on an idle machine, 1 thread
        'steps': sum(steps.values()),
        'stepsByPhase': dict(steps),
        'wallSecondsByPhase': {k: round(v, 3) for k, v in exp.phases.wall.items()},
        'nGrainsInitial': exp.initial['nGrainsInitial'],
        'nSpheresFinal': len(r),
        'maxGeneration': int(np.max(exp.outputs.grains.generation, initial=0)),
        'Bg': grading.marsal(before, after),
        'Br': grading.hardin(before, after),
        'BBI': grading.bbi(before, after),
        'lostAsFines': p['lostAsFines'],
        'plateHeight0': exp.loading.z0,
        'porosity0': exp.porosity0(),
        # a whole number when the loading ended within a time step of one (the step loop stops there)
        'cycles': int(round(cycles)) if abs(cycles - round(cycles)) * exp.T <= O.dt else cycles,
        'loadingTime': float(a[-1, 0]),
        'loadingStartTime': exp.loading.t0,
        'forceErrorRms': float(np.sqrt(np.mean((a[loaded, 1] - target[loaded]) ** 2))) if loaded.any() else None,
        'dtFinal': O.dt,
        'stoppedBy': exp.stoppedBy,
        'inertialNumber': exp.outputs.inertialSummary([e['t'] - exp.loading.t0 for e in exp.events()
                                                        if e['kind'] == 'crush']),
        # the state at the end (the half-load sweep's columns when stopAt stops the loading early)
        'forceFinal': float(a[-1, 1]),
        'appliedFinal': float(a[-1, 5]),
        'unbalancedFinal': grains.unbalanced(),
        'vRmsFinal': grains.vRms(),
        'checkSeconds': {e.label: e.checkSeconds for e in engs},
        'nChecks': {e.label: e.nChecks for e in engs},
        'maxProtrusion': exp.maxProtrusion,
        'nEscaped': exp.nEscaped,
        'packingFile': exp.packing.state().get('file'),
        'packingReused': exp.packing.state().get('reused'),
        'prepEscaped': exp.packing.state().get('escaped'),
        'stateFiles': [os.path.basename(f) for f in exp.saved],
        'threads': int(os.environ.get('OMP_NUM_THREADS', 1)),
        'yade': getattr(getattr(__import__('yade'), 'config', None), 'version', ''),
        'params': dict(p),
    }
    if exp.jumper is not None:   # cycle jumping: what was simulated, jumped and extrapolated
        jumps = cyclic.jumpSummary(exp.outputs.cycleTable(), exp.jumper)
        s.update({k: v for k, v in jumps.items() if k != 'cycles'})   # cycles: from the loading time, above
    return s
