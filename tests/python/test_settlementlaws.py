"""ballast.settlementlaws: the laws recovered from settlements made with them by hand (no YADE)."""
import numpy as np
import pytest

from ballast import settlementlaws


def test_a_logarithmic_and_a_power_settlement_give_their_laws_back():
    N = np.arange(1, 201)
    fit = settlementlaws.fitLaws(N, 1e-4 + 5e-5 * np.log(N))
    assert fit['log']['a'] == pytest.approx(1e-4, rel=1e-9) and fit['log']['b'] == pytest.approx(5e-5, rel=1e-9)
    assert fit['log']['r2'] == pytest.approx(1.0, abs=1e-12) and fit['power']['r2'] < 1 - 1e-3
    fit = settlementlaws.fitLaws(N, 2e-4 * N ** 0.2)
    assert fit['power']['c'] == pytest.approx(2e-4, rel=1e-9) and fit['power']['d'] == pytest.approx(0.2, rel=1e-9)
    assert fit['power']['r2'] == pytest.approx(1.0, abs=1e-12) and fit['log']['r2'] < 1 - 1e-3
    with pytest.raises(ValueError, match='at least 3 cycles N >= 1'):
        settlementlaws.fitLaws([0, 1, 2], [1, 2, 3])


def test_the_jumped_cycles_settlement_is_b_ln_N_over_n_with_b_known_then():
    """Rows: simulated cycles n = 1..5 at counted cycles 1, 2, 3, 10, 20 of a bed settling 2e-4 + 5e-5 ln n: the
    law (over rows ceil(n / 2)..n, at least 3) is found from the fourth row on, and the jumped cycles add
    5e-5 ln(N / n)."""
    n = np.arange(1, 6)
    N = np.array([1, 2, 3, 10, 20])
    got = settlementlaws.settlementJumped(N, 2e-4 + 5e-5 * np.log(n))
    np.testing.assert_allclose(got, [0, 0, 0, 5e-5 * np.log(10 / 4), 5e-5 * np.log(20 / 5)], rtol=1e-9, atol=1e-18)
    assert settlementlaws.settlementLaw([1e-4, 2e-4, 3e-4]) is None          # rows 2..3: two
    assert settlementlaws.settlementLaw(2e-4 + 5e-5 * np.log(n))['b'] == pytest.approx(5e-5, rel=1e-9)


def test_a_bed_that_stopped_settling_adds_nothing_for_its_jumped_cycles():
    """Settled 0.1 mm in its first 4 cycles, then not at all for 8: the recent half (rows 6..12) has b = 0, where a
    law over every row would extrapolate the early settling."""
    s = np.array([0.25, 0.5, 0.75, 1.0] + [1.0] * 8) * 1e-4
    N = np.arange(1, 13) * 10
    assert settlementlaws.settlementJumped(N, s)[-1] == pytest.approx(0.0, abs=1e-15)
    assert settlementlaws.fitLaws(np.arange(1, 13), s)['log']['b'] > 1e-5


def test_the_steps_of_cycles_that_crushed_are_not_extrapolated():
    """A bed settling 2e-4 + 5e-5 ln n over 200 simulated cycles, plus a step of 3 mm in cycle 150, in which a grain
    crushed: without the flags the law of the recent half (rows 100..200) takes the step for settling (b far above
    5e-5); with them cycle 150's whole increment is taken out of every row from 150 on, and b is 5e-5 less what
    the lost increment of one cycle, 5e-5 ln(150 / 149), tilts it (1.4 %): within 2 %. The laws of the rows before 150
    are untouched."""
    n = np.arange(1, 201)
    s = 2e-4 + 5e-5 * np.log(n) + np.where(n >= 150, 3e-3, 0.0)
    changed = n == 150
    want = s - np.where(n >= 150, s[149] - s[148], 0.0)
    np.testing.assert_allclose(settlementlaws.withoutSteps(s, changed), want, rtol=0, atol=1e-18)
    assert settlementlaws.settlementLaw(s)['b'] > 1e-3
    assert settlementlaws.settlementLaw(s, changed)['b'] == pytest.approx(5e-5, rel=0.02)
    N = n * 100
    got = settlementlaws.settlementJumped(N, s, changed)
    np.testing.assert_allclose(got[-1], 5e-5 * np.log(100), rtol=0.02)
    np.testing.assert_array_equal(got[:149], settlementlaws.settlementJumped(N, s)[:149])
    assert settlementlaws.settlementJumped(N, s)[-1] > 10 * got[-1]
    # no flag set: the settlements themselves, bit for bit; a flag on row 1 (the seating) takes nothing out
    np.testing.assert_array_equal(settlementlaws.withoutSteps(s, n < 0), s)
    np.testing.assert_array_equal(settlementlaws.withoutSteps(s, n == 1), s)
    with pytest.raises(ValueError, match='3 flags for 200 settlements'):
        settlementlaws.withoutSteps(s, [True, False, False])


def test_a_cycle_changed_the_bed_when_a_grain_crushed_or_abraded_in_it():
    # counts per cycle: cycles 2 (a crush), 3 (an abrasion) and 5 (both) changed it
    np.testing.assert_array_equal(settlementlaws.bedChanged([0, 1, 0, 0, 2], [0, 0, 3, 0, 1]),
                                  [False, True, True, False, True])
    # the same cycles as running totals: crushes 0 1 1 1 3, abrasions 0 0 3 3 4
    np.testing.assert_array_equal(settlementlaws.bedChanged([0, 1, 1, 1, 3], [0, 0, 3, 3, 4], totals=True),
                                  [False, True, True, False, True])
    assert list(settlementlaws.bedChanged([2], [0], totals=True)) == [True]  # the first cycle from 0
    assert settlementlaws.bedChanged(0, 1) and settlementlaws.bedChanged(1) and not settlementlaws.bedChanged(0, 0)
