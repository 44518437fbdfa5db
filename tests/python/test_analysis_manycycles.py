"""ballast.analysis.manycycles: the table and figure of several many-cycle runs, from runs written by
hand (no YADE)."""
import json
import os
import subprocess
import sys

import csv

import pytest

from ballast.analysis import manycycles

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def fakeRun(path, seed, fatigue, settlements, cpu):
    os.makedirs(path)
    rows = ['cycle,t,settlement,resilient,nCrushed,nAbraded,Bg,maxDamage']
    rows += ['%d,%g,%g,1e-5,0,0,%g,0' % (k + 1, 0.125 * (k + 1), s, 0.5 * k) for k, s in enumerate(settlements)]
    with open(os.path.join(path, 'cycles.csv'), 'w') as fh:
        fh.write('\n'.join(rows) + '\n')
    with open(os.path.join(path, 'psd.csv'), 'w') as fh:
        fh.write('sieve_mm,passing_before,passing_after\n50,100,100\n')
    s = {'nCrushed': 3, 'nFatigueCrushed': 2 if fatigue else 0, 'Bg': 1.5, 'cpuSeconds': cpu, 'big': list(range(1000)),
         'params': {'seed': seed, 'fatigue': fatigue, 'fatigueExponent': 30.0}}
    with open(os.path.join(path, 'summary.json'), 'w') as fh:
        json.dump(s, fh)
    return path


def test_table_by_hand(tmp_path):
    a = fakeRun(str(tmp_path / 'a'), 2, False, [2e-4, 2.5e-4, 2.6e-4, 2.7e-4], 160.0)
    b = fakeRun(str(tmp_path / 'b'), 3, True, [1e-4, 3e-4], 90.0)
    t = manycycles.table([a, b])
    assert [r['cycles'] for r in t] == [4, 2] and [r['fatigue'] for r in t] == [False, True]
    assert [r['cpuPerCycle'] for r in t] == [40.0, 45.0]               # 160 s / 4, 90 s / 2
    assert [r['settlementN_mm'] for r in t] == pytest.approx([0.27, 0.3], rel=1e-12)
    assert [r['nFatigueCrushed'] for r in t] == [0, 2]


def test_script_keeps_compact_records_and_draws(tmp_path):
    a = fakeRun(str(tmp_path / 'runs' / 'a'), 2, False, [2e-4, 2.5e-4], 80.0)
    out = tmp_path / 'docs'
    p = subprocess.run([sys.executable, os.path.join(ROOT, 'studies', 'cycles_figure.py'), a, '--out', str(out)],
                       capture_output=True, text=True, env=dict(os.environ))
    assert p.returncode == 0, p.stderr
    with open(out / 'a' / 'summary.json') as fh:
        kept = json.load(fh)
    assert 'big' not in kept and kept['params']['seed'] == 2 and kept['cpuSeconds'] == 80.0
    with open(out / 'runs.csv') as fh:
        assert [r['cycles'] for r in csv.DictReader(fh)] == ['2']
    assert os.path.getsize(out / 'cycles.png') > 10000
    assert sorted(os.listdir(out / 'a')) == ['cycles.csv', 'psd.csv', 'record.json', 'summary.json']
    # a folder without cycles.csv is refused before anything is written
    p = subprocess.run([sys.executable, os.path.join(ROOT, 'studies', 'cycles_figure.py'), str(tmp_path), '--out',
                        str(tmp_path / 'other')], capture_output=True, text=True)
    assert p.returncode == 2 and 'has no cycles.csv' in p.stderr and not (tmp_path / 'other').exists()
