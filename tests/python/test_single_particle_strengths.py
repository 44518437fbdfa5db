"""ballast.experiments.single_particle.strengths: survival by mean rank, the Weibull fit with its 95 %
intervals, and the size law fitted to every grain (no YADE)."""
import math

import numpy as np
import pytest

from ballast.experiments.single_particle import strengths

FT0, M = 3.1e6, 1.0


def test_survival_by_mean_rank():
    s, ps = strengths.survival([3.0, 1.0, 2.0])
    assert s.tolist() == [1.0, 2.0, 3.0] and ps.tolist() == [0.75, 0.5, 0.25]   # 1 - i / (N + 1)


@pytest.mark.parametrize('k', [3.0, 10.0])
def test_weibull_fit_contains_the_modulus_and_the_scale(k):
    w = 2e7 * np.random.default_rng(7).weibull(k, 400)
    fit = strengths.weibullFit(w)
    assert fit['modulusLow'] < k < fit['modulusHigh'] and fit['scaleLow'] < 2e7 < fit['scaleHigh']
    # the interval is the Fisher one: half-width 1.96 k sqrt(0.608 / N)
    assert (fit['modulusHigh'] - fit['modulusLow']) / 2 == pytest.approx(1.96 * fit['modulus'] * math.sqrt(0.6079 / 400),
                                                                        rel=1e-3)


def test_weibull_fit_of_equal_values_and_too_few():
    assert strengths.weibullFit([5.0, 5.0, 5.0])['modulus'] == math.inf
    assert strengths.weibullFit([1.0, 2.0]) is None


@pytest.mark.parametrize('k', [3.0, 10.0])
def test_size_law_recovers_ft0_m_and_the_modulus(k):
    rng = np.random.default_rng(11)
    r = rng.uniform(0.01025, 0.02225, 300)
    fit = strengths.sizeLawFit(r, FT0 / r ** M * rng.weibull(k, 300))
    assert fit['kLow'] < k < fit['kHigh'] and fit['bLow'] < M < fit['bHigh'] and fit['s0Low'] < FT0 < fit['s0High']


def test_size_law_without_scatter_is_the_closed_form():
    r = np.array([0.01, 0.015, 0.02, 0.022])
    fit = strengths.sizeLawFit(r, FT0 / r ** 1.5)
    assert fit['b'] == pytest.approx(1.5, rel=1e-12) and fit['s0'] == pytest.approx(FT0, rel=1e-12)
    assert fit['k'] == math.inf
    with pytest.raises(ValueError, match='at least 3 grains of at least 2 sizes'):
        strengths.sizeLawFit([0.01, 0.01, 0.01], [1.0, 2.0, 3.0])


def test_classes_of_equal_width():
    cls, edges = strengths.classes([0.0205, 0.028, 0.0285, 0.0445], 0.0205, 0.0445, 3)
    assert edges.tolist() == pytest.approx([0.0205, 0.0285, 0.0365, 0.0445]) and cls.tolist() == [0, 0, 1, 2]


def test_a_modulus_of_rounding_is_no_scatter():
    """Strengths on one law up to a relative noise of 1e-6 (a deterministic test's rounding) fit a modulus in the
    thousands: above NO_SCATTER it is reported as infinite, in a class fit and in the size law."""
    rng = np.random.default_rng(5)
    r = rng.uniform(0.01, 0.022, 40)
    sigma = 3.1e6 / r * (1 + 1e-6 * rng.standard_normal(40))
    w = strengths.weibullFit(1e8 * (1 + 1e-6 * rng.standard_normal(10)))   # one size, rounding only
    assert math.isinf(w['modulus']) and math.isinf(w['modulusLow'])
    law = strengths.sizeLawFit(r, sigma)
    assert math.isinf(law['k']) and law['b'] == pytest.approx(1.0, abs=1e-4)
    # real scatter stays finite
    assert strengths.weibullFit(rng.weibull(5.0, 200) * 1e8)['modulus'] < strengths.NO_SCATTER
