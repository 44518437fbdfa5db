"""The load of section 4: one cycle of eq. 8, F(t) = Fmax/2 [sin(2 pi f t - pi/2) + 1], applied
through a rigid plate resting on the grains, by force control of the plate's speed."""
import math

import numpy as np
from yade import O, Vector3, utils
from yade.wrapper import PyRunner

from .callbacks import command


def eq8(Fmax, f, t):
    """Eq. 8: the force [N] at loading time t [s] (a number or an array)."""
    if np.ndim(t):
        return Fmax / 2 * (np.sin(2 * math.pi * f * np.asarray(t, dtype=float) - math.pi / 2) + 1)
    return Fmax / 2 * (math.sin(2 * math.pi * f * t - math.pi / 2) + 1)


class ServoLoad:
    """A rigid plate (an infinite wall: the grains stay inside the cylinder) moved kinematically like
    the ram of a servo-hydraulic press: every SERVO_PERIOD steps it gets the speed that removes
    SERVO_GAIN of the gap between eq. 8 and the force of the grains on it, estimated with the
    stiffness of its contacts, at most vMax. Between crushing events the force follows eq. 8; when a
    grain under the plate crushes the force drops and the plate moves down at up to vMax until the
    grains carry eq. 8 again: the horizontal jumps of the F-delta diagram.

    Replace it by any object with start(exp), force(), delta(), target(t), state(), setState(s)."""

    SERVO_PERIOD = 4    # [steps] between updates of the plate velocity
    SERVO_GAIN = 0.3    # [-] fraction of the force error the plate corrects per update
    KPLATE_EVERY = 25   # [updates] between sums of the plate contacts' stiffness (a loop over all its interactions)
    LABEL = 'oedoForce'

    def __init__(self):
        self.plate = None
        self.z0 = None          # [m] plate height at the start of loading
        self.t0 = None          # [s] O.time at the start of loading
        self.Kplate, self.calls = 0.0, 0

    def state(self):
        return {'plate': self.plate, 'z0': self.z0, 't0': self.t0, 'Kplate': self.Kplate, 'calls': self.calls}

    def setState(self, s):
        for k, v in s.items():
            setattr(self, k, v)

    def start(self, exp, steel):
        """Seat the plate on the highest grain and put its control before NewtonIntegrator."""
        self.p = exp.p
        x, r = exp.grainArrays()[:2]
        self.z0 = float(np.max(x[:, 2] + r))
        self.plate = O.bodies.append(utils.wall(self.z0, axis=2, sense=-1, material=steel))
        self.t0 = O.time
        engines = list(O.engines)
        k = next(i for i, e in enumerate(engines) if type(e).__name__ == 'NewtonIntegrator')
        O.engines = engines[:k] + [PyRunner(command=command('loading', 'step'), iterPeriod=self.SERVO_PERIOD,
                                            label=self.LABEL)] + engines[k:]

    def bind(self, exp):
        self.p = exp.p

    def target(self, t):
        """Eq. 8 at loading time t [s]."""
        return eq8(self.p['Fmax'], self.p['f'], t)

    def force(self):
        """Force of the grains on the plate [N]: the plate moves kinematically, so the force
        container holds only its contact forces of this step."""
        return O.forces.f(self.plate)[2]

    def delta(self):
        """Plate displacement since the start of loading [m] (the paper's delta)."""
        return self.z0 - O.bodies[self.plate].state.pos[2]

    def top(self):
        return O.bodies[self.plate].state.pos[2]

    def step(self):
        p, n = self.p, self.SERVO_PERIOD
        F = self.force()
        if self.calls % self.KPLATE_EVERY == 0:
            # the wall has an interaction (mostly potential) with every grain: summed only now and then
            self.Kplate = sum(i.phys.kn for i in O.bodies[self.plate].intrs() if i.isReal)
        self.calls += 1
        err = self.target(O.time - self.t0 + n * O.dt) - F
        v = self.SERVO_GAIN * err / (max(self.Kplate, p['Fmax'] / 1e-3) * n * O.dt)  # Fmax/1 mm: approach gently
        O.bodies[self.plate].state.vel = Vector3(0, 0, -max(-p['vMax'], min(p['vMax'], v)))
