"""ballast.oedometer.loading: eq. 8 by hand, and the servo plate on one grain: the force on the plate
follows eq. 8 and the floor carries the plate force plus the grain's weight (statics)."""
import math

import numpy as np
import pytest

pytest.importorskip('yade')
from yade import O, utils  # noqa: E402

from ballast.oedometer import callbacks, check, scene  # noqa: E402
from ballast.oedometer.loading import ServoLoad, eq8  # noqa: E402

FMAX, F = 2e4, 50.0   # [N], [Hz]: a small load, a short cycle
R = 0.02              # [m] the grain
TOL_FOLLOW = 0.03     # [-] of Fmax: RMS of plate force - eq. 8 once the plate is seated (servo lag)
TOL_STATICS = 0.01    # [-] of Fmax: floor force - (plate force + weight), the grain's inertia at 50 Hz


def test_eq8_by_hand():
    T = 1 / F
    assert eq8(FMAX, F, 0.0) == pytest.approx(0.0, abs=1e-9 * FMAX)
    assert eq8(FMAX, F, T / 4) == pytest.approx(FMAX / 2, rel=1e-12)
    assert eq8(FMAX, F, T / 2) == pytest.approx(FMAX, rel=1e-12)
    assert eq8(FMAX, F, 3 * T / 4) == pytest.approx(FMAX / 2, rel=1e-12)
    t = np.linspace(0, T, 7)
    np.testing.assert_allclose(eq8(FMAX, F, t), [eq8(FMAX, F, float(x)) for x in t], rtol=1e-14, atol=1e-9)


class OneGrain:
    """What ServoLoad needs of an experiment: parameters, grains, and being the live one."""

    def __init__(self):
        self.p = check({'Fmax': FMAX, 'f': F, 'vMax': 1.0})
        self.loading = ServoLoad()

    def grainArrays(self):
        b = O.bodies[self.grain]
        return np.array([tuple(b.state.pos)]), np.array([b.shape.radius]), np.array([b.state.mass])

    def ownsScene(self):
        return True


def test_servo_plate_follows_eq8_on_one_grain():
    O.reset()
    exp = OneGrain()
    ballast, steel = scene.materials(exp.p, exp.p['young'])
    floor = O.bodies.append(utils.wall(0, axis=2, sense=1, material=steel))
    exp.grain = O.bodies.append(utils.sphere((0, 0, R), R, material=ballast))
    O.bodies[exp.grain].state.blockedDOFs = 'xyXYZ'  # only the axis: the statics are along z
    O.engines = scene.engines(damping=0.2)
    O.dt = 0.5 * utils.PWaveTimeStep()
    callbacks.setLive(exp)
    exp.loading.start(exp, steel)
    assert exp.loading.z0 == pytest.approx(2 * R, rel=1e-12)  # seated on the top of the grain
    assert [type(e).__name__ for e in O.engines][3:5] == ['PyRunner', 'NewtonIntegrator']  # the servo before Newton
    t, Fp, Ff = [], [], []
    steps = int(1 / F / O.dt)
    for _ in range(200):
        O.run(steps // 200, True)
        t.append(O.time - exp.loading.t0)
        Fp.append(exp.loading.force())
        Ff.append(-O.forces.f(floor)[2])
    t, Fp, Ff = map(np.array, (t, Fp, Ff))
    seated = t > 0.1 / F
    err = (Fp - eq8(FMAX, F, t)) / FMAX
    assert math.sqrt(np.mean(err[seated] ** 2)) <= TOL_FOLLOW
    weight = O.bodies[exp.grain].state.mass * 9.81
    assert np.max(np.abs(Ff - Fp - weight)[seated]) <= TOL_STATICS * FMAX
    assert exp.loading.delta() > 0  # the plate went down into the grain
    callbacks.setLive(None)
