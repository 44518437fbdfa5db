"""What the box test records while it cycles: the sleeper and the engines sampled `samples` times a cycle, and a
row of cycles.csv closed at each cycle's end (docs/box.md, "Output")."""
import math
import time

import numpy as np
from yade import O

from ... import runtime
from ...engines import BallastCrushEngine
from .. import breakage, chain, grains, quasistatic
from ..cyclic import CycleRecorder

LOAD = 'boxLoad'   # the label of the load on the sleeper (InterpolatingDirectedForceEngine)


@runtime.persistent('BoxRecorder')
class Recorder(CycleRecorder):
    """Samples the sleeper and the engines `samples` times a cycle (a callback at simulated times) and closes
    a row of cycles.csv at each cycle's end: the permanent settlement (at the seating load), the resilient
    deflection, the work of the load over the cycle, crushes and abrasions, the largest fatigue damage."""

    COLUMNS = ('t', 'cycle', 'F', 'Fgrains', 'settlement', 'tilt', 'nCrushed', 'nAbraded', 'maxStressRatio',
               'inertialNumber')
    CYCLE_COLUMNS = ('cycle', 't', 'settlement', 'settlementPeak', 'resilient', 'work', 'crushes', 'abrasions',
                     'nCrushed', 'nAbraded', 'maxDamage', 'maxStressRatio', 'nGrains', 'tilt', 'cpuSeconds', 'dt',
                     'stepsPerCycle', 'inertialMax', 'inertialMedian', 'responseRatio')
    iter0 = None   # O.iter at the current cycle's start (states saved before the steps per cycle have none)
    partial = None   # the cycle cut short where the sleeper reached the floor: its row of cycles.csv ends at the stop

    def __init__(self, sleeper=None, z0=None, t0=None, period=None):
        self.sleeper, self.z0, self.t0, self.period = sleeper, z0, t0, period
        # the rows of the current cycle (samples.csv holds them all: BoxTest.sample appends each), of cycles.csv;
        # a saved state keeps only the current cycle's, so it stays small over thousands of cycles
        self.samples, self.cycles = [], []
        self.start = None                    # index in samples of the current cycle's first row
        self.cpu = None                      # process CPU [s] at the current cycle's start (not saved: per process)
        self.jumped = 0                      # cycles advanced by cycle jumping, not simulated (docs/cycles.md)

    def state(self):
        return {k: getattr(self, k) for k in ('sleeper', 'z0', 't0', 'period', 'samples', 'cycles', 'start', 'jumped',
                                              'iter0', 'partial')}

    @classmethod
    def fromState(cls, s, ref=None):
        return runtime.fromAttributes(cls, s)

    def underside(self):
        """Height of the sleeper's underside [m] at its centre."""
        b = O.bodies[self.sleeper]
        return b.state.pos[2] - b.shape.extents[2]

    def tilt(self):
        """The sleeper's rotation about y [rad]."""
        q = O.bodies[self.sleeper].state.ori
        axis, angle = q.toAxisAngle()
        return float(angle * axis[1])

    def applied(self):
        return -chain.engine(LOAD).force[2]

    def grainsForce(self):
        """Upward force of the grains on the sleeper [N]: its force container holds the contacts and the applied load."""
        return O.forces.f(self.sleeper)[2] + self.applied()

    def inertialNumber(self, p, area, peak, ownStep=None):
        """The bed's inertial number under the sleeper now (experiments.quasistatic): its speed over the bed's depth
        under it, the grains' force on it over its footprint `area` [m^2], NaN below 1 % of the `peak` load [N]."""
        return quasistatic.inertialNumber(p, O.bodies[self.sleeper].state.vel[2], self.underside(), self.grainsForce(),
                                          area, peak, ownStep)

    def sample(self, p, area, peak, ownStep=None):
        """A row of samples.csv; returns the cycle it closed, or 0. p: the run's parameters; area [m^2] and peak
        [N]: the sleeper's footprint and the peak load, ownStep [s] the grains' own step, for the inertial number."""
        crushed, abraded, ratio = breakage.counts()   # the ratio at the engine's last check
        row = [O.time - self.t0, self.cycle(), self.applied(), self.grainsForce(), self.z0 - self.underside(),
               self.tilt(), crushed, abraded, ratio, self.inertialNumber(p, area, peak, ownStep)]
        return self.keep(row, p, ownStep)

    def closeCycle(self, end, p, ownStep=None):
        # rows of states saved before the inertial number have 9 entries
        rows = np.array([list(r) + [math.nan] * (10 - len(r)) for r in self.samples[self.start:end + 1]], dtype=float)
        F, s = rows[:, 2], rows[:, 4]
        crush = [e for e in O.engines if isinstance(e, BallastCrushEngine)]
        n = int(rows[-1, 1])
        self.cycles.append([n, rows[-1, 0], s[-1], float(np.max(s)), float(np.max(s) - s[-1]),
                            float(np.sum(0.5 * (F[1:] + F[:-1]) * np.diff(s))),
                            int(rows[-1, 6] - rows[0, 6]), int(rows[-1, 7] - rows[0, 7]), int(rows[-1, 6]),
                            int(rows[-1, 7]), max([e.maxDamage for e in crush], default=0.0),
                            float(np.max(rows[:, 8])) if crush else math.nan, len(grains.bodies()),
                            rows[-1, 5], time.process_time() - self.cpu if self.cpu is not None else math.nan, O.dt,
                            O.iter - self.iter0 if self.iter0 is not None else math.nan,
                            *quasistatic.cycleStats(rows[:, 9]),
                            quasistatic.responseRatio(self.period, O.bodies[self.sleeper].state.mass +
                                                      quasistatic.bedMass(p, grains.arrays()[2], ownStep),
                                                      float(np.max(F) - np.min(F)), float(np.max(s) - s[-1]))])
        self.cpu, self.iter0 = time.process_time(), O.iter

    def closePartial(self, p, ownStep=None):
        """The cycle under way closed where the run stopped (the sleeper on the floor): its row of cycles.csv numbered
        as the cycle it cut short and ending at the last sample, so that every count and the last settlement of
        cycles.csv are the run's at its stop."""
        n = int(self.samples[-1][1]) + 1
        self.closeCycle(len(self.samples) - 1, p, ownStep)
        self.cycles[-1][0] = n
        self.partial = n
        self.samples, self.start = self.samples[-1:], 0
