"""The binding of CycleJump.hpp (ballast._ballast.cycleJumpPlan): what it returns for a steady grain worked out by
hand, the shapes and values it refuses naming them. The law's bounds are tested in tests/cpp/test_CycleJump.cpp
and fuzzed against the law written again in Python (test__ballast_fuzz.py)."""
import numpy as np
import pytest

from ballast import _ballast as B

LAW = dict(window=4, steady=0.2, maxDamage=0.99, margin=1, growth=1000.0, endurance=0.5, driftNoise=2.0, exponent=10.0,
           driftDamage=0.0)


def test_a_steady_grain_jumps_to_the_last_cycle_it_survives():
    """r = 0.4 0.6^8 a cycle at a peak of 0.6; after 4 cycles D = 4 r: it survives floor(0.4 / r - 4) = 55 more
    peaks, so 55 - margin 1 = 54 cycles; a grain without damage, its peaks steady at 0.3, does not bound it."""
    r = 0.4 * 0.6 ** 8
    damage = np.array([[k * r, 0.0] for k in range(5)])
    peaks = np.tile([0.6, 0.3], (4, 1))
    cycles, limit, grain, maxRate, rate, peak, drift = B.cycleJumpPlan(damage, peaks, 100, 1000, **LAW)
    assert (cycles, limit, grain, peak, drift) == (54, 'failure', 0, 0.6, 0.0)
    assert maxRate == pytest.approx(r, rel=1e-14) and rate.shape == (2,) and rate[1] == 0.0


def test_without_damage_the_count_at_most_doubles_at_growth_1():
    assert B.cycleJumpPlan(np.zeros((3, 4)), np.zeros((2, 4)), 40, 99, **dict(LAW, window=2, growth=1.0))[:3] == (
        40, 'growth', -1)
    assert B.cycleJumpPlan(np.zeros((3, 4)), np.zeros((2, 4)), 400, 99, **dict(LAW, window=2, growth=1.0))[:3] == (
        99, 'remaining', -1)


def test_peaks_that_only_scatter_do_not_bound_the_jump():
    """Peaks 0.38, 0.42 | 0.40, 0.44: the halves' means differ by 0.02, the difference's standard error is
    sqrt(4 0.02^2 / 2 (1/2 + 1/2)) = 0.028284; driftNoise 0.5: d = (0.02 - 0.014142) / 2 a cycle reaches the endurance
    ratio 0.5 from 0.44 in floor(20.485) = 20 cycles; at 2 the difference is noise, no bound."""
    peaks = np.array([[0.38], [0.42], [0.40], [0.44]])
    assert B.cycleJumpPlan(np.zeros((5, 1)), peaks, 10 ** 6, 1000, **dict(LAW, driftNoise=0.5))[:3] == (
        20, 'endurance', 0)
    assert B.cycleJumpPlan(np.zeros((5, 1)), peaks, 10 ** 6, 1000, **LAW)[:3] == (1000, 'remaining', -1)


def test_a_grain_drifting_past_the_endurance_ratio_collects_at_most_driftDamage():
    """b = 1, e = 0.25, peaks 0.109375 | 0.125 (window 2): d = 1/64 a cycle from 0.125. The bound on the damage
    collected, (1/d) [s^2/2 - s^3/3] from 0.25 to 0.125 + (DN + 1)/64, is 0.38997 at DN = 9 and 0.59546 at 10:
    driftDamage 0.5 allows 9 cycles; 0 allows 7 (the 8th peak is 0.25 itself and would collect (1 - 0.25) 0.25)."""
    law = dict(LAW, window=2, endurance=0.25, driftNoise=0.0, exponent=1.0, margin=0)
    peaks = np.array([[0.109375], [0.125]])
    plan = B.cycleJumpPlan(np.zeros((3, 1)), peaks, 10 ** 6, 1000, **dict(law, driftDamage=0.5))
    assert plan[:3] == (9, 'endurance', 0) and plan[5:] == (0.125, 1 / 64)
    assert B.cycleJumpPlan(np.zeros((3, 1)), peaks, 10 ** 6, 1000, **law)[:3] == (7, 'endurance', 0)


@pytest.mark.parametrize('damage,peaks,error,match', [
    (np.zeros((4, 2)), np.zeros((3, 2)), TypeError, r'damage: expected a \(3,N\) array'),
    (np.zeros((3, 2)), np.zeros((2, 1)), TypeError, r'peaks: expected a \(2,2\) array'),
    (np.array([[0.0], [0.2], [0.1]]), np.full((2, 1), 0.6), ValueError, "grain 0's damage falls from 0.2 to 0.1"),
    (np.array([[0.0], [np.nan], [0.1]]), np.full((2, 1), 0.6), ValueError, 'damage'),
    (np.array([[0.0], [0.1], [0.2]]), np.zeros((2, 1)), ValueError, "peaks: grain 0's damage grew")])
def test_bad_arrays_are_refused_naming_them(damage, peaks, error, match):
    """Shapes are TypeErrors, values ValueErrors, as in every binding."""
    with pytest.raises(error, match=match):
        B.cycleJumpPlan(damage, peaks, 10, 10, **dict(LAW, window=2))


def test_the_cycle_counts_must_be_whole_numbers_in_range():
    for name, bad in (('remaining', -1), ('remaining', 2.5), ('remaining', 1e16), ('cycle', 0)):
        args = dict(cycle=10, remaining=10, **dict(LAW, window=2))
        args[name] = bad
        with pytest.raises(ValueError, match=r'%s: expected an integer in \[' % name):
            B.cycleJumpPlan(np.zeros((3, 1)), np.zeros((2, 1)), **args)
