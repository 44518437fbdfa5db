"""Rolling resistance (rollingFriction > 0, docs/box.md "Rolling resistance"): YADE's CohFrictMat without
cohesion on the linear law. Worked out by hand: the contact keeps the linear law's stiffness and limits
its rolling moment to rollingFriction min(R1, R2) Fn; a sphere resting on a fixed sphere of the same
radius with its contact at an angle theta from the vertical carries m g sin(theta) in friction, whose
moment about its centre the rolling moment must balance: it stays where tan(theta) < rollingFriction
and rolls off where tan(theta) > rollingFriction (friction tan 0.8 = 1.03 holds it in both)."""
import math

import pytest

pytest.importorskip('yade')
from yade import O, utils  # noqa: E402

from ballast.experiments.box import check as boxCheck  # noqa: E402
from ballast.experiments import scene  # noqa: E402
from ballast.experiments.oedometer.parameters import check  # noqa: E402
from ballast.geometry import frictPhysStiffness  # noqa: E402
from ballast.params import ParamError  # noqa: E402

R, ETA = 0.015, 0.2   # [m], [-]


def pair(theta, eta=ETA):
    """A fixed sphere and a free one resting on it, their contact at theta [rad] from the vertical, gravity on."""
    O.reset()
    p = boxCheck({'rollingFriction': eta, 'young': 3e8})
    ballast, _ = scene.materials(p, p['young'])
    O.engines = scene.engines(0.3, 'linear', scene.rolling(p))
    low = O.bodies.append(utils.sphere((0, 0, 0), R, material=ballast, fixed=True))
    u = 1e-6   # a small overlap: the contact exists from the first step
    top = O.bodies.append(utils.sphere(((2 * R - u) * math.sin(theta), 0, (2 * R - u) * math.cos(theta)), R,
                                       material=ballast))
    O.dt = 0.5 * utils.PWaveTimeStep()
    return p, low, top


def test_a_grain_pair_keeps_the_linear_stiffness_and_limits_rolling_to_eta_r_fn():
    p, low, top = pair(0.0)
    O.run(int(0.1 / O.dt), True)   # resting on it (the first overlap pushes it off a little)
    i = O.interactions[low, top]
    assert i.isReal
    assert type(i.phys).__name__ == 'CohFrictPhys' and type(i.geom).__name__ == 'ScGeom6D'
    kn, ks = frictPhysStiffness(3e8, p['poisson'], R, 3e8, p['poisson'], R)
    assert i.phys.kn == pytest.approx(kn, rel=1e-12) and i.phys.ks == pytest.approx(ks, rel=1e-12)
    assert i.phys.maxRollPl == pytest.approx(ETA * R, rel=1e-12)
    assert i.phys.tangensOfFrictionAngle == pytest.approx(math.tan(0.8), rel=1e-12)


@pytest.mark.parametrize('tanTheta, stays', [(0.5 * ETA, True), (2.0 * ETA, False)])
def test_a_sphere_on_a_sphere_stays_while_tan_theta_is_below_the_rolling_friction(tanTheta, stays):
    theta = math.atan(tanTheta)
    _, low, top = pair(theta)
    x0 = O.bodies[top].state.pos[0]
    O.run(int(0.3 / O.dt), True)   # 0.3 s: a sphere rolling off has left by several mm (g t^2 / 2 sin(theta) > 30 mm)
    moved = abs(O.bodies[top].state.pos[0] - x0)
    if stays:
        assert moved < 1e-4 and O.interactions.has(low, top)
    else:
        assert moved > 5e-3


def test_without_rolling_friction_the_paper_spheres_roll_off():
    theta = math.atan(0.5 * ETA)
    O.reset()
    p = boxCheck({'young': 3e8, 'rollingFriction': 0.0})
    ballast, _ = scene.materials(p, p['young'])
    assert type(ballast).__name__ == 'FrictMat'
    O.engines = scene.engines(0.3, 'linear', scene.rolling(p))
    O.bodies.append(utils.sphere((0, 0, 0), R, material=ballast, fixed=True))
    top = O.bodies.append(utils.sphere(((2 * R - 1e-6) * math.sin(theta), 0, (2 * R - 1e-6) * math.cos(theta)), R,
                                       material=ballast))
    O.dt = 0.5 * utils.PWaveTimeStep()
    x0 = O.bodies[top].state.pos[0]
    O.run(int(0.3 / O.dt), True)
    assert abs(O.bodies[top].state.pos[0] - x0) > 5e-3


def test_rolling_friction_needs_the_linear_law():
    for checker in (check, boxCheck):
        with pytest.raises(ParamError, match="rollingFriction = 0.1 is not allowed: needs law = 'linear'"):
            checker({'rollingFriction': 0.1, 'law': 'hertz'})
