"""ballast.experiments.box.zones: where the grains broke, worked out by hand for a few points (no YADE)."""
import math

import numpy as np
import pytest

from ballast.experiments.box.zones import DEPTH_BANDS, localCharacter, table, zoneOf

GEOMETRY = {'boxLength': 0.7, 'boxWidth': 0.3, 'sleeperWidth': 0.25, 'dMax': 0.0445}


def test_each_point_falls_in_its_zone():
    # under (|x| <= 0.125), beside, at an end wall (|x| > 0.35 - 0.0445), at a side wall (|y| > 0.15 - 0.0445)
    x = [0.0, 0.125, 0.2, 0.31, -0.33, 0.0]
    y = [0.0, 0.1, 0.0, 0.0, 0.0, 0.11]
    assert list(zoneOf(x, y, **GEOMETRY)) == ['under', 'under', 'beside', 'wall', 'wall', 'wall']


def test_the_table_counts_every_crush_once_by_zone_and_depth_band():
    zBase = 0.3
    x = np.array([0.0, 0.05, 0.2, 0.0, 0.32])
    y = np.zeros(5)
    z = np.array([0.29, 0.05, 0.25, 0.0, 0.1])   # depths 0.01, 0.25, 0.05, 0.3 (the floor), 0.2
    t = table(x, y, z, zBase, GEOMETRY)
    band = zBase / DEPTH_BANDS
    assert t['bands'][0] == (0.0, pytest.approx(band)) and t['bands'][-1][1] == pytest.approx(zBase)
    assert t['under'] == [1, 0, 0, 0, 2] and t['beside'] == [1, 0, 0, 0, 0] and t['wall'] == [0, 0, 0, 1, 0]
    assert sum(map(sum, (t['under'], t['beside'], t['wall']))) == 5


def test_local_character_by_hand():
    x, y, z = np.array([0.0, 0.0, 0.2, 0.0]), np.zeros(4), np.array([0.28, 0.26, 0.2, 0.1])
    c = localCharacter(x, y, z, 0.3, 3, 300, GEOMETRY)
    assert c['crushedShare'] == pytest.approx(0.01) and c['underShare'] == pytest.approx(0.75)
    # depths 0.02, 0.04, 0.1, 0.2 m: median (0.04 + 0.1)/2, 90th percentile 0.1 + 0.7 (0.2 - 0.1) (linear, numpy's)
    assert c['depthMedian'] == pytest.approx(0.07) and c['depth90'] == pytest.approx(0.17)
    none = localCharacter([], [], [], 0.3, 0, 300, GEOMETRY)
    assert none['crushedShare'] == 0 and math.isnan(none['underShare']) and math.isnan(none['depth90'])
