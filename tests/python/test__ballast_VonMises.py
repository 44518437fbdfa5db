"""Tests of pkg/python/bind_VonMises.cpp: the equivalent stress of eq. 2,
sigma_e = sqrt(((sI - sII)^2 + (sII - sIII)^2 + (sI - sIII)^2) / 2), and the principal stresses, of the
symmetric part of one (3,3) tensor or of an (N,3,3) stack."""
import math

import numpy as np
import pytest

import ballast._ballast as B


def test_von_mises_closed_forms():
    sig, tau = 7.0e6, 3.0e6
    assert B.vonMises(np.diag([sig, 0, 0])) == pytest.approx(sig, rel=1e-15)   # uniaxial: sigma_e = |sigma|
    assert B.vonMises(np.diag([0, 0, -sig])) == pytest.approx(sig, rel=1e-15)
    assert B.vonMises(np.eye(3) * -sig) == 0.0                                  # isotropic: no deviator
    shear = np.array([[0, tau, 0], [tau, 0, 0], [0, 0, 0]])
    assert B.vonMises(shear) == pytest.approx(math.sqrt(3) * tau, rel=1e-15)     # pure shear: sqrt(3) tau
    # (3, 2, 1) sigma: sqrt((1 + 1 + 4) / 2) sigma = sqrt(3) sigma
    assert B.vonMises(np.diag([3, 2, 1]) * sig) == pytest.approx(math.sqrt(3) * sig, rel=1e-15)


def test_only_the_symmetric_part_counts():
    # [[0, 2 tau], [0, 0]] has the symmetric part of the pure shear tau
    tau = 5.0
    skewed = np.array([[0, 2 * tau, 0], [0, 0, 0], [0, 0, 0]])
    assert B.vonMises(skewed) == pytest.approx(math.sqrt(3) * tau, rel=1e-15)
    np.testing.assert_allclose(B.principalStresses(skewed), [tau, 0, -tau], atol=1e-14)


def test_principal_stresses_sorted():
    np.testing.assert_allclose(B.principalStresses(np.diag([1.0, 3.0, 2.0])), [3, 2, 1], rtol=1e-15)


def test_stacks_match_eq2_from_the_principal_stresses():
    rng = np.random.default_rng(1)
    S = rng.normal(size=(50, 3, 3)) * 1e6
    ve, p = B.vonMises(S), B.principalStresses(S)
    assert ve.shape == (50,) and p.shape == (50, 3)
    assert np.all(p[:, 0] >= p[:, 1]) and np.all(p[:, 1] >= p[:, 2])
    eq2 = np.sqrt(((p[:, 0] - p[:, 1]) ** 2 + (p[:, 1] - p[:, 2]) ** 2 + (p[:, 0] - p[:, 2]) ** 2) / 2)
    np.testing.assert_allclose(ve, eq2, rtol=1e-10)
    assert B.vonMises(np.zeros((0, 3, 3))).shape == (0,)


@pytest.mark.parametrize('call,exc,message', [
    (lambda: B.vonMises(np.zeros((2, 2))), TypeError, 'sigma: expected a (3,3) or (N,3,3) array, got shape (2,2)'),
    (lambda: B.principalStresses(np.zeros((2, 3))), TypeError, 'sigma: expected a (3,3) or (N,3,3) array, got shape (2,3)'),
    (lambda: B.vonMises([np.eye(3), np.diag([1e200, 0, 0])]), ValueError,
     'sigma: expected values whose von Mises stress is finite, the result would be inf at index 1'),
    (lambda: B.principalStresses(np.full((3, 3), 1.7e308)), ValueError,
     'sigma: expected values whose principal stress is finite, the result would be nan'),
])
def test_bad_input_names_the_argument(call, exc, message):
    with pytest.raises(exc) as e:
        call()
    assert str(e.value) == message
