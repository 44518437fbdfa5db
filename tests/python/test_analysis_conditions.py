"""ballast.analysis.conditions and scripts/conditions.py: a study's realizations at chosen cycles, condition by
condition, worked out by hand on fabricated records (no YADE): totals with the jumped cycles' share, the mean,
smallest and largest over the seeds, BBI of the last grading by then, failures counted and not averaged; and
scripts/curve_fit.py and scripts/conditions.py run without YADE, as the docs run them."""
import json
import math
import os
import subprocess
import sys

import pandas as pd
import pytest

from ballast.analysis import conditions

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, '..', '..', 'scripts', 'conditions.py')


def records(root, runs, continues=None):
    """Records with one run per {runId: (seed, confining, [axialStrain per cycle], axialStrainJumped or None,
    failedInCycle or None, [(cycle, BBI)])}; continues: {runId: the state it continued from}."""
    rows = []
    for k, (rid, (seed, p, values, jumped, failed, bbi)) in enumerate(runs.items()):
        d = os.path.join(root, 'runs', rid)
        os.makedirs(d)
        summary = {'params': {'seed': seed, 'confining': p, 'continueFrom': (continues or {}).get(rid, '')}}
        if failed:
            summary.update(stoppedBy='failure', failedInCycle=failed)
        with open(os.path.join(d, 'summary.json'), 'w') as fh:
            json.dump(summary, fh)
        frame = pd.DataFrame({'cycle': range(1, len(values) + 1), 'settlement': 0.0, 'crushes': 0, 'abrasions': 0,
                              'axialStrain': values})
        if jumped is not None:
            frame['axialStrainJumped'] = jumped
        frame.to_csv(os.path.join(d, 'cycles.csv'), index=False)
        pd.DataFrame(bbi, columns=['cycle', 'BBI']).to_csv(os.path.join(d, 'grading.csv'), index=False)
        rows.append({'line': k + 2, 'runId': rid, 'row': {'seed': str(seed)}})
    with open(os.path.join(root, 'study.json'), 'w') as fh:
        json.dump({'experiment': 'triaxial', 'rows': rows}, fh)
    return str(root)


RUNS = {'a1': (1, 60e3, [0.01, 0.02, 0.03], None, None, [(0, 0.0), (2, 0.004)]),
        'a2': (2, 60e3, [0.02, 0.03, 0.05], [0.0, 0.0, 0.01], None, [(0, 0.0), (1, 0.002), (3, 0.008)]),
        'b1': (1, 10e3, [0.09], None, 2, [(0, 0.0), (1, 0.001)]),
        'b2': (2, 10e3, [0.05, 0.08, 0.12], None, None, [(0, 0.0)])}


def test_per_seed_and_per_condition_by_hand(tmp_path):
    root = records(tmp_path / 'p', RUNS)
    seeds = conditions.realizationTable([root], ['confining'], ['axialStrain'], [1, 3])
    a2 = seeds[seeds.runId == 'a2'].set_index('cycle')
    assert a2.axialStrain[3] == pytest.approx(0.06) and a2.BBI[3] == 0.008 and a2.BBI[1] == 0.002   # with its jump
    b1 = seeds[seeds.runId == 'b1'].set_index('cycle')
    assert b1.axialStrain[1] == 0.09 and math.isnan(b1.failedInCycle[1])
    assert math.isnan(b1.axialStrain[3]) and b1.failedInCycle[3] == 2   # failed before N: counted, not a value
    table = conditions.conditionTable(seeds, ['axialStrain']).set_index(['condition', 'cycle'])
    a = table.loc[('confining=60000', 3)]
    assert a.seeds == 2 and a.failed == 0
    assert a.axialStrain_mean == pytest.approx((0.03 + 0.06) / 2) and a.axialStrain_min == 0.03
    assert a.axialStrain_max == pytest.approx(0.06) and a.BBI_mean == pytest.approx((0.004 + 0.008) / 2)
    b = table.loc[('confining=10000', 3)]
    assert b.seeds == 1 and b.failed == 1 and b.failedInCycles == '2' and b.axialStrain_mean == 0.12
    text = conditions.markdown(table.reset_index(), ['axialStrain'])
    assert '| confining=60000 | 3 | 2 | 4.5 [3, 6] | 0.006 [0.004, 0.008] |  |' in text
    assert '| confining=10000 | 3 | 1 | 12 | 0 | 1 (in cycle 2) |' in text


def test_a_cycle_a_jump_went_over_is_read_on_the_jumps_log_law(tmp_path):
    """A jumping run's cycles.csv has no row for the cycles it jumped: cycle 5 between the simulated 3 and 10 is the
    straight line in ln N between their totals (by hand); a cycle past the last row is not reached."""
    root = tmp_path / 'j'
    records(root, {'j1': (1, 60e3, [0.01, 0.02, 0.03, 0.05, 0.06], [0, 0, 0, 0.01, 0.012], None, [(0, 0.0)])})
    c = pd.read_csv(root / 'runs' / 'j1' / 'cycles.csv')
    c['cycle'] = [1, 2, 3, 10, 11]
    c.to_csv(root / 'runs' / 'j1' / 'cycles.csv', index=False)
    seeds = conditions.realizationTable([str(root)], ['confining'], ['axialStrain'], [3, 5, 10, 12]).set_index('cycle')
    t3, t10 = 0.03, 0.05 + 0.01
    assert seeds.axialStrain[3] == pytest.approx(t3) and seeds.axialStrain[10] == pytest.approx(t10)
    assert seeds.axialStrain[5] == pytest.approx(t3 + (t10 - t3) * math.log(5 / 3) / math.log(10 / 3), rel=1e-12)
    assert 12 not in seeds.index


def test_a_realization_whose_slices_go_on_in_another_study_counts_once(tmp_path):
    """Seed 1's first slice in study 'first', its second (continued from the first's state, its cycles.csv holding
    every cycle) in study 'second'; seed 2 in 'first' only: one condition of two seeds, seed 1 read from its last
    slice. A run of the same name in a third study that nobody continued stays a realization of its own."""
    first = records(tmp_path / 'first', {'s1': (1, 60e3, [0.01, 0.02], None, None, [(0, 0.0)]),
                                         's2': (2, 60e3, [0.02, 0.03, 0.04, 0.05], None, None, [(0, 0.0)])})
    second = records(tmp_path / 'second', {'s1-more': (1, 60e3, [0.01, 0.02, 0.025, 0.03], None, None, [(0, 0.0)])},
                     continues={'s1-more': '../first/runs/s1/state-end.yade.gz'})
    seeds = conditions.realizationTable([first, second], ['confining'], ['axialStrain'], [2, 4])
    assert sorted(seeds.runId.unique()) == ['s1-more', 's2']   # s1 is the first slice of s1-more
    short = records(tmp_path / 'short', {'a2': (2, 60e3, [0.02, 0.03], None, None, [(0, 0.0)])})
    other = records(tmp_path / 'other', {'b1': (1, 10e3, [0.1, 0.2], None, None, [(0, 0.0)])})
    long = records(tmp_path / 'long', {'c1': (3, 60e3, [0.01, 0.02, 0.025, 0.03], None, None, [(0, 0.0)])})
    order = conditions.conditionTable(conditions.realizationTable([short, other, long], ['confining'], ['axialStrain'],
                                                                  [2, 4]), ['axialStrain'])
    # each condition's cycles together and in order, whichever study brought a cycle first
    assert list(zip(order.condition, order.cycle)) == [('confining=60000', 2), ('confining=60000', 4),
                                                        ('confining=10000', 2)]
    table = conditions.conditionTable(seeds, ['axialStrain']).set_index(['condition', 'cycle'])
    assert list(table.index) == [('confining=60000', 2), ('confining=60000', 4)]
    assert table.loc[('confining=60000', 4)].seeds == 2
    assert table.loc[('confining=60000', 4)].axialStrain_mean == pytest.approx((0.03 + 0.05) / 2)
    third = records(tmp_path / 'third', {'s1': (3, 60e3, [0.04, 0.06], None, None, [(0, 0.0)])})
    seeds = conditions.realizationTable([first, second, third], ['confining'], ['axialStrain'], [2])
    assert sorted(seeds.runId) == ['s1', 's1-more', 's2'] and sorted(seeds.seed) == [1, 2, 3]


def test_the_scripts_run_without_yade_and_refuse_a_missing_quantity(tmp_path):
    root = records(tmp_path / 'p', RUNS)
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(p for p in sys.path if 'yade' not in p))
    ok = subprocess.run([sys.executable, SCRIPT, root, '--by', 'confining', '--at', '1', '--out', str(tmp_path / 'o'),
                         '--quantities', 'axialStrain'], capture_output=True, text=True, env=env)
    assert ok.returncode == 0, ok.stderr
    assert len(pd.read_csv(tmp_path / 'o' / 'conditions.csv')) == 2
    bad = subprocess.run([sys.executable, SCRIPT, root, '--by', 'confining', '--out', str(tmp_path / 'o'),
                          '--quantities', 'volumetricStrain'], capture_output=True, text=True, env=env)
    assert bad.returncode == 2 and bad.stderr.count('\n') == 1 and 'wrote no volumetricStrain' in bad.stderr
    fit = subprocess.run([sys.executable, os.path.join(HERE, '..', '..', 'scripts', 'curve_fit.py'), root, '--curve',
                          'axialStrain=' + str(tmp_path / 'none.csv'), '--out', str(tmp_path / 'f')],
                         capture_output=True, text=True, env=env)
    assert fit.returncode == 2 and 'No module named' not in fit.stderr, fit.stderr


def test_a_measured_curve_stands_beside_its_quantity_read_in_log_n(tmp_path):
    """--curve: the measured value at each N beside the seeds' mean, read as curve_fit reads it: a monotone curve
    (its running median is itself) interpolated in log N, by hand at N = 3 between the points at 1 and 10; a curve of
    a quantity not asked for and a malformed curve are refused in one line."""
    root = records(tmp_path / 'p', RUNS)
    curve = tmp_path / 'axial.csv'
    curve.write_text('N,axial_strain\n1,0.01\n10,0.02\n100,0.04\n')
    table = conditions.conditionTable(conditions.realizationTable([root], ['confining'], ['axialStrain'], [1, 3]),
                                      ['axialStrain'])
    fitted = conditions.withMeasured(table, ['axialStrain'], {'axialStrain': str(curve)})
    at3 = fitted[(fitted.condition == 'confining=60000') & (fitted.cycle == 3)].iloc[0]
    assert at3.axialStrain_measured == pytest.approx(0.01 + 0.01 * math.log(3) / math.log(10), rel=1e-12)
    assert fitted[fitted.cycle == 1].axialStrain_measured.tolist() == [0.01, 0.01]
    late = conditions.withMeasured(table, ['axialStrain'], {'axialStrain': str(curve)})
    late.loc[late.cycle == 1, 'axialStrain_measured'] = math.nan   # a curve that starts after N = 1
    assert '| confining=60000 | 1 | 2 | 1.5 [1, 2] | - |' in conditions.markdown(late, ['axialStrain'])
    text = conditions.markdown(fitted, ['axialStrain'])
    assert '| axialStrain [%] | measured [%] | BBI |' in text
    row = '| confining=60000 | 3 | 2 | 4.5 [3, 6] | %.3g | 0.006 [0.004, 0.008] |  |' % (100 * at3.axialStrain_measured)
    assert row in text
    with pytest.raises(ValueError, match='volumetricStrain, not among the quantities'):
        conditions.withMeasured(table, ['axialStrain'], {'volumetricStrain': str(curve)})
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(p for p in sys.path if 'yade' not in p))
    bad = tmp_path / 'bad.csv'
    bad.write_text('N,axial_strain\n1,0.01\nten,0.02\n')
    r = subprocess.run([sys.executable, SCRIPT, root, '--by', 'confining', '--at', '1', '--quantities', 'axialStrain',
                        '--curve', 'axialStrain=%s' % bad, '--out', str(tmp_path / 'o')],
                       capture_output=True, text=True, env=env)
    assert r.returncode == 2 and r.stderr.count('\n') == 1 and 'line 3' in r.stderr, r.stderr
    r = subprocess.run([sys.executable, SCRIPT, root, '--by', 'confining', '--at', '1', '--quantities', 'axialStrain',
                        '--curve', 'axialStrain=%s' % curve, '--out', str(tmp_path / 'o')],
                       capture_output=True, text=True, env=env)
    assert r.returncode == 0 and 'measured [%]' in r.stdout, r.stderr
    assert pd.read_csv(tmp_path / 'o' / 'conditions.csv').axialStrain_measured.tolist() == [0.01, 0.01]
