"""ballast.analysis.agreement and scripts/agreement.py: the paired comparison of an option's runs with a reference's,
the verdicts worked out by hand (Student's t with 2 degrees of freedom has a closed form: F(t) = 1/2 + t / (2
sqrt(t^2 + 2)), its quantile t_q = (2q - 1) / sqrt(2q(1 - q))) (no YADE)."""
import json
import math
import os
import subprocess
import sys

import pytest

from ballast.analysis import agreement

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, '..', '..', 'scripts', 'agreement.py')


def study(root, runs, extra='tilt'):
    """Records with one run per {runId: (seed, [(settlement, tilt) per cycle], continueFrom runId or None[, other
    parameters])}."""
    rows = []
    for k, (rid, (seed, values, fromRun, *more)) in enumerate(runs.items()):
        d = os.path.join(root, 'runs', rid)
        os.makedirs(d)
        cont = '/x/runs/%s/state-end.yade.gz' % fromRun if fromRun else ''
        with open(os.path.join(d, 'summary.json'), 'w') as fh:
            json.dump({'params': dict({'seed': seed, 'continueFrom': cont}, **(more[0] if more else {}))}, fh)
        with open(os.path.join(d, 'cycles.csv'), 'w') as fh:
            fh.write('cycle,settlement,resilient,%s\n' % extra
                     + ''.join('%d,%r,1e-6,%r\n' % (n + 1, s, t) for n, (s, t) in enumerate(values)))
        rows.append({'line': k + 2, 'runId': rid, 'row': {'seed': str(seed)}})
    with open(os.path.join(root, 'study.json'), 'w') as fh:
        json.dump({'experiment': 'box', 'rows': rows}, fh)
    return str(root)


def test_bias_t_and_p_as_by_hand():
    # d = 1, 2, 3: mean 2, sd 1, t = 2 sqrt(3); p = 1 - t / sqrt(t^2 + 2) with 2 degrees of freedom
    out = agreement.test([1.0, 2.0, 3.0], [10.0, 20.0, 30.0])
    t = 2 * math.sqrt(3)
    assert out['t'] == pytest.approx(t, rel=1e-12)
    assert out['p'] == pytest.approx(1 - t / math.sqrt(t * t + 2), rel=1e-9)
    assert out['seedStd'] == pytest.approx(10.0, rel=1e-12)
    q = 0.95   # the 90 % interval: t_0.95 / sqrt(3)
    assert out['interval'] == pytest.approx((2 * q - 1) / math.sqrt(2 * q * (1 - q)) / math.sqrt(3), rel=1e-9)
    assert out['relativeDifference'] == pytest.approx(0.1, rel=1e-12)
    assert out['verdict'] == 'within the seed scatter'   # 2 + 1.686 < 10


def test_verdicts_turn_on_the_margin_and_the_bias():
    # the same differences against seeds that differ by less than the interval's reach: 2 + 1.686 > sd 3.0
    assert agreement.test([1.0, 2.0, 3.0], [10.0, 13.0, 16.0])['verdict'] == 'not shown either way'
    # against seeds that differ by 3.7 the interval lies inside
    assert agreement.test([1.0, 2.0, 3.0], [10.0, 13.7, 17.4])['verdict'] == 'within the seed scatter'
    # a steady shift of 5 +- 0.1: t = 5 / (0.1 / sqrt 3) = 86.6, p = 1.3e-4
    out = agreement.test([4.9, 5.0, 5.1], [10.0, 20.0, 30.0])
    assert out['p'] == pytest.approx(1 - out['t'] / math.sqrt(out['t'] ** 2 + 2), rel=1e-6)
    assert out['p'] < 0.05 and out['verdict'] == 'changed'
    # identical differences: zero is no bias, anything else a sure one
    assert agreement.test([0.0, 0.0], [1.0, 2.0])['verdict'] == 'within the seed scatter'
    assert agreement.test([0.5, 0.5], [1.0, 2.0])['verdict'] == 'changed'
    assert agreement.test([0.5], [1.0])['verdict'] is None


def test_pairs_by_seed_from_the_last_slice(tmp_path):
    ref = study(tmp_path / 'ref', {'r1-c1': (1, [(1.0, 0.1)], None),
                                   'r1-c2': (1, [(1.0, 0.1), (1.5, 0.2)], 'r1-c1'),
                                   'r2-c2': (2, [(2.0, 0.3), (2.5, 0.4)], None)})
    opt = study(tmp_path / 'opt', {'o1': (1, [(1.1, 0.1), (1.7, 0.3)], None),
                                   'o2': (2, [(2.1, 0.3), (2.9, 0.2)], None),
                                   'o3': (3, [(9.0, 9.0), (9.0, 9.0)], None)})   # no reference for seed 3
    frame = agreement.values([opt, ref], ['settlement', 'tilt'], [2])
    assert sorted(frame.runId) == ['o1', 'o2', 'o3', 'r1-c2', 'r2-c2']   # the slice r1-c1 read as r1-c2
    pairs, verdicts = agreement.compare(frame, opt, ref, ['settlement', 'tilt'], [2])
    s = pairs[pairs.quantity == 'settlement'].set_index('seed')
    assert list(s.index) == [1, 2]
    assert s.difference.to_list() == pytest.approx([0.2, 0.4], abs=1e-12)
    v = {x['quantity']: x for x in verdicts}
    assert v['settlement']['meanDifference'] == pytest.approx(0.3, abs=1e-12)
    assert v['tilt']['meanDifference'] == pytest.approx((0.1 - 0.2) / 2, abs=1e-12)
    with pytest.raises(ValueError, match='no nGrains'):
        agreement.values([opt], ['nGrains'], [1])
    with pytest.raises(ValueError, match='share no seed'):
        agreement.compare(frame, opt, ref, ['settlement'], [7])


def test_script_writes_its_files_and_refuses_bad_input(tmp_path):
    ref = study(tmp_path / 'ref', {'r%d' % s: (s, [(s, 0.0)], None) for s in (1, 2, 3)})
    opt = study(tmp_path / 'opt', {'o%d' % s: (s, [(s + 0.01 * s, 0.0)], None) for s in (1, 2, 3)})
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    out = tmp_path / 'out'
    r = subprocess.run([sys.executable, SCRIPT, opt, '--reference', ref, '--at', '1', '--out', str(out)],
                       capture_output=True, text=True, env=env)
    assert r.returncode == 0, r.stderr
    got = json.load(open(out / 'agreement.json'))['verdicts']
    assert [v['quantity'] for v in got] == ['settlement', 'resilient']
    assert got[0]['meanDifference'] == pytest.approx(0.02, rel=1e-9)
    assert 'settlement N=1' in r.stdout
    for bad, word in ((['--alpha', '0.7'], "argument --alpha: '0.7'"), (['--at', '0'], "argument --at: '0'")):
        r = subprocess.run([sys.executable, SCRIPT, opt, '--reference', ref, '--out', str(out)] + bad,
                           capture_output=True, text=True, env=env)
        assert r.returncode == 2 and word in r.stderr, r.stderr
    r = subprocess.run([sys.executable, SCRIPT, opt, '--reference', ref, '--quantities', 'work', '--out', str(out)],
                       capture_output=True, text=True, env=env)
    assert r.returncode == 2 and 'wrote no work in cycles.csv' in r.stderr


def test_one_study_split_by_a_parameter(tmp_path):
    """A table holding the option's rows and the reference's: PATH[NAME=VALUE] selects each (a number as written in a
    table, 1e-3, or as %g, 0.001); both sides must select by the same parameters."""
    both = study(tmp_path / 'both', {'true1': (1, [(1.0, 0.0)], None, {'quasiStatic': 0.0}),
                                     'true2': (2, [(2.0, 0.0)], None, {'quasiStatic': 0.0}),
                                     'qs1': (1, [(1.1, 0.0)], None, {'quasiStatic': 0.001}),
                                     'qs2': (2, [(2.3, 0.0)], None, {'quasiStatic': 0.001})})
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    out = tmp_path / 'out'
    r = subprocess.run([sys.executable, SCRIPT, both + '[quasiStatic=1e-3]', '--reference', both + '[quasiStatic=0]',
                        '--quantities', 'settlement', '--at', '1', '--out', str(out)], capture_output=True, text=True,
                       env=env)
    assert r.returncode == 0, r.stderr
    v = json.load(open(out / 'agreement.json'))['verdicts'][0]
    assert v['seeds'] == 2 and v['meanDifference'] == pytest.approx((0.1 + 0.3) / 2, abs=1e-12)
    assert agreement.selection(both + '[quasiStatic=0.001]')[1] == agreement.selection(both + '[quasiStatic=1e-3]')[1]
    for bad, word in (([both + '[quasiStatic=1e-3]', '--reference', both], 'different parameters'),
                      ([both + '[quasiStatic]', '--reference', both + '[quasiStatic=0]'], 'PATH[NAME=VALUE ...]'),
                      ([both + '[quasiStatic=0.01]', '--reference', both + '[quasiStatic=0]'], 'no run of')):
        r = subprocess.run([sys.executable, SCRIPT] + bad + ['--at', '1', '--out', str(out)], capture_output=True,
                           text=True, env=env)
        assert r.returncode == 2 and word in r.stderr, r.stderr
