"""ballast.analysis.curvefit and scripts/curve_fit.py: runs against a measured curve, the smoothing, the
interpolation in log N and the scores worked out by hand (no YADE)."""
import json
import math
import os
import subprocess
import sys

import numpy as np
import pandas as pd
import pytest

from ballast.analysis import curvefit

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, '..', '..', 'scripts', 'curve_fit.py')


def study(root, runs):
    """Records with one run per {runId: (seed, rollingFriction, [axialStrain per cycle])}."""
    rows = []
    for k, (rid, (seed, rf, values)) in enumerate(runs.items()):
        d = os.path.join(root, 'runs', rid)
        os.makedirs(d)
        with open(os.path.join(d, 'summary.json'), 'w') as fh:
            json.dump({'params': {'seed': seed, 'rollingFriction': rf, 'continueFrom': ''}}, fh)
        with open(os.path.join(d, 'cycles.csv'), 'w') as fh:
            fh.write('cycle,settlement,axialStrain\n' + ''.join(
                '%d,0.0,%r\n' % (n + 1, v) for n, v in enumerate(values)))
        rows.append({'line': k + 2, 'runId': rid, 'row': {'seed': str(seed)}})
    with open(os.path.join(root, 'study.json'), 'w') as fh:
        json.dump({'experiment': 'triaxial', 'rows': rows}, fh)
    return str(root)


def curveFile(tmp_path, text, name='axial.csv'):
    path = tmp_path / name
    path.write_text(text)
    return str(path)


def test_the_running_median_takes_out_a_digitised_outlier_and_keeps_the_ends():
    s = curvefit.smoothed([1, 2, 3, 4, 5], [0.1, 0.2, 0.9, 0.4, 0.5])
    assert s.tolist() == [0.1, 0.2, 0.4, 0.5, 0.5]
    assert curvefit.smoothed([1, 2], [0.3, 0.1]).tolist() == [0.3, 0.1]


def test_runs_scored_against_the_curve_by_hand(tmp_path):
    # measured: 0.01 at N = 1, 0.03 at N = 100 (a line in log N: 0.02 at N = 10); the median of three keeps a line
    path = curveFile(tmp_path, 'N,axial_strain\n1,0.01\n10,0.02\n100,0.03\n')
    root = study(tmp_path / 's', {'near': (1, 0.1, [0.011] + [0.0] * 8 + [0.018]),
                                  'far': (1, 0.3, [0.002] + [0.0] * 8 + [0.004])})
    frame = curvefit.table([root], {'axialStrain': path}, [1, 10], params=['rollingFriction'])
    near = frame[frame.runId == 'near'].set_index('cycle')
    assert near.measured[1] == pytest.approx(0.01) and near.measured[10] == pytest.approx(0.02)
    assert near.difference[1] == pytest.approx(0.001) and near.difference[10] == pytest.approx(-0.002)
    ranked = curvefit.scores(frame, ['rollingFriction'])
    assert ranked.runId.tolist() == ['near', 'far'] and ranked.rollingFriction.tolist() == [0.1, 0.3]
    assert ranked.rms[0] == pytest.approx(math.sqrt((0.001 ** 2 + 0.002 ** 2) / 2), rel=1e-12)
    assert ranked.bias_axialStrain[1] == pytest.approx((-0.008 - 0.016) / 2, rel=1e-12)
    # N = 1000 lies beyond the measured curve: not compared
    assert set(curvefit.table([root], {'axialStrain': path}, [1, 1000]).cycle) == {1}


def test_a_jumped_run_is_compared_with_its_extrapolated_strain(tmp_path):
    """With cycle jumping a run's strain at a cycle count is the simulated one plus its extrapolation over the
    jumped cycles (axialStrainJumped): a run at 0.015 simulated and 0.005 extrapolated at N = 100 is 0.02 there."""
    path = curveFile(tmp_path, 'N,axial_strain\n1,0.01\n10,0.02\n100,0.03\n')
    root = str(tmp_path / 's')
    d = os.path.join(root, 'runs', 'j')
    os.makedirs(d)
    with open(os.path.join(d, 'summary.json'), 'w') as fh:
        json.dump({'params': {'seed': 1, 'continueFrom': ''}}, fh)
    with open(os.path.join(d, 'cycles.csv'), 'w') as fh:
        fh.write('cycle,settlement,axialStrain,axialStrainJumped\n1,0,0.01,0\n100,0,0.015,0.005\n')
    with open(os.path.join(root, 'study.json'), 'w') as fh:
        json.dump({'experiment': 'triaxial', 'rows': [{'line': 2, 'runId': 'j', 'row': {'seed': '1'}}]}, fh)
    frame = curvefit.table([root], {'axialStrain': path}, [1, 100]).set_index('cycle')
    assert frame.simulated[100] == pytest.approx(0.02, rel=1e-12) and frame.difference[100] == pytest.approx(-0.01)
    assert frame.simulated[1] == pytest.approx(0.01, rel=1e-12)
    # records of before the column: the extrapolation made here by the same law, b ln(N / n) over the simulated rows
    c = pd.DataFrame({'cycle': [1, 2, 3, 4, 5, 20], 'jumped': [0, 0, 0, 0, 0, 14], 'crushes': 0, 'abrasions': 0,
                      'axialStrain': 0.01 + 0.002 * np.log(np.arange(1, 7))})
    assert curvefit.total(c, 'axialStrain')[-1] == pytest.approx(0.01 + 0.002 * math.log(6) + 0.002 * math.log(20 / 6),
                                                                 rel=1e-9)


def test_the_script_writes_its_files_and_refuses_what_it_cannot_read(tmp_path):
    path = curveFile(tmp_path, 'N,axial_strain\n1,0.01\n10,0.02\n100,0.03\n')
    root = study(tmp_path / 's', {'r1': (1, 0.1, list(np.linspace(0.01, 0.02, 10)))})
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    out = str(tmp_path / 'out')
    ok = subprocess.run(['/usr/bin/python3', SCRIPT, root, '--curve', 'axialStrain=' + path, '--at', '1', '10',
                         '--out', out], capture_output=True, text=True, env=env, timeout=120)
    assert ok.returncode == 0, ok.stderr
    assert pd.read_csv(os.path.join(out, 'scores.csv')).runId.tolist() == ['r1']
    assert os.path.getsize(os.path.join(out, 'fit.png')) > 10000
    bad = curveFile(tmp_path, 'N,axial_strain\n1,0.01\n10,x\n', 'bad.csv')
    no = subprocess.run(['/usr/bin/python3', SCRIPT, root, '--curve', 'axialStrain=' + bad, '--out', out],
                        capture_output=True, text=True, env=env, timeout=120)
    assert no.returncode == 2 and 'line 3' in no.stderr and len(no.stderr.splitlines()) == 1
    missing = subprocess.run(['/usr/bin/python3', SCRIPT, root, '--curve', 'volumetricStrain=' + path, '--out', out],
                             capture_output=True, text=True, env=env, timeout=120)
    assert missing.returncode == 2 and 'wrote no volumetricStrain' in missing.stderr
