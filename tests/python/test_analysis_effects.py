"""Tests of ballast.analysis.effects: Kruskal-Wallis across the values of the studied parameter, Friedman
and Page within seeds, and the differences the runs could have detected, each worked out by hand on a
fabricated study (study_fakes.fabricateStudy; no yade)."""
import math

import numpy as np
import pytest

from ballast.analysis.effects import blockedTest, effectTest
from ballast.study.data import StudyData
from study_fakes import MISSING, RUNS, fabricateStudy


def test_kruskal_wallis_and_the_detectable_difference_by_hand(tmp_path):
    # two values of Tc, displacements 1, 2, 3 mm and 4, 5, 6 mm: ranks 1-3 and 4-6, rank sums 6 and 15, N = 6:
    # H = 12 / (N (N + 1)) (6²/3 + 15²/3) - 3 (N + 1) = 12/42 * 87 - 21 = 3.857142...; chi² with 1 degree of
    # freedom: p = erfc(sqrt(H / 2)) = 0.049535; pooled standard deviation 1 mm, groups of 3:
    # d(4 degrees of freedom) * 1 mm * sqrt(2/3), d = 3.761060 the noncentrality at which a two-sided t test at 5 %
    # with 4 degrees of freedom has power 0.8 (the normal approximation's 2.801585 claimed more)
    runs = [(1, 0, 1e-3, 0), (2, 0, 2e-3, 0), (3, 0, 3e-3, 0), (1, 0.04, 4e-3, 0), (2, 0.04, 5e-3, 0), (3, 0.04, 6e-3, 0)]
    data = StudyData(fabricateStudy(tmp_path / 's', runs=runs, missing=[]))
    t = effectTest(data)
    assert t['H'] == pytest.approx(12 / 42 * 87 - 21, rel=1e-12)
    assert t['p'] == pytest.approx(math.erfc(math.sqrt(t['H'] / 2)), rel=1e-9) and t['p'] == pytest.approx(0.049535, abs=1e-6)
    assert t['pooledStd [m]'] == pytest.approx(1e-3, rel=1e-12)
    assert t['detectableDifference [m]'] == pytest.approx(3.761060 * 1e-3 * math.sqrt(2 / 3), rel=1e-6)
    assert (t['groups'], t['runs'], t['smallestGroup']) == (2, 6, 3)
    # all the same: p = 1; one run per value: no test
    same = [(s, tc, 1e-3, 0) for s, tc, _, _ in runs]
    assert effectTest(StudyData(fabricateStudy(tmp_path / 'same', runs=same, missing=[])))['p'] == 1.0
    assert effectTest(StudyData(fabricateStudy(tmp_path / 'one', runs=runs[::3], missing=[]))) is None


def test_friedman_within_seeds_by_hand(tmp_path):
    # y = seed offset (0, 5, 10 mm) + Tc offset (0, 10, 20 mm) + residual +-1 mm with zero row and column sums:
    # every seed ranks the three values 1, 2, 3: rank sums 3, 6, 9, b = k = 3:
    # chi2 = 12 / (b k (k + 1)) (3² + 6² + 9²) - 3 b (k + 1) = 126/3 - 36 = 6; 2 degrees of freedom: p = exp(-3);
    # residual standard deviation sqrt(4 (1 mm)² / (2 * 2)) = 1 mm with (b - 1)(k - 1) = 4 degrees of freedom:
    # detectable d(4) 1 mm sqrt(2/3), d(4) = 3.761060
    e = {(1, 0): 1, (1, 0.01): -1, (2, 0): -1, (2, 0.01): 1}
    runs = [(s, tc, 1e-3 * (5 * (s - 1) + 10 * j + e.get((s, tc), 0)), 0) for s in (1, 2, 3) for j, tc in enumerate((0, 0.01, 0.04))]
    t = blockedTest(StudyData(fabricateStudy(tmp_path / 's', runs=runs, missing=[])))
    assert t['chi2'] == pytest.approx(6.0, rel=1e-12) and t['p'] == pytest.approx(math.exp(-3), rel=1e-9)
    assert t['residualStd [m]'] == pytest.approx(1e-3, rel=1e-9)
    assert t['detectableDifference [m]'] == pytest.approx(3.761060e-3 * math.sqrt(2 / 3), rel=1e-6)
    assert (t['seeds'], t['values']) == (3, 3)
    # Page's trend test: every seed rises, L = 1*3 + 2*6 + 3*9 = 42, the largest there is; exact p of a rise =
    # P(all three seeds in order) = (1/3!)^3 = 1/216, two-sided 2/216
    assert t['trend'] == 'rise' and t['pageL'] == 42 and t['pTrend'] == pytest.approx(2 / 216, rel=1e-9)
    fall = blockedTest(StudyData(fabricateStudy(tmp_path / 'fall', runs=[(s, tc, -d, c) for s, tc, d, c in runs], missing=[])))
    assert fall['trend'] == 'fall' and fall['pTrend'] == pytest.approx(2 / 216, rel=1e-9)
    # another quantity in its unit: the crushed grains are 0 everywhere, no evidence of any effect
    crushed = blockedTest(StudyData(fabricateStudy(tmp_path / 'q', runs=runs, missing=[])), 'nCrushed')
    assert crushed['quantity'] == 'nCrushed' and (crushed['chi2'], crushed['p'], crushed['residualStd [-]']) == (0.0, 1.0, 0.0)
    # a seed missing one value is not a block; with one complete seed left there is no test
    assert blockedTest(StudyData(fabricateStudy(tmp_path / 'gap', runs=runs[:-1], missing=[])))['seeds'] == 2
    assert blockedTest(StudyData(fabricateStudy(tmp_path / 'fig5', runs=RUNS, missing=MISSING))) is None
    # a value where no run has the quantity is left out (the others keep their test): deltaMax = 2 delta
    data = StudyData(fabricateStudy(tmp_path / 'part', runs=runs + [(s, 0.1, 0.5, 0) for s in (1, 2, 3)], missing=[]))
    for r in data.runs:
        if r.value == 0.1:
            del r.summary['deltaMax']
    part = blockedTest(data, 'deltaMax')
    assert part['valuesTested'] == [0.0, 0.01, 0.04] and part['seeds'] == 3 and part['chi2'] == pytest.approx(6.0, rel=1e-12)
    # two values only: Friedman needs three
    two = [r for r in runs if r[1] != 0.04]
    assert blockedTest(StudyData(fabricateStudy(tmp_path / 'two', runs=two, missing=[]))) is None


@pytest.mark.parametrize('n,sigmas', [(5, 2.0244), (2, 5.6535)])
def test_detectable_difference_by_the_t_distribution(n, sigmas):
    """The audit's numbers: two groups of n, 2n - 2 degrees of freedom, in standard deviations: 2.02 at n = 5
    and 5.65 at n = 2 (the normal approximation gave 1.77 and 2.80); and the power at it is 0.8."""
    from scipy import stats
    from ballast.analysis.effects import detectable
    dof = 2 * n - 2
    d = detectable(0.05, 0.8, dof)
    assert d * math.sqrt(2 / n) == pytest.approx(sigmas, abs=1e-4)
    tc = stats.t.ppf(0.975, dof)
    with np.errstate(all='ignore'):  # scipy's nct far in its tail
        assert stats.nct.sf(tc, dof, d) + stats.nct.cdf(-tc, dof, d) == pytest.approx(0.8, abs=1e-9)
