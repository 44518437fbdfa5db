"""Tests of pkg/python/bind_ClumpSplit.cpp: how a crushed clump splits, by hand (the core is tested in
tests/cpp/test_ClumpSplit.cpp, the split in a YADE scene in test_grainkinds_clump_split.py)."""
import numpy as np
import pytest

import ballast._ballast as B

A, BB, R = 0.01, 0.02, 0.011
POS = [[A, BB, 0], [A, -BB, 0], [-A, BB, 0], [-A, -BB, 0]]


def test_uniaxial_tension_along_x_by_hand():
    # l = (T, 0, 0): one plane x = 0; members 0, 1 (x > 0) first; 0-2 and 1-3 are 2A = 0.02 < 2R apart
    out = B.clumpSplit(stress=np.diag([1e6, 0.0, 0.0]), centre=[0, 0, 0], memberPositions=POS, memberRadii=[R] * 4)
    assert out['nPieces'] == 2 and out['median'] is False
    assert out['piece'].dtype == np.int64 and out['piece'].tolist() == [0, 0, 1, 1]
    np.testing.assert_allclose(out['normals'], [[1.0, 0, 0]], atol=1e-14)
    assert out['pairs'].shape == (2, 2) and out['pairs'].tolist() == [[0, 2], [1, 3]]


def test_centre_shifts_the_plane():
    # the same tension with the centre at x = 1.5 A: every member has x < 1.5 A, all on one side, so the median
    # fallback halves them along n1 = x: the two at x = -A (members 2, 3) below the two at x = +A (0, 1)
    out = B.clumpSplit(np.diag([1e6, 0.0, 0.0]), [1.5 * A, 0, 0], POS, [R] * 4)
    assert out['median'] is True and out['nPieces'] == 2
    assert out['piece'].tolist() == [0, 0, 1, 1]   # pieces numbered by first member: {0, 1} then {2, 3}


@pytest.mark.parametrize('kw, words', [
    (dict(stress=np.eye(2)), 'stress'), (dict(stress=np.full((3, 3), np.nan)), 'stress'),
    (dict(centre=[0.0, 0.0]), 'centre'), (dict(memberPositions=np.zeros((0, 3)), memberRadii=[]), 'memberPositions'),
    (dict(memberRadii=[R, R, 0.0, R]), r'memberRadii\[2\]: expected a finite number > 0, got 0'),
    (dict(memberRadii=[R] * 3), 'memberRadii'), (dict(memberPositions='x'), 'memberPositions'),
])
def test_bad_input_names_the_argument(kw, words):
    args = dict(stress=np.eye(3), centre=[0.0, 0, 0], memberPositions=POS, memberRadii=[R] * 4)
    args.update(kw)
    with pytest.raises((ValueError, TypeError), match=words):
        B.clumpSplit(**args)
