"""ballast.experiments.sample, the one sample builder: the cloud of grains in the container's shape, worked
out against its definition (sizes, place, volume, the lowest kept first), and the store read back as it was."""
import math
import os

import numpy as np
import pytest

pytest.importorskip('yade')
from ballast.experiments import sample  # noqa: E402
from ballast.geometry import sphereVolume  # noqa: E402

D_MIN, D_MAX = 0.0205, 0.0445   # [m] the paper's grains


@pytest.mark.parametrize('shape', [sample.CylinderShape(0.15), sample.BoxShape(0.7, 0.3)])
def test_a_cloud_holds_the_volume_asked_in_the_shape_lowest_first(shape):
    vSolid = 0.003   # [m^3]
    x, r, top = sample.cloud(shape, D_MIN, D_MAX, vSolid, seed=3, zBottom=0.1)
    rMax, gap = D_MAX / 2, 0.05 * D_MIN
    assert np.all((r >= D_MIN / 2 * (1 - 1e-9)) & (r <= D_MAX / 2 * (1 + 1e-9)))
    vol = np.cumsum(sphereVolume(r))
    assert vol[-1] >= vSolid > vol[-2]             # just enough grains: the last one reaches vSolid
    assert np.all(np.diff(x[:, 2]) >= 0)           # the lowest kept first
    assert x[:, 2].min() >= 0.1 + rMax + gap * (1 - 1e-9) and top == pytest.approx(np.max(x[:, 2] + r))
    if isinstance(shape, sample.CylinderShape):
        assert np.all(np.hypot(x[:, 0], x[:, 1]) < 0.15 - rMax - gap)
    else:
        assert np.all(np.abs(x[:, 0]) <= 0.35 - rMax - gap) and np.all(np.abs(x[:, 1]) <= 0.15 - rMax - gap)
    # no two grains overlap (makeCloud's promise, kept by the selection)
    d = np.linalg.norm(x[:, None, :] - x[None, :, :], axis=2) - (r[:, None] + r[None, :])
    assert np.all(d[~np.eye(len(r), dtype=bool)] >= -1e-12)
    # the same seed gives the same cloud, another seed another one
    again = sample.cloud(shape, D_MIN, D_MAX, vSolid, seed=3, zBottom=0.1)
    assert np.array_equal(again[0], x) and np.array_equal(again[1], r)
    assert not np.array_equal(sample.cloud(shape, D_MIN, D_MAX, vSolid, seed=4, zBottom=0.1)[1], r)


def test_more_than_the_cloud_can_hold_is_refused_naming_the_volumes():
    class Tiny(sample.BoxShape):
        def region(self, vSolid, rMax, gap, zBottom, grainVolume):
            lo, hi, h, num = sample.BoxShape.region(self, vSolid, rMax, gap, zBottom, grainVolume)
            return lo, hi, h, 3   # three grains cannot hold vSolid
    with pytest.raises(RuntimeError, match=r'cloud: 0.003 m\^3 of grains asked, .* placed'):
        sample.cloud(Tiny(0.7, 0.3), D_MIN, D_MAX, 0.003, seed=1)


class Phases:
    def __init__(self):
        self.steps, self.wall, self.said = {'deposit': 10}, {'deposit': 0.5}, []

    def say(self, msg):
        self.said.append(msg)


class Exp:
    runId = 'run'

    def __init__(self):
        self.phases = Phases()


def test_the_store_keeps_the_grains_to_the_bit_and_builds_once(tmp_path, monkeypatch):
    x = np.array([[0.1, 0.2, 0.3], [1 / 3, 2 / 7, 0.5]])
    r = np.array([0.011, 1 / 97])
    built = []

    def build():
        built.append(1)
        return {'top': 0.25}
    exp = Exp()
    monkeypatch.setattr(sample.grains, 'arrays', lambda: (x, r, np.ones(2)))   # the scene's grains
    path, doc, reused = sample.stored(exp, str(tmp_path / 'store'), {'seed': 1}, 'bed.json', True, build, 'bed')
    again = sample.stored(exp, str(tmp_path / 'store'), {'seed': 1}, 'bed.json', True, build, 'bed')
    assert built == [1] and not reused and again[2] and again[1] == doc
    assert doc['key'] == {'seed': 1} and doc['top'] == 0.25 and doc['steps'] == {'deposit': 10}
    g = np.array([[float(v) for v in row] for row in doc['grains']])
    assert np.array_equal(g[:, :3], x) and np.array_equal(g[:, 3], r)   # repr round-trips every bit
    assert exp.phases.said == ['bed: 2 grains saved to %s' % path, 'bed: reusing %s' % path]
    assert os.listdir(str(tmp_path / 'store')) == ['bed.json']         # written atomically: no temporary left
