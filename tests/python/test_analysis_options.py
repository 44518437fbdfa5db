"""ballast.analysis.options: an option's runs against the paper's settings paired by seed; the numbers
worked out by hand from four made-up pairs."""
import math

import pandas as pd
import pytest
from scipy import stats

from ballast.analysis import options


def runs(seeds, delta, crushed, cpu):
    return pd.DataFrame({'params.seed': seeds, 'deltaAtAppliedPeak': delta, 'nCrushed': crushed, 'cpuSeconds': cpu,
                         'stepsByPhase.load': [1000 * c for c in cpu]})


def test_paired_comparison_by_hand():
    opt = runs([1, 2, 3, 4, 9], [0.050, 0.001, 0.040, 0.0003, 0.07], [150, 3, 140, 0, 160], [60, 30, 50, 20, 70])
    ref = runs([4, 3, 2, 1], [0.0002, 0.004, 0.0008, 0.045], [0, 4, 2, 140], [40, 40, 60, 120])
    c = options.compare(opt, ref)
    assert c['n'] == 4 and c['seeds'] == [1, 2, 3, 4]           # seed 9 has no pair
    d = [0.005, 0.0002, 0.036, 0.0001]                           # option - reference, seeds 1-4
    mean = sum(d) / 4
    sd = math.sqrt(sum((x - mean) ** 2 for x in d) / 3)
    half = stats.t.ppf(0.975, 3) * sd / 2
    assert c['meanDifference'] == pytest.approx(mean, rel=1e-12)
    assert (c['meanDifferenceLow'], c['meanDifferenceHigh']) == pytest.approx((mean - half, mean + half), rel=1e-12)
    assert c['cohenDz'] == pytest.approx(mean / sd, rel=1e-12)
    assert c['option']['avalanching'] == 0.5 and c['reference']['avalanching'] == 0.25   # above 5 mm
    assert c['changedClass'] == [3]                             # 4 mm quiet, 40 mm avalanche
    assert c['option']['crushes'] == pytest.approx((150 + 3 + 140 + 0) / 4)
    assert c['cpuRatioMedian'] == pytest.approx(0.5)           # ratios 60/120, 30/60, 50/40, 20/40
    assert c['loadStepsRatioMedian'] == pytest.approx(0.5)
    assert c['pWilcoxon'] == pytest.approx(0.125)               # all four differences positive: 2 / 2^4
    assert 0 < c['pMannWhitney'] <= 1


def test_identical_runs_and_too_few_pairs():
    a = runs([1, 2, 3], [0.01, 0.02, 0.0001], [1, 2, 3], [1, 1, 1])
    c = options.compare(a, a)
    assert c['meanDifference'] == 0 and c['pWilcoxon'] == 1.0 and c['cpuRatioMedian'] == 1.0
    with pytest.raises(ValueError, match='1 seed.s. in both studies'):
        options.compare(runs([1], [0.1], [1], [1]), a)
    # two reference runs of seed 2: which is its pair is ambiguous (before: both taken, misaligned)
    with pytest.raises(ValueError, match='the reference holds 2 runs of seed 2'):
        options.compare(a, runs([1, 2, 2], [0.01, 0.02, 0.03], [1, 2, 3], [1, 1, 1]))


def test_runs_older_than_an_option_hold_the_papers_value():
    """Records made before timeStep / stopAt / densityStep existed count as the paper's settings."""
    f = pd.DataFrame({'params.seed': [1, 2, 3, 4], 'params.f': [4.0] * 4,
                      'params.timeStep': [None, 'pwave', 'stiffness', 'stiffness'],
                      'params.stopAt': [None, 0.0, 0.5, 0.0]})
    assert list(options.select(f, f=4.0, **options.PAPER)['params.seed']) == [1, 2]
    assert list(options.select(f, **options.OPTIONS['combined'])['params.seed']) == [3]
    assert list(options.select(f, **options.OPTIONS['stiffness'])['params.seed']) == [4]
    assert options.select(f, **options.OPTIONS['peak']).empty
    with pytest.raises(KeyError, match="no parameter 'Tc'"):
        options.select(f, Tc=6.25e-4)


def test_the_markdown_table_holds_the_numbers():
    opt = runs([1, 2, 3, 4], [0.050, 0.001, 0.040, 0.0003], [150, 3, 140, 0], [60, 30, 50, 20])
    ref = runs([1, 2, 3, 4], [0.045, 0.0008, 0.004, 0.0002], [140, 2, 4, 0], [120, 60, 40, 40])
    table = options.markdown({'peak': options.compare(opt, ref)})
    head, rule, row = table.splitlines()
    assert head.count('|') == rule.count('|') == row.count('|') == 12
    cells = [c.strip() for c in row.split('|')[1:-1]]
    assert cells[:3] == ['peak', '4', '22.8 (12.5)']          # means [mm]: 91.3 / 4, 49.99 / 4
    assert cells[3].startswith('+10.3 [')                     # (5 + 0.2 + 36 + 0.1) / 4 mm
    assert cells[7] == '50 % (25 %)' and cells[8] == '1 of 4'  # seed 3: 4 mm quiet, 40 mm avalanche
    assert cells[9:] == ['x0.50', 'x0.50']


def test_avalanche_shares_by_hand():
    """Option quiet on all five seeds, the reference avalanching on four: Fisher's two-sided p is the hypergeometric
    tail of the tables as extreme, (6 + 6) / C(10, 5) = 12 / 252; McNemar's, the four discordant pairs all one way,
    2 / 2^4. Equal shares give 1."""
    opt = runs([1, 2, 3, 4, 5], [0.0004, 0.0005, 0.0003, 0.0003, 0.0002], [3, 12, 2, 2, 0], [1] * 5)
    ref = runs([1, 2, 3, 4, 5], [0.057, 0.0003, 0.052, 0.035, 0.041], [209, 1, 219, 233, 214], [1] * 5)
    c = options.compare(opt, ref)
    assert c['option']['avalanching'] == 0 and c['reference']['avalanching'] == 0.8
    assert c['pFisherAvalanching'] == pytest.approx(12 / 252, rel=1e-12)
    assert c['pMcNemarAvalanching'] == pytest.approx(2 / 16, rel=1e-12)
    same = options.compare(ref, ref)
    assert same['pFisherAvalanching'] == 1.0 and same['pMcNemarAvalanching'] == 1.0
