"""ballast.grading: the percentage passing, Marsal's B_g and Hardin's B_r against gradings worked
out by hand (no YADE)."""
import math

import numpy as np
import pytest

from ballast import grading

SIEVES = (0.063, 1.0, 10.0, 100.0)  # [mm] a short series for hand computations


def test_passing_by_mass_with_fines():
    d = np.array([0.5, 5, 50]) * 1e-3          # [m] one grain between each pair of sieves
    m = np.array([1.0, 2.0, 7.0])               # [kg]
    np.testing.assert_allclose(grading.passing(d, m, SIEVES), [0, 10, 30, 100])
    # 10 kg of dust pass every sieve: (0 + 10) / 20, (1 + 10) / 20, ...
    np.testing.assert_allclose(grading.passing(d, m, SIEVES, fines=10.0), [50, 55, 65, 100])
    # a grain exactly at a sieve's aperture passes it
    np.testing.assert_allclose(grading.passing([0.01], [1.0], SIEVES), [0, 0, 100, 100])
    with pytest.raises(ValueError, match='no mass'):
        grading.passing([], [], SIEVES)


def test_retained_sums_to_100():
    r = grading.retained([0, 10, 30, 100])
    np.testing.assert_allclose(r, [0, 10, 20, 70, 0])
    assert r.sum() == pytest.approx(100)


def test_marsal_by_hand():
    """Before: everything between 10 and 100 mm. After: half of it between 1 and 10 mm. The interval
    10-100 mm lost 50 % (100 -> 50), the others only gained: B_g = 50 %."""
    assert grading.marsal([0, 0, 0, 100], [0, 0, 50, 100]) == pytest.approx(50.0, rel=1e-12)
    # after: 20 % in the pan, 50 % in 1-10 mm, 30 % left in 10-100 mm: that interval lost 70 % (the others
    # gained 20 and 50): B_g = 70 %
    assert grading.marsal([0, 0, 0, 100], [20, 20, 70, 100]) == pytest.approx(70.0, rel=1e-12)
    # a coarse interval losing and a fine one losing too: both decreases count
    assert grading.marsal([0, 0, 40, 100], [60, 60, 60, 100]) == pytest.approx(40.0 + 20.0, rel=1e-12)
    assert grading.marsal([0, 0, 0, 100], [0, 0, 0, 100]) == 0.0


def test_hardin_by_hand():
    """Before: fraction passing 0 at 10 mm rising linearly in log10(d) to 1 at 100 mm. B_p is the area
    above the curve from log10(0.074) to 2: (1 - log10 0.074) under the full retained fraction from 0.074
    to 10 mm, plus the triangle 1/2 from 10 to 100 mm: 1 + 1.130768 + 0.5 = 2.630768. After: 0.5 passing
    10 mm, 0 at 1 mm: (0 - log10 0.074) + (1 - 0.25) + 0.25 = 2.130768. B_r = 0.5 / 2.630768 = 0.190058."""
    before, after = [0, 0, 0, 100], [0, 0, 50, 100]
    bp0 = 1 - math.log10(0.074) + 0.5
    bp1 = -math.log10(0.074) + 0.75 + 0.25
    assert grading.breakagePotential(before, SIEVES) == pytest.approx(bp0, rel=1e-12)
    assert grading.breakagePotential(after, SIEVES) == pytest.approx(bp1, rel=1e-12)
    assert grading.hardin(before, after, SIEVES) == pytest.approx(0.5 / bp0, rel=1e-12)
    assert grading.hardin(before, before, SIEVES) == 0.0


def test_hardin_fines_below_d0_have_no_potential():
    """All the mass below 0.074 mm (dust passing every sieve) has B_p = 0: B_r = 1."""
    assert grading.breakagePotential([100, 100, 100, 100], SIEVES) == pytest.approx(0.0, abs=1e-15)
    assert grading.hardin([0, 0, 0, 100], [100, 100, 100, 100], SIEVES) == pytest.approx(1.0, rel=1e-12)


def test_coarsest_sieve_must_pass_everything():
    with pytest.raises(ValueError, match='coarsest sieve'):
        grading.breakagePotential([0, 0, 0, 90], SIEVES)


def test_sieve_series():
    s = np.array(grading.SIEVES_MM)
    assert np.all(np.diff(s) > 0)
    for a in (0.063, 0.5, 22.4, 31.5, 40, 50, 63, 80):  # EN 13450's railway ballast sieves
        assert a in grading.SIEVES_MM


def test_bbi_by_hand():
    """Before: 0 % passing up to 10 mm, then linear in log10(d) to 100 % at 100 mm (its top size).
    After: 25 % passing 10 mm. A, between the curves: a triangle of height 25 over log10(1) to log10(100)
    = 25. The boundary of maximum breakage runs from 0 % at 0.075 mm to 100 % at 100 mm over the log
    length L = 2 - log10(0.075): the area under it is 50 L, the area under the grading before 50 (a
    triangle over [1, 2]): A + B = 50 (L - 1), BBI = 0.5 / (L - 1) = 0.235301."""
    before, after = [0, 0, 0, 100], [0, 0, 25, 100]
    L = 2 - math.log10(0.075)
    assert grading.bbi(before, after, SIEVES) == pytest.approx(0.5 / (L - 1), rel=1e-12)
    assert grading.bbi(before, before, SIEVES) == 0.0
    # the boundary from 1 mm instead: it passes 50 % at 10 mm, the grading after 25 %; A = 25 as above and
    # A + B = the area under the boundary (100) minus the area under the grading before (50): BBI = 0.5
    assert grading.bbi(before, after, SIEVES, finest=1.0) == pytest.approx(0.5, rel=1e-12)
    # a grading after that lies on that boundary: BBI = 1
    assert grading.bbi(before, [0, 0, 50, 100], SIEVES, finest=1.0) == pytest.approx(1.0, rel=1e-12)


def test_bbi_boundary_is_checked():
    with pytest.raises(ValueError, match='finest = 200'):
        grading.bbi([0, 0, 0, 100], [0, 0, 25, 100], SIEVES, finest=200.0)
    with pytest.raises(ValueError, match='coarsest sieve'):
        grading.bbi([0, 0, 0, 90], [0, 0, 25, 100], SIEVES)
    # the top size of a grading is the first sieve that passes everything
    assert grading.topSize([0, 0, 100, 100], SIEVES) == 10.0


def test_everything_passing_is_exactly_100_percent():
    """Issue found at the end of a 2-hour run: 1 400 fragments and the lost mass as fines summed to
    99.99999999999999 % on the coarsest sieve, and Hardin's index refused it as retained mass. A sieve
    that every grain passes gets exactly 100; the indices take a rounding-level shortfall."""
    rng = np.random.default_rng(3)
    d = rng.uniform(0.004, 0.03, 1400)
    m = rng.uniform(1e-4, 3e-2, 1400)
    P = grading.passing(d, m, SIEVES, fines=float(np.sum(m)) * 0.37)
    assert P[-1] == 100.0 and P[-2] < 100.0    # 100 mm passes every grain (30 mm at most), 10 mm not
    before = [0, 0, 0, 100 - 1e-14]
    assert grading.hardin(before, [0, 0, 50, 100], SIEVES) > 0 and grading.bbi(before, [0, 0, 50, 100], SIEVES) > 0


def test_bbi_stays_within_its_definition_with_dust_above_the_boundary():
    """The audit: BBI 1.061 and 1.193, the lost volume counted as dust passing below the boundary's 0.075 mm.
    Above the boundary the grading is maximum breakage already: BBI = 1, never more."""
    before = [0, 0, 0, 100]
    dusty = [60, 80, 90, 100]  # the finest sieve passes 60 %: above the boundary's 0 % at `finest`
    assert grading.bbi(before, dusty, SIEVES, finest=1.0) == pytest.approx(1.0, rel=1e-12)
    assert 0 <= grading.bbi(before, [30, 30, 40, 100], SIEVES, finest=1.0) <= 1
