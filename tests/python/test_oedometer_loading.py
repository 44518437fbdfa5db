"""ballast.oedometer.loading: each load mode on one grain: the applied force is eq. 8 (ballast.oedometer.loadcurve),
the grain's force on the plate follows it, the floor carries that force plus the grain's weight
(statics), and the displacement mode moves the plate at its speed until the grain carries Fmax."""
import math

import numpy as np
import pytest

pytest.importorskip('yade')
from yade import O, utils  # noqa: E402

from ballast.experiments import scene  # noqa: E402
from ballast.oedometer import check  # noqa: E402
from ballast.experiments.oedometer.rig import Rig  # noqa: E402
from ballast.oedometer.loadcurve import eq8, loadCurve  # noqa: E402
from ballast.oedometer.loading import DisplacementLoad, PlateLoad, ServoLoad  # noqa: E402

FMAX, F = 2e4, 50.0   # [N], [Hz]: a small load, a short cycle
R = 0.02              # [m] the grain
TOL_FOLLOW = 0.03     # [-] of Fmax: RMS of plate force - eq. 8 once the plate is seated (servo lag)
TOL_STATICS = 0.01    # [-] of Fmax: floor force - (plate force + weight), the grain's inertia at 50 Hz
TOL_APPLIED = 1e-6    # [-] of Fmax: the plate's applied force against eq. 8 (interpolated from 4000 samples: 2.5e-7)


class OneGrain:
    """What a load needs: parameters and the rig (the grain is the scene's only sphere)."""

    def __init__(self, mode, **kw):
        self.p = check(dict({'Fmax': FMAX, 'f': F, 'vMax': 1.0, 'loadMode': mode}, **kw))
        self.loading = {'plate': PlateLoad, 'servo': ServoLoad, 'displacement': DisplacementLoad}[mode]()


def oneGrain(mode, **kw):
    """A grain on a floor with the plate of `mode` seated on it; (experiment, floor id)."""
    O.reset()
    exp = OneGrain(mode, **kw)
    ballast, steel = scene.materials(exp.p, exp.p['young'])
    floor = O.bodies.append(utils.wall(0, axis=2, sense=1, material=steel, mask=scene.STEEL_MASK))
    exp.grain = O.bodies.append(utils.sphere((0, 0, R), R, material=ballast, mask=scene.GRAIN_MASK))
    O.bodies[exp.grain].state.blockedDOFs = 'xyXYZ'  # only the axis: the statics are along z
    O.engines = scene.engines(damping=0.2, law=exp.p['law'])
    O.dt = 0.5 * utils.PWaveTimeStep()
    exp.loading.start(exp.p, Rig(None, ballast, steel))
    assert exp.loading.z0 == pytest.approx(2 * R, rel=1e-12)  # seated on the top of the grain
    return exp, floor


@pytest.mark.parametrize('mode,law', [('plate', 'linear'), ('servo', 'linear'), ('plate', 'hertz'), ('servo', 'hertz')])
def test_plate_follows_eq8_on_one_grain(mode, law):
    exp, floor = oneGrain(mode, law=law)
    names = [type(e).__name__ for e in O.engines]
    assert names.index('NewtonIntegrator') == names.index(
        'InterpolatingDirectedForceEngine' if mode == 'plate' else 'Callback') + 1  # the load acts before Newton
    t, Fp, Fa, Ff, d = [], [], [], [], []
    steps = int(1 / F / O.dt)
    for _ in range(200):
        O.run(steps // 200, True)
        t.append(O.time - exp.loading.t0)
        Fp.append(exp.loading.force())
        Fa.append(exp.loading.applied())
        Ff.append(-O.forces.f(floor)[2])
        d.append(exp.loading.delta())
    t, Fp, Fa, Ff, d = map(np.array, (t, Fp, Fa, Ff, d))
    seated = t > 0.1 / F
    if mode == 'plate':  # the force applied to the plate is eq. 8 of the step's time
        tStep = t - O.dt  # the recorded force was applied at the start of the last step
        assert np.max(np.abs(Fa - eq8(FMAX, F, tStep))) <= TOL_APPLIED * FMAX
        b = O.bodies[exp.loading.plate]
        mass = exp.p['steelDensity'] * math.pi * (exp.p['diameter'] / 2) ** 2 * exp.p['plateThickness']
        assert b.state.mass == pytest.approx(mass, rel=1e-12) and b.state.blockedDOFs == 'xyXYZ'
    err = (Fp - eq8(FMAX, F, t)) / FMAX
    assert math.sqrt(np.mean(err[seated] ** 2)) <= TOL_FOLLOW
    weight = O.bodies[exp.grain].state.mass * 9.81
    assert np.max(np.abs(Ff - Fp - weight)[seated]) <= TOL_STATICS * FMAX
    assert d[np.argmax(Fp)] > 0  # the plate went down into the grain


def test_plate_cycles_between_fmax_and_fmin():
    """Fmin > 0: after the first peak the applied force is loadCurve's cycle (the force table switches at
    T/2), for two more cycles."""
    Fmin = 0.3 * FMAX
    exp, _ = oneGrain('plate', Fmin=Fmin)
    t, Fa = [], []
    steps = int(1 / F / O.dt)
    for _ in range(250):
        O.run(int(2.5 * steps) // 250, True)
        t.append(O.time - exp.loading.t0 - O.dt)  # the force recorded was applied at the start of the last step
        Fa.append(exp.loading.applied())
    t, Fa = np.array(t), np.array(Fa)
    assert t[-1] > 2.4 / F
    assert np.max(np.abs(Fa - loadCurve(FMAX, Fmin, F, t))) <= TOL_APPLIED * FMAX
    assert np.min(Fa[t > 0.6 / F]) == pytest.approx(Fmin, rel=1e-3)


def test_displacement_mode_moves_at_its_speed_until_fmax():
    speed = 0.02  # [m/s]
    exp, _ = oneGrain('displacement', plateSpeed=speed)
    assert not exp.loading.done()
    O.run(1000, True)
    assert exp.loading.delta() == pytest.approx(speed * 1000 * O.dt, rel=1e-9)
    assert np.isnan(exp.loading.applied())
    while not exp.loading.done():
        O.run(200, True)
    assert exp.loading.force() >= FMAX
