"""Tests of pkg/python/bind_Fatigue.cpp: one sample of the grains' stress ratios s = sigma_e / f_t; a peak
s_p >= endurance that s falls `hysteresis` below adds D += (1 - s_p) s_p^b (Basquin-Miner, docs/fatigue.md),
and a grain crushes when s > 1 - D. The parameters are checked against their ranges: b in [1, 100],
endurance in [0, 1), hysteresis in [0.001, 0.5], rMin >= 0."""
import math

import numpy as np
import pytest

import ballast._ballast as B

FRESH = [0.0, 0.0, 1.0, 0.0]  # undamaged, no extreme yet, rising, no peak


def test_a_peak_is_counted_and_a_damaged_grain_crushes():
    """Three grains, exponent 2, endurance 0.5, hysteresis 0.1. Ratios 0.8, 0.4, 0.8 rise to their first sample;
    then 0.6, 0.25, 0.75: grain 0 fell 0.2 > 0.1 from 0.8, a peak: D = (1 - 0.8) 0.8^2 = 0.128, and 0.6 < 1 - 0.128
    leaves it; grain 1 fell 0.15 from 0.4 < endurance: a reversal without damage; grain 2 fell 0.05 < 0.1: still
    rising. Then 0.9 > 1 - 0.128 crushes grain 0."""
    fresh, r = np.tile(FRESH, (3, 1)), [0.02, 0.02, 0.02]
    st, crush = B.fatigueCheck([0.8, 0.4, 0.8], r, fresh, 2.0, 0.5, 0.1, 0.0)
    np.testing.assert_array_equal(st, [[0, 0.8, 1, 0], [0, 0.4, 1, 0], [0, 0.8, 1, 0]])
    assert crush.dtype == bool and not crush.any()
    st, crush = B.fatigueCheck([0.6, 0.25, 0.75], r, st, 2.0, 0.5, 0.1, 0.0)
    np.testing.assert_allclose(st, [[0.128, 0.6, 0, 1], [0, 0.25, 0, 0], [0, 0.8, 1, 0]], rtol=1e-15)
    assert not crush.any()
    st, crush = B.fatigueCheck([0.9, 0.3, 0.8], r, st, 2.0, 0.5, 0.1, 0.0)
    assert list(crush) == [True, False, False]
    assert fresh[0, 2] == 1.0 and fresh[0, 0] == 0.0  # the input state is not changed in place


def test_a_constant_peak_crushes_in_the_cycle_miners_rule_says():
    """s = 0.6 (1 - cos 2 pi t) / 2 sampled 20 times a cycle, b = 8: each peak adds 0.4 x 0.6^8 = 0.0067185; the
    grain crushes once s > 1 - D, i.e. once D > 0.4 after more than N_f = 0.6^-8 = 59.5 peaks: 60 peaks,
    counted in cycle 60, and the rise of cycle 61 crushes it."""
    state, cycle = np.array([FRESH]), 0
    while cycle < 100:
        cycle += 1
        for k in range(20):
            s = 0.6 * (1 - math.cos(2 * math.pi * k / 20)) / 2
            state, crush = B.fatigueCheck([s], [0.02], state, 8.0, 0.5, 0.05, 0.0)
            if crush[0]:
                break
        if crush[0]:
            break
    assert cycle == 61
    assert state[0, 3] == 60
    assert state[0, 0] == pytest.approx(60 * 0.4 * 0.6 ** 8, rel=1e-13)


def test_grains_below_rmin_never_degrade():
    st, crush = B.fatigueCheck([0.5, 0.5], [0.005, 0.02], [[0.9, 0, 1, 0]] * 2, 8.0, 0.5, 0.05, 0.01)
    assert list(crush) == [False, True]
    np.testing.assert_array_equal(st[0], [0.9, 0, 1, 0])  # not even sampled


@pytest.mark.parametrize('exponent,endurance,hysteresis', [(1.0, 0.0, 0.001), (100.0, 0.999, 0.5)])
def test_parameters_at_the_ends_of_their_ranges(exponent, endurance, hysteresis):
    st, _ = B.fatigueCheck([0.9, 0.1], [0.02, 0.02], [[0, 0.9, 1, 0], [0, 1.0, 1, 0]], exponent, endurance, hysteresis, 0.0)
    # grain 1 fell 0.9 from its peak 1.0 (>= any hysteresis): D = (1 - 1) 1^b = 0, one peak
    assert st[1, 3] == (1.0 if 1.0 >= endurance else 0.0) and st[1, 0] == 0.0


F1 = [FRESH]


@pytest.mark.parametrize('call,exc,message', [
    (lambda: B.fatigueCheck([0.5], [0.02], F1, 0.5, 0.5, 0.1, 0), ValueError, 'exponent: expected a number in [1, 100], got 0.5'),
    (lambda: B.fatigueCheck([0.5], [0.02], F1, 101, 0.5, 0.1, 0), ValueError, 'exponent: expected a number in [1, 100], got 101'),
    (lambda: B.fatigueCheck([0.5], [0.02], F1, 2, 1.0, 0.1, 0), ValueError, 'endurance: expected a number in [0, 1), got 1'),
    (lambda: B.fatigueCheck([0.5], [0.02], F1, 2, -0.1, 0.1, 0), ValueError, 'endurance: expected a number in [0, 1), got -0.1'),
    (lambda: B.fatigueCheck([0.5], [0.02], F1, 2, 0.5, 0.0005, 0), ValueError,
     'hysteresis: expected a number in [0.001, 0.5], got 0.0005'),
    (lambda: B.fatigueCheck([0.5], [0.02], F1, 2, 0.5, 0.7, 0), ValueError, 'hysteresis: expected a number in [0.001, 0.5], got 0.7'),
    (lambda: B.fatigueCheck([0.5], [0.02], F1, 2, 0.5, 0.1, -1.0), ValueError, 'rMin: expected a finite number >= 0, got -1'),
    (lambda: B.fatigueCheck([0.5], [0.02], np.zeros((2, 4)), 2, 0.5, 0.1, 0), TypeError,
     'state: expected an (1,4) array (damage, extreme, rising, peaks) per ratio, got shape (2,4)'),
    (lambda: B.fatigueCheck([-0.5], [0.02], F1, 2, 0.5, 0.1, 0), ValueError, 'ratio[0]: expected a finite number >= 0, got -0.5'),
    (lambda: B.fatigueCheck([0.5], [0.0], F1, 2, 0.5, 0.1, 0), ValueError, 'radii[0]: expected a finite number > 0, got 0'),
    (lambda: B.fatigueCheck([0.5], [0.02], [[0, 0, 2, 0]], 2, 0.5, 0.1, 0), ValueError,
     'state[0]: expected damage >= 0, rising 0 or 1 and peaks >= 0, got (0, 0, 2, 0)'),
    (lambda: B.fatigueCheck([0.0], [0.02], [[np.inf, 0, 1, 0]], 100, 0.5, 0.1, 0.0), ValueError,
     'state: expected finite numbers, got inf at flat index 0'),
])
def test_bad_input_names_the_argument_the_value_and_the_range(call, exc, message):
    with pytest.raises(exc) as e:
        call()
    assert str(e.value) == message
