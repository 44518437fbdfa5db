"""The load of section 4: eq. 8, F(t) = Fmax/2 [sin(2 pi f t - pi/2) + 1], on a steel plate seated
on the grains. Three ways (``loadMode``):

* ``plate`` (PlateLoad): the plate is a body free along the cylinder axis with the mass of a steel
  plate of ``plateThickness``; eq. 8 is a force applied to it (YADE's InterpolatingDirectedForceEngine,
  no Python per step). A crush under it shows as a horizontal jump of F-delta, as in the paper.
* ``servo`` (ServoLoad): the plate is moved kinematically like the ram of a servo-hydraulic press,
  its speed set every SERVO_PERIOD steps from the gap between eq. 8 and the grains' force.
* ``displacement`` (DisplacementLoad): the plate moves down at ``plateSpeed`` until the grains carry
  Fmax (calibration).

Each records the force the grains exert on the plate (``force()``) and the applied force
(``applied()``: eq. 8 as applied or aimed at; NaN where none is applied).
"""
import math

import numpy as np
from yade import O, Vector3, utils
from yade.wrapper import InterpolatingDirectedForceEngine, Wall

from ... import runtime
from .. import chain, grains
from .. import scene
from .loadcurve import eq8, loadCurve

# samples of eq. 8 per cycle for the plate's force: linear interpolation errs by at most
# Fmax pi^2 / (4 N^2) (2e-7 Fmax at N = 4000)
EQ8_SAMPLES = 4000


class PlateBase:
    """A steel plate (a YADE Box a little wider than the cylinder, free or kinematic along the axis only)
    seated on the highest grain at the start of loading. With grain 'polyhedron' the plate is a YADE Wall, its
    plane the underside: YADE's polyhedra touch walls and facets, not boxes (docs/grains.md, "Polyhedra")."""

    LABEL = 'oedoForce'

    def __init__(self):
        self.plate = None
        self.z0 = None          # [m] height of the plate's underside at the start of loading
        self.t0 = None          # [s] O.time at the start of loading
        self.p = None           # the experiment's parameters (bind)

    def state(self):
        return {'plate': self.plate, 'z0': self.z0, 't0': self.t0}

    @classmethod
    def fromState(cls, s, ref=None):
        return runtime.fromAttributes(cls, s)

    def bind(self, p):
        """The parameters (at start and after a restore)."""
        self.p = p

    def seat(self, p, steel, dynamic):
        """The plate on the highest grain: its underside at z0."""
        self.p = p
        self.z0 = grains.top()
        half = 0.5 * p['plateThickness']
        side = 0.55 * p['diameter']  # half of a square plate covering the cylinder's mouth
        if p['grain'] == 'polyhedron':
            # a wall, not a polyhedron plate: YADE cuts a polyhedron by a plane (cheap, exact for a flat plate wider
            # than the mouth) where a polyhedron plate would be a grain to the kind and a CGAL intersection a contact
            b = utils.wall(self.z0, axis=2, sense=-1, material=steel, color=scene.STEEL_COLOR, mask=scene.STEEL_MASK)
            b.state.inertia = Vector3(1, 1, 1)   # a wall has none; its rotations are blocked, but Newton divides by it
            b.dynamic = dynamic
        else:
            b = utils.box((0, 0, self.z0 + half), (side, side, half), material=steel, fixed=not dynamic,
                          color=scene.STEEL_COLOR, mask=scene.STEEL_MASK)
        if dynamic:
            # a round steel plate of the cylinder's diameter, moving along the axis only, not slowed by
            # the grains' local damping (the load on it is the applied force, nothing else)
            b.state.mass = p['steelDensity'] * math.pi * (p['diameter'] / 2) ** 2 * p['plateThickness']
            b.state.blockedDOFs = 'xyXYZ'
            b.state.isDamped = False
        self.plate = O.bodies.append(b)
        self.t0 = O.time

    def target(self, t):
        """The load at loading time t [s] (loadCurve: eq. 8, then cycles down to Fmin)."""
        p = self.p
        return eq8(p['Fmax'], p['f'], t) if p['Fmin'] == 0 else loadCurve(p['Fmax'], p['Fmin'], p['f'], t)

    def delta(self):
        """Plate displacement since the start of loading [m] (the paper's delta)."""
        return self.z0 - self.top()

    def top(self):
        """Height of the plate's underside [m] (a wall's plane is its underside)."""
        b = O.bodies[self.plate]
        return b.state.pos[2] - (0.0 if isinstance(b.shape, Wall) else 0.5 * self.p['plateThickness'])

    def contactForce(self):
        """Force of the grains on a kinematic plate [N]: the force container holds only its contacts."""
        return O.forces.f(self.plate)[2]

    def done(self):
        return False


@runtime.persistent('PlateLoad')
class PlateLoad(PlateBase):
    """Eq. 8 applied to a free steel plate."""

    SWITCH = 'oedoLoadSwitch'

    def start(self, p, rig):
        self.seat(p, rig.steel, dynamic=True)
        T = 1.0 / p['f']
        tau = np.linspace(0, T, EQ8_SAMPLES + 1)
        engines = [InterpolatingDirectedForceEngine(
            ids=[self.plate], times=list(self.t0 + tau), magnitudes=list(eq8(p['Fmax'], p['f'], tau)),
            direction=Vector3(0, 0, -1), wrap=True, label=self.LABEL)]
        if p['Fmin'] > 0:  # at T/2 the force table becomes the cycle between Fmax and Fmin (once, in Python)
            engines.append(runtime.callback(self, 'switchToCycles', virtPeriod=T / 2, virtLast=self.t0,
                                            label=self.SWITCH))
        chain.insertBeforeNewton(engines)

    def switchToCycles(self):
        p = self.p
        T = 1.0 / p['f']
        tau = np.linspace(0.5 * T, 1.5 * T, EQ8_SAMPLES + 1)
        e = self.engine()
        e.times, e.magnitudes = list(self.t0 + tau), list(loadCurve(p['Fmax'], p['Fmin'], p['f'], tau))
        for r in O.engines:
            if r.label == self.SWITCH:
                r.dead = True  # once (PeriodicEngine's nDo counts its silent first call)

    def engine(self):
        return next(e for e in O.engines if e.label == self.LABEL)

    def applied(self):
        """The force applied to the plate this step [N] (eq. 8, interpolated)."""
        return -self.engine().force[2]

    def force(self):
        """Force of the grains on the plate [N]: the plate's force container holds the contacts and the
        applied force (gravity is applied by Newton apart)."""
        return O.forces.f(self.plate)[2] + self.applied()


@runtime.persistent('ServoLoad')
class ServoLoad(PlateBase):
    """A kinematic plate like the ram of a servo-hydraulic press: every SERVO_PERIOD steps it gets the
    speed that removes SERVO_GAIN of the gap between eq. 8 and the grains' force, estimated with the
    stiffness of its contacts, at most vMax."""

    SERVO_PERIOD = 4    # [steps] between updates of the plate velocity
    SERVO_GAIN = 0.3    # [-] fraction of the force error the plate corrects per update
    KPLATE_EVERY = 25   # [updates] between sums of the plate contacts' stiffness (a loop over its interactions)

    def __init__(self):
        PlateBase.__init__(self)
        self.Kplate, self.calls = 0.0, 0

    def state(self):
        return dict(PlateBase.state(self), Kplate=self.Kplate, calls=self.calls)

    def start(self, p, rig):
        self.seat(p, rig.steel, dynamic=False)
        chain.insertBeforeNewton([runtime.callback(self, 'step', iterPeriod=self.SERVO_PERIOD, label=self.LABEL)])

    def force(self):
        return self.contactForce()

    def applied(self):
        return self.target(O.time - self.t0)

    def step(self):
        p, n = self.p, self.SERVO_PERIOD
        F = self.force()
        if self.calls % self.KPLATE_EVERY == 0:
            self.Kplate = sum(i.phys.kn for i in O.bodies[self.plate].intrs() if i.isReal)
        self.calls += 1
        err = self.target(O.time - self.t0 + n * O.dt) - F
        v = self.SERVO_GAIN * err / (max(self.Kplate, p['Fmax'] / 1e-3) * n * O.dt)  # Fmax/1 mm: approach gently
        O.bodies[self.plate].state.vel = Vector3(0, 0, -max(-p['vMax'], min(p['vMax'], v)))


@runtime.persistent('DisplacementLoad')
class DisplacementLoad(PlateBase):
    """The plate moves down at plateSpeed until the grains carry Fmax (or the cycle time ends)."""

    def start(self, p, rig):
        self.seat(p, rig.steel, dynamic=False)
        O.bodies[self.plate].state.vel = Vector3(0, 0, -self.p['plateSpeed'])

    def force(self):
        return self.contactForce()

    def applied(self):
        return float('nan')

    def done(self):
        return self.force() >= self.p['Fmax']


MODES = {'plate': PlateLoad, 'servo': ServoLoad, 'displacement': DisplacementLoad}
