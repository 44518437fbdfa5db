"""Tests of pkg/python/bind_Weibull.cpp: the grains' Weibull strength factors w = (-ln U)^(1/k), U uniform from
(seed, key), with the modulus k checked against its range (0, no scatter, or [1, 50]) and the seed against
[0, 2^63 - 1], the ranges ballast.params declares."""
import math

import numpy as np
import pytest

import ballast._ballast as B


def ksDistance(sorted_sample, cdf):
    n = len(sorted_sample)
    return max(np.max(np.arange(1, n + 1) / n - cdf), np.max(cdf - np.arange(n) / n))


def test_strengths_of_many_grains_follow_the_weibull_law_and_eq4():
    """5 000 grains of each of two sizes with modulus k = 3: the strengths f_t = w ft0 / r^m pass a
    Kolmogorov-Smirnov test against P_f = 1 - exp(-(f / sigma_0)^k) with sigma_0 = ft0 / r^m (eq. 4, the
    characteristic strength) at the 1 % level (D < 1.628 / sqrt(n) = 0.023), and a size law off by 10 % fails it."""
    n, ft0, k = 5000, 2e5, 3.0
    for r, keys in ((0.01, np.arange(n)), (0.02, np.arange(n, 2 * n))):
        w = B.weibullFactors(9, keys, k)
        _, ft, _ = B.crushCheck(np.zeros((n, 3, 3)), np.full(n, r), ft0, 1.0, 0.0, factor=w)
        sigma0, f = ft0 / r, np.sort(ft)
        assert ksDistance(f, 1 - np.exp(-(f / sigma0) ** k)) < 1.628 / math.sqrt(n), r
        assert np.quantile(ft, 1 - math.exp(-1)) == pytest.approx(sigma0, rel=0.03)
        assert ksDistance(f, 1 - np.exp(-(f / (1.1 * sigma0)) ** k)) > 1.628 / math.sqrt(n)


def test_modulus_one_is_the_exponential_law():
    # k = 1: w = -ln U is exponential with mean 1 and median ln 2 (standard errors 0.007 and 0.007 at n = 20 000)
    w = B.weibullFactors(5, np.arange(20000), 1.0)
    assert np.mean(w) == pytest.approx(1.0, abs=0.03)
    assert np.median(w) == pytest.approx(math.log(2), abs=0.03)


def test_no_scatter_reproducible_and_independent_of_the_order():
    np.testing.assert_array_equal(B.weibullFactors(3, [5, 1, 9], 0.0), [1.0, 1.0, 1.0])  # k = 0: w = 1 exactly
    a = B.weibullFactors(11, [5, 17, 3], 3.0)
    np.testing.assert_array_equal(a[::-1], B.weibullFactors(11, [3, 17, 5], 3.0))
    assert B.weibullFactors(11, [17], 3.0)[0] == a[1]
    assert B.weibullFactors(12, [5], 3.0)[0] != a[0]  # another seed, another strength
    top = 2 ** 63 - 1  # the largest seed
    assert B.weibullFactors(top, [1], 3.0)[0] != B.weibullFactors(top - 1, [1], 3.0)[0]


@pytest.mark.parametrize('modulus', [0.0, 1.0, 50.0])
def test_modulus_at_the_ends_of_its_range(modulus):
    assert np.all(B.weibullFactors(1, np.arange(10), modulus) > 0)


@pytest.mark.parametrize('call,exc,message', [
    (lambda: B.weibullFactors(1, [1, 2], -2.0), ValueError, 'modulus: expected 0 or a number in [1, 50], got -2'),
    (lambda: B.weibullFactors(1, [1, 2], 0.5), ValueError, 'modulus: expected 0 or a number in [1, 50], got 0.5'),
    (lambda: B.weibullFactors(1, [1, 2], 50.5), ValueError, 'modulus: expected 0 or a number in [1, 50], got 50.5'),
    (lambda: B.weibullFactors(1, [1, 2], np.nan), ValueError, 'modulus: expected a finite number, got nan'),
    (lambda: B.weibullFactors(1, [1, -2], 3.0), ValueError, 'keys: expected integers >= 0, got -2 at index 1'),
    (lambda: B.weibullFactors(-1, [1], 3.0), ValueError, 'seed: expected an integer in [0, 2^63 - 1], got -1'),
    (lambda: B.weibullFactors(2 ** 63, [1], 3.0), ValueError,
     'seed: expected an integer in [0, 2^63 - 1], got 9223372036854775808'),
    (lambda: B.weibullFactors(1.0, [1], 3.0), TypeError, 'seed: expected an integer in [0, 2^63 - 1], got 1.0'),
])
def test_bad_input_names_the_argument_the_value_and_the_range(call, exc, message):
    with pytest.raises(exc) as e:
        call()
    assert str(e.value) == message
