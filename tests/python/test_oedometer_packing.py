"""ballast.oedometer.packing: the packing store (built once, then the same grains for every run of the seed).
The cloud of the shared sample builder is tested in test_sample.py."""
import json
import math
import os

import numpy as np
import pytest

pytest.importorskip('yade')
from ballast.experiments import grains  # noqa: E402
from ballast.oedometer import Oedometer  # noqa: E402

SMALL = dict(diameter=0.12, height=0.06, dMin=0.02, dMax=0.026, progress=60)


def test_store_builds_once_then_reuses(tmp_path):
    kw = dict(SMALL, results=str(tmp_path / 'r'), packingDir=str(tmp_path / 'packings'))
    first = Oedometer(**kw).prepare()
    assert not first.packing.reused and os.path.exists(first.packing.file)
    with open(first.packing.file) as fh:
        data = json.load(fh)
    assert data['key']['seed'] == 1 and data['key']['diameter'] == SMALL['diameter']
    stored = np.array(data['grains'], dtype=float)
    x, r, _ = grains.arrays()
    assert len(r) == len(stored) >= 5
    # in the cylinder, filled to about its height (the fill fraction is chosen for that)
    assert np.all(np.hypot(x[:, 0], x[:, 1]) + r <= first.cylinder.Rv + 1e-3)
    assert np.all(x[:, 2] - r >= -1e-3) and np.max(x[:, 2] + r) <= SMALL['height'] + SMALL['dMax']
    second = Oedometer(**dict(kw, f=3)).prepare()
    assert second.packing.reused and second.packing.file == first.packing.file
    x2, r2, _ = grains.arrays()
    np.testing.assert_array_equal(r2, r)  # the same grains; positions after the same settling
    np.testing.assert_array_equal(x2, x)


def test_paper_size_sample_is_dense(tmp_path):
    """Section 4's sample (300 x 150 mm cylinder, grains uniform in [20.5, 44.5] mm), seed 1: porosity under
    the plate seated on the highest grain at most 0.46 (issue 11; the loose deposition gave 0.524), the
    cylinder filled to about its height, grain sizes as asked."""
    run = Oedometer(results=str(tmp_path / 'r'), packingDir=str(tmp_path / 'packings'), progress=60).prepare()
    x, r, _ = grains.arrays()
    top = float(np.max(x[:, 2] + r))
    porosity = 1 - np.sum(4 / 3 * math.pi * r ** 3) / (math.pi * 0.15 ** 2 * top)
    assert porosity <= 0.46
    assert abs(top - 0.15) <= 0.0445 / 2  # within half a grain of the cylinder's height
    assert 0.0205 / 2 * (1 - 1e-9) <= r.min() and r.max() <= 0.0445 / 2 * (1 + 1e-9)
    assert np.all(np.hypot(x[:, 0], x[:, 1]) + r <= run.cylinder.Rv + 1e-3) and np.all(x[:, 2] - r >= -1e-3)
