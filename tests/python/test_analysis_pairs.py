"""ballast.analysis.pairs: runs paired by seed, and a seed held twice refused (no YADE)."""
import pandas as pd
import pytest

from ballast.analysis.pairs import bySeed, common, keyed, oneRunPerSeed


def test_the_seeds_every_group_has_sorted():
    assert common({3: 'a', 1: 'b', 2: 'c'}, [2, 3, 7], pd.Series([0.1, 0.2], index=[3, 2])) == [2, 3]
    frame = pd.DataFrame({'x': [1, 2]}, index=[5, 1])
    assert common(frame, {1: 0, 5: 0, 6: 0}) == [1, 5]   # a frame by its index, not its columns
    assert common({1: 0}, {2: 0}) == [] and common() == []


def test_a_seed_held_twice_is_refused_naming_its_runs():
    runs = pd.DataFrame({'seed': [1, 2, 1], 'runId': ['a', 'b', 'c'], 'delta': [0.1, 0.2, 0.3]})
    with pytest.raises(ValueError, match=r'option holds 2 runs of seed 1 \(2 rows\): which to pair is ambiguous'):
        bySeed(runs, 'option')
    assert list(bySeed(runs[:2], 'option').delta) == [0.1, 0.2]
    # rows per cycle: one run a seed is many rows; two runs of seed 1 are refused by their run ids
    cycles = pd.DataFrame({'seed': [1, 1, 2, 1], 'cycle': [1, 2, 1, 1], 'runId': ['a', 'a', 'b', 'c']})
    assert oneRunPerSeed(cycles[:3], 'study', run='runId') is not None
    with pytest.raises(ValueError, match=r'study holds 2 runs of seed 1 \(a, c\)'):
        oneRunPerSeed(cycles, 'study', run='runId')
    # a key of several columns: seed 1 at 10 and at 20 cycles are two keys
    assert list(bySeed(pd.DataFrame({'seed': [1, 1], 'cycles': [10, 20], 'x': [0, 1]}), 'j', ['seed', 'cycles']).x) == [0, 1]


def test_keyed_pairs_refuse_a_key_twice():
    assert keyed([(1, 'a'), (2, 'b')], 'w') == {1: 'a', 2: 'b'}
    with pytest.raises(ValueError, match=r'onset holds 2 runs of seed 4 \(vonMises\)'):
        keyed([((4, 'vonMises'), 1), ((4, 'vonMises'), 2)], 'onset')
