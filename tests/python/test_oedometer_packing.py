"""ballast.oedometer.packing: the falling cloud (no overlaps, inside the cylinder, sizes as asked) and
the packing store (built once, then the same grains for every run of the seed)."""
import json
import math
import os

import numpy as np
import pytest

pytest.importorskip('yade')
from ballast.oedometer import Oedometer, StoredPacking, check  # noqa: E402

SMALL = dict(diameter=0.12, height=0.06, dMin=0.02, dMax=0.026, vibTime=0.05, progress=60)


def test_cloud_places_grains_apart_inside_the_cylinder():
    p = check(SMALL)
    Rin, n = p['diameter'] / 2, 40
    pos, r, h = StoredPacking().cloud(p, np.random.default_rng(3), n, Rin)
    assert len(r) == n and np.all(np.diff(r) <= 0)  # big first
    assert np.all((2 * r >= p['dMin']) & (2 * r <= p['dMax']))
    gap = 0.05 * p['dMin']
    d = np.linalg.norm(pos[:, None] - pos[None], axis=2)
    iu = np.triu_indices(n, 1)
    assert np.all(d[iu] > (r[:, None] + r[None])[iu] + gap * (1 - 1e-12))
    assert np.all(np.hypot(pos[:, 0], pos[:, 1]) + r <= Rin)
    assert np.all(pos[:, 2] - r >= gap * (1 - 1e-12)) and np.all(pos[:, 2] + r <= h + 1e-12)
    solid = np.sum(4 / 3 * math.pi * r ** 3) / (math.pi * Rin ** 2 * h)
    assert solid <= StoredPacking.CLOUD_SOLID * (1 + 1e-12)


def test_store_builds_once_then_reuses(tmp_path):
    kw = dict(SMALL, results=str(tmp_path / 'r'), packingDir=str(tmp_path / 'packings'))
    first = Oedometer(**kw).prepare()
    assert not first.packing.reused and os.path.exists(first.packing.file)
    with open(first.packing.file) as fh:
        data = json.load(fh)
    assert data['key']['seed'] == 1 and data['key']['diameter'] == SMALL['diameter']
    stored = np.array(data['grains'], dtype=float)
    x, r, _ = first.grainArrays()
    assert len(r) == len(stored) >= 5
    # in the cylinder; the excess above the rim was cut before vibrating, which lifts a grain by less
    # than the cylinder's displacement amplitude a / w^2
    p = first.p
    lift = p['vibAcc'] / (2 * math.pi * p['vibFreq']) ** 2
    assert np.all(np.hypot(x[:, 0], x[:, 1]) + r <= first.cylinder.Rv + 1e-3)
    assert np.all(x[:, 2] + r <= SMALL['height'] + lift) and np.all(x[:, 2] - r >= -1e-3)
    second = Oedometer(**dict(kw, f=3)).prepare()
    assert second.packing.reused and second.packing.file == first.packing.file
    x2, r2, _ = second.grainArrays()
    np.testing.assert_array_equal(r2, r)  # the same grains; positions after the same settling
    np.testing.assert_array_equal(x2, x)
