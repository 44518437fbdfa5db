"""Tests of pkg/python/bind_InertialNumber.cpp: I = |rate| d sqrt(rho / p) (GDR MiDi 2004)."""
import math

import numpy as np
import pytest

import ballast._ballast as B


def test_inertial_number_by_hand():
    p = 1e6 / (math.pi * 0.15 ** 2)
    I = B.inertialNumber([1e-3 / 0.15, -0.1], 0.0325, 2600.0, p)
    np.testing.assert_allclose(I, [1e-3 / 0.15 * 0.0325 * math.sqrt(2600.0 / p), 0.1 * 0.0325 * math.sqrt(2600.0 / p)],
                               rtol=1e-15)


def test_bad_input_names_the_parameter():
    with pytest.raises(ValueError, match='pressure'):
        B.inertialNumber(0.1, 0.03, 2600.0, 0.0)
