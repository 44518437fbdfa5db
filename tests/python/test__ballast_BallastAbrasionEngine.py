"""Tests of pkg/python/bind_BallastAbrasionEngine.cpp: the abrasion decision of eq. 6, abrade <=> r >= rMin and
max over the grain's contacts of p0 > strength, p0 = 3 F_N / (2 pi R u_N) of eq. 7, with the parameters checked
against their ranges (strength > 0, rMin >= 0); and the bounds on p0 that let the prefilter skip contacts."""
import math

import numpy as np
import pytest

import ballast._ballast as B


def p0(F, R, uN):
    return 3 * F / (2 * math.pi * R * uN)


def test_the_largest_pressure_over_the_contacts_of_each_side():
    radii = np.array([0.02, 0.01])
    F, uN = np.array([1e3, 5e3, 2e3]), np.array([1e-5, 1e-5, 2e-5])
    g1, g2 = np.array([0, 0, -1]), np.array([-1, 1, 1])  # -1: a wall or a body that is not checked
    R1, R2 = np.array([0.02, 0.02, 0.0]), np.array([0.0, 0.01, 0.01])
    p = p0(F, np.array([0.02, 0.02 * 0.01 / 0.03, 0.01]), uN)
    strength = 0.5 * (p[0] + p[1])
    pmax, abrade = B.abrasionCheck(radii, g1, g2, F, R1, R2, uN, strength, 0.0)
    np.testing.assert_allclose(pmax, [max(p[0], p[1]), max(p[1], p[2])], rtol=1e-12)
    assert abrade.dtype == bool and list(abrade) == [pmax[0] > strength, pmax[1] > strength]


def test_threshold_and_rmin():
    # each grain on a wall at 1.01 and 0.99 times the strength; below rMin never, at rMin yes
    S, uN, rMin = 2e8, 1e-5, 0.015
    radii = np.array([0.02, 0.02, 0.01, rMin])
    fac = np.array([1.01, 0.99, 5.0, 1.01])
    F = fac * S * 2 * math.pi * radii * uN / 3
    pmax, abrade = B.abrasionCheck(radii, np.arange(4), -np.ones(4, int), F, radii, np.zeros(4), np.full(4, uN), S, rMin)
    np.testing.assert_allclose(pmax, fac * S, rtol=1e-12)
    assert list(abrade) == [True, False, False, True]


def hertzContact(F, r, other, Es):
    """(F l, p0) of a Hertz contact of force F: overlap u = (3F / (4 E* sqrt R))^(2/3), branch l = r - u/2."""
    R = r if other == 0 else r * other / (r + other)
    u = (3 * F / (4 * Es * math.sqrt(R))) ** (2 / 3)
    return F * (r - u / 2), B.hertzPressure(F, r, other, u)


def test_fabric_stress_bound_of_grains_with_hertz_contacts():
    # grain 0 (r 0.02): one contact with the smallest sphere (0.005); grain 1 (r 0.01): a wall and a sphere of
    # 0.03; grain 2 unloaded. Traces from eq. 3: tr sigma = -sum F l / V.
    Es, rs = 1.6e11, 0.005
    radii = np.array([0.02, 0.01, 0.015])
    c0 = [hertzContact(5e4, 0.02, rs, Es)]
    c1 = [hertzContact(2e4, 0.01, 0.0, Es), hertzContact(8e4, 0.01, 0.03, Es)]
    sig = np.zeros((3, 3, 3))
    for g, cs in ((0, c0), (1, c1)):
        sig[g] = -np.eye(3) * sum(fl for fl, _ in cs) / (3 * 4 / 3 * math.pi * radii[g] ** 3)
    b = B.abrasionBound(sig, radii, rs, Es)
    assert b[0] >= c0[0][1] and b[1] >= max(p for _, p in c1)
    assert b[0] / c0[0][1] == pytest.approx((2 * c0[0][0] / 5e4 / 0.02) ** (1 / 3), rel=1e-12)  # (2 l / r)^(1/3)
    assert b[2] == 0.0


def test_sphere_contact_bound_is_eq7_at_the_largest_overlap_ratio():
    Es, R = 1.6e11, 0.02 * 0.005 / 0.025
    u = (3 * 5e4 / (4 * Es * math.sqrt(R))) ** (2 / 3)
    assert B.sphereContactBound(u / (2 * R), Es) == pytest.approx(B.hertzPressure(5e4, 0.02, 0.005, u), rel=1e-12)
    assert B.sphereContactBound(-1.0, Es) == 0.0  # YADE's value when no spheres touch


R1 = [0.01]


@pytest.mark.parametrize('call,exc,message', [
    (lambda: B.abrasionCheck(R1, [0], [-1], [1.0], [0.01], [0.0], [1e-6], -5.0, 0.0), ValueError,
     'strength: expected a finite number > 0, got -5'),
    (lambda: B.abrasionCheck(R1, [0], [-1], [1.0], [0.01], [0.0], [1e-6], 0.0, 0.0), ValueError,
     'strength: expected a finite number > 0, got 0'),
    (lambda: B.abrasionCheck(R1, [0], [-1], [1.0], [0.01], [0.0], [1e-6], 5.0, -1.0), ValueError,
     'rMin: expected a finite number >= 0, got -1'),
    (lambda: B.abrasionCheck(R1, [0], [1], [1.0], [0.01], [0.0], [1e-6], 1.0, 0.0), ValueError,
     'grain2[0]: expected -1 or 0 <= index < 1, got 1'),
    (lambda: B.abrasionCheck(R1, [3], [-1], [1.0], [0.01], [0.0], [1e-6], 1.0, 0.0), ValueError,
     'grain1[0]: expected -1 or 0 <= index < 1, got 3'),
    (lambda: B.abrasionCheck([0.01, 0.0], [0], [-1], [1.0], [0.01], [0.0], [1e-6], 5.0, 0.0), ValueError,
     'radii[1]: expected a finite number > 0, got 0'),
    (lambda: B.abrasionCheck(R1, [0, 0], [-1], [1.0], [0.01], [0.0], [1e-6], 1.0, 0.0), TypeError,
     'grain2: expected a 1-d array of length 2, like grain1, got shape (1,)'),
    (lambda: B.abrasionCheck(R1, [0], [-1], [1e300], [0.01], [0.0], [1e-300], 1.0, 0.0), ValueError,
     'Fn, R1, R2, uN: expected values whose Hertz pressure is finite, the result would be inf at index 0'),
    (lambda: B.abrasionBound(np.zeros((2, 3, 3)), [0.02], 0.0, 1e11), TypeError,
     'stresses: expected an (1,3,3) array, one tensor per radius, got shape (2,3,3)'),
    (lambda: B.abrasionBound(np.zeros((1, 3, 3)), [0.02], -1.0, 1e11), ValueError, 'rPartner: expected a finite number >= 0, got -1'),
    (lambda: B.abrasionBound(np.zeros((1, 3, 3)), [0.02], 0.0, 0.0), ValueError, 'EstarMax: expected a finite number > 0, got 0'),
    (lambda: B.abrasionBound(np.full((1, 3, 3), 1e308), [1.0], 0.0, 1e11), ValueError,
     'stresses: expected values whose trace is finite, the result would be inf at index 0'),
    (lambda: B.abrasionBound(-np.eye(3)[None] * 1e300, [1.0], 0.0, 1e11), ValueError,
     'stresses, radii, rPartner, EstarMax: expected values whose abrasion pressure bound is finite, the result would be '
     'inf at index 0'),
    (lambda: B.sphereContactBound(np.float64('nan'), 1e11), ValueError, 'maxOverlapRatio: expected a finite number, got nan'),
    (lambda: B.sphereContactBound(1e308, 1e308), ValueError,
     'maxOverlapRatio, EstarMax: expected values whose pressure bound is finite, the result would be inf'),
])
def test_bad_input_names_the_argument_the_value_and_what_is_allowed(call, exc, message):
    with pytest.raises(exc) as e:
        call()
    assert str(e.value) == message
