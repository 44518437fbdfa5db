"""The binding of CycleJump.hpp (ballast._ballast.cycleJumpPlan): what it returns for a steady grain worked out by
hand, the shapes it refuses naming them. The law's bounds are tested in tests/cpp/test_CycleJump.cpp."""
import numpy as np
import pytest

from ballast import _ballast as B


def test_a_steady_grain_jumps_to_the_last_cycle_it_survives():
    """r = 0.4 0.6^8 a cycle at a peak of 0.6; after 4 cycles D = 4 r: it survives floor(0.4 / r - 4) = 55 more
    peaks, so 55 - margin 1 = 54 cycles; a grain without damage does not bound it."""
    r = 0.4 * 0.6 ** 8
    damage = np.array([[k * r, 0.0] for k in range(5)])
    cycles, limit, grain, maxRate, rate = B.cycleJumpPlan(damage, [0.6, 0.0], 1000, 4, 0.2, 0.99, 1)
    assert (cycles, limit, grain) == (54, 'failure', 0)
    assert maxRate == pytest.approx(r, rel=1e-14) and rate.shape == (2,) and rate[1] == 0.0


def test_no_damage_jumps_over_every_remaining_cycle():
    assert B.cycleJumpPlan(np.zeros((3, 4)), np.zeros(4), 99, 2, 0.2, 0.05, 1)[:3] == (99, 'remaining', -1)


@pytest.mark.parametrize('damage,peak,error,match', [
    (np.zeros((4, 2)), [0.0, 0.0], TypeError, r'damage: expected a \(3,2\) array'),
    (np.zeros((3, 2)), [0.0], TypeError, r'damage: expected a \(3,1\) array'),
    (np.zeros((3, 1)), [[0.0]], TypeError, 'peak: expected a 1-d array'),
    (np.array([[0.0], [0.2], [0.1]]), [0.6], ValueError, "grain 0's damage falls from 0.2 to 0.1"),
    (np.array([[0.0], [np.nan], [0.1]]), [0.6], ValueError, 'damage')])
def test_bad_arrays_are_refused_naming_them(damage, peak, error, match):
    """Shapes are TypeErrors, values ValueErrors, as in every binding."""
    with pytest.raises(error, match=match):
        B.cycleJumpPlan(damage, peak, 10, 2, 0.2, 0.05, 1)


def test_remaining_must_be_a_whole_number_of_cycles():
    for bad in (-1, 2.5, 1e16):
        with pytest.raises(ValueError, match=r'remaining: expected an integer in \[0, 1e15\]'):
            B.cycleJumpPlan(np.zeros((3, 1)), [0.0], bad, 2, 0.2, 0.05, 1)
