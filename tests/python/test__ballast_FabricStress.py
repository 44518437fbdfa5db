"""Tests of pkg/python/bind_FabricStress.cpp: the fabric (Love-Weber) stress of eq. 3,
sigma_ij = (1/V) sum_c l_i^c F_j^c, V = 4/3 pi r^3, of one grain (fabricStress) and of many (grainStresses)."""
import math

import numpy as np
import pytest

import ballast._ballast as B


def test_two_opposite_forces_give_3F_over_2pi_r2():
    # l = (+-r, 0, 0), F = (-+F, 0, 0): sum l_x F_x = -2 r F, over V: -3 F / (2 pi r^2); every other entry is 0
    r, F = 0.016, 2.5e4
    s = B.fabricStress(r, [[r, 0, 0], [-r, 0, 0]], [[-F, 0, 0], [F, 0, 0]])
    assert s.shape == (3, 3)
    assert s[0, 0] == pytest.approx(-3 * F / (2 * math.pi * r ** 2), rel=1e-14)  # compression negative
    s[0, 0] = 0
    assert not s.any()


def test_the_tensor_is_not_symmetrised():
    # a tangential force F_y at l = (r, 0, 0) gives sigma_xy = r F / V and sigma_yx = 0
    r, F = 0.5, 3.0
    s = B.fabricStress(r, [[r, 0, 0]], [[0, F, 0]])
    assert s[0, 1] == pytest.approx(r * F / (4 / 3 * math.pi * r ** 3), rel=1e-15)
    assert s[1, 0] == 0


def test_grain_stresses_are_eq3_grain_by_grain():
    radii = np.array([0.01, 0.02, 0.03])
    idx = np.array([0, 0, 1, 1, 1])  # grain 2 has no contact
    rng = np.random.default_rng(2)
    l, f = rng.normal(size=(5, 3)) * 0.01, rng.normal(size=(5, 3)) * 1e3
    S = B.grainStresses(radii, idx, l, f)
    assert S.shape == (3, 3, 3)
    for g in range(2):
        m = idx == g
        expected = np.einsum('ci,cj->ij', l[m], f[m]) / (4 / 3 * math.pi * radii[g] ** 3)
        np.testing.assert_allclose(S[g], expected, rtol=1e-12)
        np.testing.assert_allclose(S[g], B.fabricStress(radii[g], l[m], f[m]), rtol=1e-15)
    assert not S[2].any()
    assert B.grainStresses([], np.zeros(0, dtype=int), np.zeros((0, 3)), np.zeros((0, 3))).shape == (0, 3, 3)


def test_huge_radius_that_stays_finite():
    r = 1e100
    s = B.fabricStress(r, [[r, 0, 0], [-r, 0, 0]], [[-1e150, 0, 0], [1e150, 0, 0]])
    assert s[0, 0] == pytest.approx(-3 * 1e150 / (2 * math.pi * r ** 2), rel=1e-12)


@pytest.mark.parametrize('call,exc,message', [
    (lambda: B.fabricStress(-1.0, [[1, 0, 0]], [[1, 0, 0]]), ValueError, 'radius: expected a finite number > 0, got -1'),
    (lambda: B.fabricStress(0.0, [[1, 0, 0]], [[1, 0, 0]]), ValueError, 'radius: expected a finite number > 0, got 0'),
    (lambda: B.fabricStress('a', [[1, 0, 0]], [[1, 0, 0]]), TypeError, 'radius: expected real numbers, got dtype <U1'),
    (lambda: B.fabricStress(1.0, [[1, 0, 0]], [[1, 0, 0], [1, 0, 0]]), TypeError,
     'forces: expected as many rows as branches (1), got 2'),
    (lambda: B.fabricStress(1e-200, [[1, 0, 0]], [[1, 0, 0]]), ValueError,
     'radius: expected a radius whose volume 4/3 pi r^3 neither under- nor overflows (about 2e-103 < r < 3e102), got 1e-200'),
    (lambda: B.fabricStress(1e103, [[1, 0, 0]], [[1, 0, 0]]), ValueError,
     'radius: expected a radius whose volume 4/3 pi r^3 neither under- nor overflows (about 2e-103 < r < 3e102), got 1e+103'),
    (lambda: B.fabricStress(1e-100, [[1, 0, 0]], [[1e100, 0, 0]]), ValueError,
     'radius, branches, forces: expected values whose fabric stress is finite, the result would be inf'),
    (lambda: B.grainStresses([1.0], [3], [[1, 0, 0]], [[1, 0, 0]]), ValueError, 'grainIndex[0]: expected 0 <= index < 1, got 3'),
    (lambda: B.grainStresses([1.0], [0, 0], [[1, 0, 0]], [[1, 0, 0]]), TypeError,
     'branches: expected an (2,3) array, one row per grainIndex, got shape (1,3)'),
    (lambda: B.grainStresses([1.0, 1e-200], [0], [[1, 0, 0]], [[1, 0, 0]]), ValueError,
     'radii[1]: expected a radius whose volume 4/3 pi r^3 neither under- nor overflows (about 2e-103 < r < 3e102), got 1e-200'),
    (lambda: B.grainStresses([1.0, 1e-100], [1], [[1, 0, 0]], [[1e100, 0, 0]]), ValueError,
     'radii, branches, forces: expected values whose fabric stress is finite, the result would be inf at index 1'),
])
def test_bad_input_names_the_argument(call, exc, message):
    with pytest.raises(exc) as e:
        call()
    assert str(e.value) == message
