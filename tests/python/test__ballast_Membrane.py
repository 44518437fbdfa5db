"""Tests of pkg/python/bind_Membrane.cpp: the membrane's load on a specimen's outer grains, by hand (the core's
geometry is tested in tests/cpp/test_Membrane.cpp)."""
import math

import numpy as np
import pytest

import ballast._ballast as B


def test_a_ray_through_a_grains_centre_meets_it_at_its_crown():
    # one grain r = 0.02 at 0.15 m on the centre ray of cell (theta = 0.5 dtheta, z = 0.305) of a 360 x 60 grid
    dth = 2 * math.pi / 360
    m = B.membraneLoad([[0.15 * math.cos(dth / 2), 0.15 * math.sin(dth / 2), 0.305]], [0.02], 6e4, 0.0, 0.0, 0.0, 0.6,
                       360, 60, 1.0)
    assert m['radius'].shape == (60, 360) and m['owner'].dtype == np.int64
    assert m['radius'][30, 0] == pytest.approx(0.17, rel=1e-14) and m['owner'][30, 0] == 0
    assert m['area'] == pytest.approx(np.sum(m['radius'][m['owner'] >= 0]) * dth * 0.01, rel=1e-12)
    assert m['force'][0, 2] == 0 and m['force'][0, 0] < 0   # towards the axis
    assert m['bridged'] == 0 and m['empty'] > 0


@pytest.mark.parametrize('kw, words', [
    (dict(radii=[0.0]), 'radii[0]'), (dict(pressure=-1.0), 'pressure'), (dict(z1=0.0), 'z1: expected above z0'),
    (dict(nTheta=2), 'nTheta'), (dict(nZ=0), 'nZ'), (dict(depth=-0.01), 'depth'),
    (dict(centres=[[0.1, 0.0]]), 'centres'), (dict(nTheta=2 ** 70), 'nTheta'), (dict(nZ=2.5), 'nZ'),
])
def test_bad_input_names_the_argument(kw, words):
    args = dict(centres=[[0.1, 0.0, 0.3]], radii=[0.02], pressure=6e4, axisX=0.0, axisY=0.0, z0=0.0, z1=0.6, nTheta=36,
                nZ=10, depth=0.005)
    args.update(kw)
    with pytest.raises((ValueError, TypeError), match=words.replace('[', r'\[')):
        B.membraneLoad(**args)
