"""ballast.analysis.settlement: the curves read from a study's records, the mean over runs and their laws
(ballast.settlementlaws, tested in test_settlementlaws.py) (no YADE)."""
import json
import math
import os

import numpy as np
import pytest

from ballast.analysis import settlement


def study(root, curves):
    """A records folder with one run per curve {runId: (seed, settlements)}."""
    rows = []
    for k, (rid, (seed, s)) in enumerate(curves.items()):
        d = os.path.join(root, 'runs', rid)
        os.makedirs(d)
        with open(os.path.join(d, 'summary.json'), 'w') as fh:
            json.dump({'settlement': s[-1], 'params': {'seed': seed}}, fh)
        with open(os.path.join(d, 'cycles.csv'), 'w') as fh:
            fh.write('cycle,settlement,resilient\n' + ''.join('%d,%r,1e-6\n' % (n + 1, v) for n, v in enumerate(s)))
        rows.append({'line': k + 2, 'runId': rid, 'row': {'seed': str(seed)}})
    with open(os.path.join(root, 'study.json'), 'w') as fh:
        json.dump({'experiment': 'box', 'rows': rows}, fh)
    return root


def test_the_mean_over_runs_and_its_law(tmp_path):
    N = np.arange(1, 11)
    a = list(1e-4 + 4e-5 * np.log(N))
    b = list(1e-4 + 6e-5 * np.log(N)) + [9e-4]   # one cycle more: the mean stops at the common 10
    root = study(str(tmp_path / 'box'), {'s1': (1, a), 's2': (2, b)})
    frame = settlement.curves([root])
    assert len(frame) == 21 and set(frame.seed) == {1, 2}
    f = settlement.summary(frame)[root]
    assert f['runs'] == 2 and f['cycles'] == 10 and f['settlementFirst'] == pytest.approx(1e-4)
    assert f['mean']['log']['b'] == pytest.approx(5e-5, rel=1e-9) and f['perRun']['s2']['log']['r2'] < 1
    assert f['perRun']['s1']['log']['b'] == pytest.approx(4e-5, rel=1e-9)
    assert os.path.isfile(settlement.figure(frame, {root: f}, str(tmp_path / 'settlement.png')))
    assert math.isfinite(f['settlementLast'])
    with pytest.raises(ValueError, match='no run with a cycles.csv'):
        settlement.curves([])
