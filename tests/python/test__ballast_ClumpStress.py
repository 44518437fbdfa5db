"""Tests of pkg/python/bind_ClumpStress.cpp: the Love-Weber stress of a clump from its members', by hand (the core is
tested in tests/cpp/test_ClumpStress.cpp, the clump kind in a YADE scene in test_grainkinds_clump.py)."""
import numpy as np
import pytest

import ballast._ballast as B


def test_two_members_of_one_clump_by_hand():
    # member 0 at (1, 0, 0) with sigma_0 V_0 = diag(1, 2, 3), F_0 = (0, 0, 2); member 1 at (-1, 0, 0), no stress,
    # F_1 = (0, 0, -2): a couple about y. sigma V = diag(1, 2, 3) + F_0 (x) (1, 0, 0) + F_1 (x) (-1, 0, 0), V = 2
    out = B.clumpStresses(memberStresses=[np.diag([1.0, 2.0, 3.0]) / 0.5, np.zeros((3, 3))], memberVolumes=[0.5, 0.7],
                          memberForces=[[0, 0, 2.0], [0, 0, -2.0]], memberPositions=[[1.0, 0, 0], [-1.0, 0, 0]],
                          clumpIndex=[0, 0], clumpCentres=[[0.0, 0, 0]], clumpVolumes=[2.0])
    want = np.diag([1.0, 2.0, 3.0])
    want[2, 0] = 2 * 1 + (-2) * (-1)   # f_z l_x of both members
    assert out.shape == (1, 3, 3)
    np.testing.assert_allclose(out[0], want / 2.0, rtol=1e-14, atol=1e-15)


def test_members_go_to_their_own_clump():
    out = B.clumpStresses(memberStresses=np.ones((2, 3, 3)), memberVolumes=[1.0, 3.0], memberForces=np.zeros((2, 3)),
                          memberPositions=np.zeros((2, 3)), clumpIndex=[1, 0], clumpCentres=np.zeros((2, 3)),
                          clumpVolumes=[3.0, 1.0])
    np.testing.assert_allclose(out, np.ones((2, 3, 3)), rtol=1e-14)   # each clump: its member's sigma V over its V


@pytest.mark.parametrize('kw, words', [
    (dict(memberVolumes=[0.0]), 'memberVolumes'), (dict(clumpVolumes=[-1.0]), 'clumpVolumes'),
    (dict(clumpIndex=[1]), 'clumpIndex'), (dict(clumpIndex=[-1]), 'clumpIndex'),
    (dict(memberForces=[[1.0, 2.0]]), 'memberForces'), (dict(memberStresses=np.ones((1, 3))), 'memberStresses'),
    (dict(memberPositions=[[np.nan, 0, 0]]), 'memberPositions'),
])
def test_bad_input_names_the_argument(kw, words):
    args = dict(memberStresses=np.ones((1, 3, 3)), memberVolumes=[1.0], memberForces=[[0, 0, 1.0]],
                memberPositions=[[0, 0, 0.1]], clumpIndex=[0], clumpCentres=[[0, 0, 0.0]], clumpVolumes=[1.0])
    args.update(kw)
    with pytest.raises((ValueError, TypeError), match=words):
        B.clumpStresses(**args)
