"""What the outputs read of a running oedometer, and nothing more: the parameters, the plate (the
grains' force on it, its displacement, the applied force of eq. 8), the cylinder, the engines' counters
and events, the grading against the start of loading, the inertial number, the cycle jumper (None without
jump), and the run directory."""
import math

import numpy as np
from yade import O

from ... import grading
from ...engines import BallastEngine
from .. import grains, quasistatic



def engine(label):
    """The ballast engine with this label ('crush', 'abrasion') in O.engines, or None."""
    return next((e for e in O.engines if e.label == label and isinstance(e, BallastEngine)), None)


def degradingEngines():
    return [e for e in (engine('crush'), engine('abrasion')) if e is not None]


def counter(label, name):
    """An output of the engine with this label (0 without the engine)."""
    e = engine(label)
    return getattr(e, name) if e is not None else 0


class Probe:
    def __init__(self, p, loading, rig, runDir, initial, jumper=None, stepChoice=None):
        self.p, self.loading, self.rig, self.dir, self.initial = p, loading, rig, runDir, initial
        self.jumper, self.stepChoice = jumper, stepChoice

    def ownStep(self):
        """The grains' own P-wave step [s] under density scaling now (Experiment.ownStep)."""
        return quasistatic.ownStep(self.p, self.stepChoice)

    def cyclesJumped(self):
        """Cycles advanced by cycle jumping, not simulated."""
        return self.jumper.jumped if self.jumper is not None else 0

    @property
    def T(self):
        return self.p.T

    @property
    def cylinder(self):
        return self.rig.cylinder

    @property
    def out(self):
        return self.dir.create()

    @property
    def runId(self):
        return self.dir.runId

    engine, degradingEngines, counter = staticmethod(engine), staticmethod(degradingEngines), staticmethod(counter)

    def events(self):
        """The events of both engines, in time order."""
        ev = [e for eng in self.degradingEngines() for e in eng.events]
        ev.sort(key=lambda e: (e['t'], e['iter'], e['id']))
        return ev

    def grading(self):
        """Percentage passing each sieve of grading.SIEVES_MM by mass at the start of loading and now; the
        mass the engines lost counts as fines passing every sieve if lostAsFines."""
        d, m = grains.sieve()
        fines = sum(e.massLost for e in self.degradingEngines()) if self.p['lostAsFines'] else 0.0
        # states saved before the grain kinds kept the radii
        before = self.initial['diameters'] if 'diameters' in self.initial else 2 * np.array(self.initial['radii'])
        return (grading.passing(before, self.initial['masses']), grading.passing(d, m, fines=fines))

    def inertialNumber(self):
        """The sample's inertial number now (pkg/InertialNumber.hpp): the plate's speed over the sample height,
        the grains' mean diameter, their density as their inertia sees it under density scaling, and the
        grains' force on the plate over the cylinder's section; NaN while the grains carry less than LOADED
        Fmax (the seating, where p -> 0 makes any motion look inertial)."""
        return quasistatic.inertialNumber(self.p, O.bodies[self.loading.plate].state.vel[2], self.loading.top(),
                                          self.loading.force(), math.pi * self.cylinder.Rin ** 2, self.p['Fmax'],
                                          self.ownStep())
