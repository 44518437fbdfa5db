"""Tests of pkg/python/bind_HertzPressure.cpp: the maximum Hertz pressure of eq. 7, p0 = 3 F_N / (2 pi R u_N)
with R = R1 R2 / (R1 + R2) (0 = a wall), the contact modulus and eq. 7 from the force alone, on scalars
or broadcast arrays."""
import math

import numpy as np
import pytest

import ballast._ballast as B


def test_hertz_pressure_wall_and_two_spheres():
    F, uN, R1, R2 = 1.2e4, 2e-5, 0.02, 0.015
    assert B.hertzPressure(F, R1, 0, uN) == pytest.approx(3 * F / (2 * math.pi * R1 * uN), rel=1e-15)
    R = R1 * R2 / (R1 + R2)
    assert B.hertzPressure(F, R1, R2, uN) == pytest.approx(3 * F / (2 * math.pi * R * uN), rel=1e-15)
    p = B.hertzPressure([F, 2 * F], [R1, R1], 0, [uN, uN])  # a broadcast scalar wall radius
    np.testing.assert_allclose(p, [3 * F / (2 * math.pi * R1 * uN), 6 * F / (2 * math.pi * R1 * uN)], rtol=1e-15)
    assert B.hertzPressure(-F, R1, R2, uN) == 0.0  # no compression, no contact area
    assert B.hertzPressure(F, R1, R2, -uN) == 0.0


def test_effective_radius_without_overflow():
    assert B.effectiveRadius(0.03, 0.06) == pytest.approx(0.02, rel=1e-15)
    assert B.effectiveRadius(0.0, 0.06) == 0.06
    assert B.effectiveRadius(1e200, 1e200) == pytest.approx(5e199, rel=1e-15)
    assert B.effectiveRadius(1e-200, 1e-200) == pytest.approx(5e-201, rel=1e-15)


def test_contact_modulus_and_eq7_from_the_force():
    # ballast-steel contact modulus by hand; eq. 7 from (F, uN) on a Hertz contact = the force-only form
    E, nu = 3e11, 0.3
    Es = B.contactModulus(E, nu, 10 * E, 0.25)
    assert Es == pytest.approx(1 / ((1 - nu ** 2) / E + (1 - 0.25 ** 2) / (10 * E)), rel=1e-14)
    assert B.contactModulus(2.0, 0.0, 2.0, 0.0) == 1.0  # two equal bodies, nu = 0: E / 2
    F, R = np.array([10.0, 1e4, 1e6]), 0.012
    uN = (3 * F / (4 * Es * math.sqrt(R))) ** (2 / 3)
    np.testing.assert_allclose(B.hertzPressureFromForce(F, R, Es), B.hertzPressure(F, R, 0.0, uN), rtol=1e-12)
    assert B.hertzPressureFromForce(-1.0, R, Es) == 0.0


@pytest.mark.parametrize('call,exc,message', [
    (lambda: B.hertzPressure(1.0, -1.0, 0, 1e-3), ValueError, 'R1: expected a finite number >= 0, got -1'),
    (lambda: B.hertzPressure(1.0, 0, 0, 1e-3), ValueError,
     'R1, R2: expected at least one radius > 0 (0 means a wall), got 0 and 0'),
    (lambda: B.hertzPressure(1e300, 1e-10, 0, 1e-300), ValueError,
     'Fn, R1, R2, uN: expected values whose Hertz pressure is finite, the result would be inf at index 0'),
    (lambda: B.contactModulus(1.0, 0.5, 1.0, 0.2), ValueError, 'nu1, nu2: expected Poisson ratios in [-1, 0.5), got 0.5'),
    (lambda: B.contactModulus(1.0, -1.0, 1.0, -1.0), ValueError,
     'E1, nu1, E2, nu2: expected values whose contact modulus is finite, the result would be inf at index 0'),
    (lambda: B.hertzPressureFromForce(1.0, 0.0, 1e11), ValueError, 'R: expected a finite number > 0, got 0'),
    (lambda: B.hertzPressureFromForce(1.0, 1e-200, 1e11), ValueError,
     'Fn, R, Estar: expected values whose Hertz pressure is finite, the result would be inf at index 0'),
])
def test_bad_input_names_the_argument(call, exc, message):
    with pytest.raises(exc) as e:
        call()
    assert str(e.value) == message
