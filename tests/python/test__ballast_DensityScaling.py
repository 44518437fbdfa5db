"""Tests of pkg/python/bind_DensityScaling.cpp: a sphere's own P-wave step r sqrt(rho / E) (eq. 5) and
YADE's densityScaling factor (ownStep / targetStep)^2 capped at 1, on scalars and broadcast arrays."""
import math

import numpy as np
import pytest

import ballast._ballast as B


def test_own_step_and_factor_by_hand():
    r = np.array([0.004, 0.01025, 0.02225])
    own = B.pWaveStep(r, 2600.0, 3e11)
    np.testing.assert_allclose(own, r * math.sqrt(2600.0 / 3e11), rtol=1e-15)
    s = B.densityScaling(own, 2e-6)
    np.testing.assert_allclose(s, np.minimum(1.0, (own / 2e-6) ** 2), rtol=1e-15)
    # each scaled body's own step, r sqrt(rho / (s E)), is the target where it was below it
    np.testing.assert_allclose(own / np.sqrt(s), np.maximum(own, 2e-6), rtol=1e-14)
    assert B.densityScaling(1e-7, 0.0) == 1.0


def test_bad_input_names_the_parameter():
    with pytest.raises(ValueError, match='targetStep'):
        B.densityScaling(1e-6, -1.0)
    with pytest.raises(ValueError, match='young'):
        B.pWaveStep(0.01, 2600.0, 0.0)
