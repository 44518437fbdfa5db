"""Tests of pkg/python/bind_Strength.cpp: the size-dependent strength of eq. 4, f_t = ft0 / r^m, with ft0 and m
checked against the engines' ranges (the C++ declaration ballast.params uses too: ft0 > 0, m in [0, 3])."""
import numpy as np
import pytest

import ballast._ballast as B
from ballast.engineparams import CRUSH


def test_size_strength_eq4():
    assert B.sizeStrength(2.0e5, 0.02) == pytest.approx(1.0e7, rel=1e-15)        # default m = 1, the paper
    assert B.sizeStrength(3.1e6, 0.0175, 1.0) == 3.1e6 / 0.0175                  # m = 1 is one division
    np.testing.assert_allclose(B.sizeStrength(100.0, [0.1, 0.2], 2.0), [1e4, 2500.0], rtol=1e-15)
    assert B.sizeStrength(6e6, 0.02, 0.0) == 6e6                                  # m = 0: no size effect
    assert B.sizeStrength(2.0, 0.5, 3.0) == pytest.approx(16.0, rel=1e-15)        # m = 3, the top of its range
    # halving the radius multiplies f_t by 2^m
    assert B.sizeStrength(1e5, 0.01, 1.5) / B.sizeStrength(1e5, 0.02, 1.5) == pytest.approx(2 ** 1.5, rel=1e-14)


def test_the_ranges_are_the_engines():
    for v in (0.0, 3.0):
        assert CRUSH['m'].check(v) == v
        B.sizeStrength(1e5, 0.02, v)
    for v in (-1e-300, np.nextafter(3.0, 4.0)):
        with pytest.raises(ValueError):
            CRUSH['m'].check(v)
        with pytest.raises(ValueError, match=r'^m: expected a number in \[0, 3\], got '):
            B.sizeStrength(1e5, 0.02, v)


@pytest.mark.parametrize('call,message', [
    (lambda: B.sizeStrength(0.0, 0.02, 1.0), 'ft0: expected a finite number > 0, got 0'),
    (lambda: B.sizeStrength(-1.0, 0.02), 'ft0: expected a finite number > 0, got -1'),
    (lambda: B.sizeStrength(1e5, -0.02, 1.0), 'radius: expected a finite number > 0, got -0.02'),
    (lambda: B.sizeStrength(1e5, 0.02, -1.0), 'm: expected a number in [0, 3], got -1'),
    (lambda: B.sizeStrength(1e5, 0.02, [1.0, 3.5]), 'm: expected a number in [0, 3], got 3.5'),
    (lambda: B.sizeStrength(1e5, 0.02, np.nan), 'm: expected finite numbers, got nan at flat index 0'),
    (lambda: B.sizeStrength(1e300, 1e-100, 3),
     'ft0, radius, m: expected values whose strength ft0 / r^m is finite, the result would be inf at index 0'),
])
def test_bad_input_names_the_argument_the_value_and_the_range(call, message):
    with pytest.raises(ValueError) as e:
        call()
    assert str(e.value) == message
