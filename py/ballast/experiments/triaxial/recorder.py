"""What the triaxial test records while it cycles (docs/triaxial.md, "Outputs"): the specimen `samples` times a cycle
(the deviator applied and carried by the grains, the axial and volumetric strains from the boundary: the top
platen's travel over the height at the start of cycling, the volume the membrane encloses against its volume then)
and a row of cycles.csv closed at each cycle's end (at q_min)."""
import math
import time

import numpy as np
from yade import O

from ... import runtime
from ...engines import BallastCrushEngine
from .. import breakage, grains, quasistatic
from ..cyclic import CycleRecorder
from .strains import axialStrain, resilientModulus, volumetricStrain


@runtime.persistent('TriaxialRecorder')
class Recorder(CycleRecorder):
    """Samples the specimen and the engines; closes a row of cycles.csv at each cycle's end: the permanent axial
    deformation (the platen's travel [m], `settlement` of the shared schema) and strains, the resilient axial strain
    and modulus, crushes and abrasions, the largest fatigue damage."""

    COLUMNS = ('t', 'cycle', 'q', 'qGrains', 'p', 'axialStrain', 'volumetricStrain', 'height', 'volume', 'nCrushed',
               'nAbraded', 'maxStressRatio', 'inertialNumber')
    CYCLE_COLUMNS = ('cycle', 't', 'settlement', 'resilient', 'crushes', 'abrasions', 'nCrushed', 'nAbraded',
                     'maxDamage', 'maxStressRatio', 'nGrains', 'cpuSeconds', 'dt', 'stepsPerCycle', 'inertialMax',
                     'inertialMedian', 'responseRatio', 'axialStrain', 'volumetricStrain', 'resilientStrain',
                     'resilientModulus', 'qGrainsMin', 'qGrainsMax')

    def __init__(self, top=None, H0=None, V0=None, t0=None, period=None):
        self.top, self.H0, self.V0, self.t0, self.period = top, H0, V0, t0, period
        self.samples, self.cycles = [], []   # the current cycle's rows (samples.csv holds all), cycles.csv's rows
        self.start = None   # index in samples of the current cycle's first row
        self.cpu = None     # process CPU [s] at the current cycle's start (per process: not saved)
        self.iter0 = None   # O.iter at the current cycle's start
        self.jumped = 0     # cycles advanced by cycle jumping

    def state(self):
        return {k: getattr(self, k) for k in ('top', 'H0', 'V0', 't0', 'period', 'samples', 'cycles', 'start', 'jumped',
                                              'iter0')}

    @classmethod
    def fromState(cls, s, ref=None):
        return runtime.fromAttributes(cls, s)

    def grainsForce(self):
        """The grains' push on the top platen [N], upward: its force less the load applied to it."""
        return O.forces.f(self.top)[2] - O.forces.permF(self.top)[2]

    def sample(self, p, membrane, q, ownStep=None):
        """A row of samples.csv; returns the cycle it closed, or 0. p: the run's parameters; membrane: the cell's
        (its height, volume, lateral pressure); q [Pa] the deviator applied now."""
        H, V = membrane.height(), membrane.volume
        area = V / H
        qGrains = self.grainsForce() / area - membrane.pressure
        peak = (p['confining'] + p.peakDeviator()) * area
        inertial = quasistatic.inertialNumber(p, O.bodies[self.top].state.vel[2], H, self.grainsForce(), area, peak,
                                              ownStep)
        crushed, abraded, ratio = breakage.counts()
        row = [O.time - self.t0, self.cycle(), q, qGrains, membrane.pressure + q / 3, axialStrain(self.H0, H),
               volumetricStrain(self.V0, V), H, V, crushed, abraded, ratio, inertial]
        return self.keep(row, p, ownStep)

    def closeCycle(self, end, p, ownStep=None):
        rows = np.array(self.samples[self.start:end + 1], dtype=float)
        c = dict(zip(self.COLUMNS, rows.T))
        travel = self.H0 - c['height']      # the platen's travel from the start of cycling [m]
        crush = [e for e in O.engines if isinstance(e, BallastCrushEngine)]
        resilient = float(np.max(travel) - travel[-1])
        resilientStrain = resilient / self.H0
        area = c['volume'][-1] / c['height'][-1]
        loadRange = float(np.max(c['q']) - np.min(c['q'])) * area
        self.cycles.append([
            int(c['cycle'][-1]), float(c['t'][-1]), float(travel[-1]), resilient,
            int(c['nCrushed'][-1] - c['nCrushed'][0]), int(c['nAbraded'][-1] - c['nAbraded'][0]),
            int(c['nCrushed'][-1]), int(c['nAbraded'][-1]), max([e.maxDamage for e in crush], default=0.0),
            float(np.max(c['maxStressRatio'])) if crush else math.nan, len(grains.bodies()),
            time.process_time() - self.cpu if self.cpu is not None else math.nan, O.dt,
            O.iter - self.iter0 if self.iter0 is not None else math.nan,
            *quasistatic.cycleStats(c['inertialNumber']),
            quasistatic.responseRatio(self.period, O.bodies[self.top].state.mass +
                                      quasistatic.bedMass(p, grains.arrays()[2], ownStep), loadRange, resilient),
            float(c['axialStrain'][-1]), float(c['volumetricStrain'][-1]), resilientStrain,
            resilientModulus(p.peakDeviator() - p.seatDeviator(), resilientStrain),
            float(np.min(c['qGrains'])), float(np.max(c['qGrains']))])
        self.cpu, self.iter0 = time.process_time(), O.iter
