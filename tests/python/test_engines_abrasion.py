"""Tests of py/ballast/engines/abrasion.py inside YADE, against values computed by hand:
BallastAbrasionEngine. A grain abrades exactly above the strength of eq. 7; its radius scales by gamma,
its mass by gamma^3, its inertia by gamma^5, and its contacts and stress follow the new radius.
Runs in Debian's /usr/bin/python3 with YADE imported as a module (see conftest.py)."""
import math

import pytest
from yade import O, utils

import ballast
from ballast.engines import BallastAbrasionEngine
from ballast.scenes import squeezedStress
from engine_scenes import R, add, loadedGrain


@pytest.mark.parametrize('ratio', [1.01, 0.99])
def test_abrasion_scales_radius_by_gamma_mass_by_gamma3(ratio):
    g, w1, F, arm, uN = loadedGrain()
    p0 = 3 * F / (2 * math.pi * R * uN)               # eq. 7, wall: effective radius R
    b = O.bodies[g]
    m0, I0 = b.state.mass, b.state.inertia[0]
    gamma = 0.999
    ab = add(BallastAbrasionEngine(strength=p0 / ratio, gamma=gamma, iterPeriod=1, label='abrasion'))
    O.run(1, True)
    assert ab.maxPressureRatio == pytest.approx(ratio, rel=1e-9) or ab.nAbraded == 1
    if ratio < 1:
        assert ab.nAbraded == 0 and b.shape.radius == R
        return
    assert ab.nAbraded == 1
    assert b.shape.radius == pytest.approx(gamma * R, rel=1e-15)
    assert b.state.mass == pytest.approx(gamma ** 3 * m0, rel=1e-12)
    assert b.state.inertia[0] == pytest.approx(gamma ** 5 * I0, rel=1e-12)
    assert ab.events[0]['value'] == pytest.approx(p0, rel=1e-9)
    assert ab.massLost == pytest.approx((1 - gamma ** 3) * m0, rel=1e-9)
    assert ab.volumeLost == pytest.approx((1 - gamma ** 3) * 4 / 3 * math.pi * R ** 3, rel=1e-9)
    # The contacts' reference radius follows the radius (bodyStressTensors reads refR, not shape.radius):
    for i in O.bodies[g].intrs():
        assert (i.geom.refR1 if i.id1 == g else i.geom.refR2) == pytest.approx(gamma * R, rel=1e-15)
    O.run(1, True)  # contacts still closed (overlap > (1 - gamma) R): the stress uses the new volume
    i = O.interactions[g, w1]
    F2, arm2 = abs(O.forces.f(w1)[2]), (i.geom.contactPoint - b.state.pos).norm()
    S = ballast.matricesToArray(utils.bodyStressTensors())[g]
    assert -S[2, 2] == pytest.approx(squeezedStress(F2, gamma * R, arm2), rel=1e-9)
