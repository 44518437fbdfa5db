"""Tests of ballast.analysis.mechanisms and studies/tc_mechanisms.py on fabricated studies (study.json and
summary.json written here, no yade): variants named from the parameters, means and trends by hand."""
import csv
import json
import os
import subprocess
import sys

import numpy as np
import pytest

from ballast.analysis.mechanisms import BASELINE, collect, table, trends, variantOf

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def fabricate(d, runs):
    """runs: [(params beyond the defaults, seed, Tc, delta [m], crushed)]."""
    rows = []
    for extra, seed, tc, delta, crushed in runs:
        rid = ','.join('%s=%s' % kv for kv in sorted(dict(extra, seed=seed, Tc=tc).items()))
        run = os.path.join(d, 'runs', rid)
        os.makedirs(run)
        with open(os.path.join(run, 'summary.json'), 'w') as fh:
            json.dump({'params': dict({'seed': seed, 'Tc': tc, 'f': 4.0, 'damping': 0.2, 'loadMode': 'plate', 'maxPerCheck': 0}, **extra),
                       'deltaAtAppliedPeak': delta, 'deltaAtPeak': delta, 'nCrushed': crushed}, fh)
        rows.append({'runId': rid, 'line': len(rows) + 2, 'row': {'seed': str(seed), 'Tc': str(tc)}})
    with open(os.path.join(d, 'study.json'), 'w') as fh:
        json.dump({'rows': rows, 'columns': ['seed', 'Tc']}, fh)
    return str(d)


def test_variants_are_named_from_their_parameters():
    base = {'maxPerCheck': 0, 'damping': 0.2, 'loadMode': 'plate'}
    assert variantOf(base) == BASELINE
    assert variantOf({}) == BASELINE  # a run without them has the oedometer's defaults (damping 0.2)
    assert variantOf(dict(base, maxPerCheck=1)) == 'sequential'
    assert variantOf(dict(base, damping=0.6)) == 'damped (0.6)'
    assert variantOf(dict(base, loadMode='servo', maxPerCheck=3)) == 'at most 3 per check + servo'


def test_means_and_trends_by_hand(tmp_path):
    # baseline: delta falls by 20 mm from every step to Tc = 0.01 in each of seeds 1, 2, 3 (60, 50, 40 mm -> 40,
    # 30, 20 mm); the sequential variant has seeds 1 and 2 only, +1 and -1 mm
    base = [({}, s, tc, d, 10) for s, ds in ((1, (0.060, 0.040)), (2, (0.050, 0.030)), (3, (0.040, 0.020)))
            for tc, d in zip((0.0, 0.01), ds)]
    seq = [({'maxPerCheck': 1}, 1, 0.0, 0.030, 5), ({'maxPerCheck': 1}, 1, 0.01, 0.031, 4),
           ({'maxPerCheck': 1}, 2, 0.0, 0.025, 4), ({'maxPerCheck': 1}, 2, 0.01, 0.024, 4)]
    rows = collect(fabricate(tmp_path / 'base', base), fabricate(tmp_path / 'var', seq))
    st = {(r['variant'], r['Tc']): r for r in table(rows)}
    assert st[(BASELINE, 0.0)]['delta_mean'] == pytest.approx(0.050) and st[(BASELINE, 0.0)]['delta_std'] == pytest.approx(0.010)
    assert st[(BASELINE, 0.0)]['delta_sem'] == pytest.approx(0.010 / 3 ** 0.5)
    assert st[('sequential', 0.01)]['n'] == 2 and st[('sequential', 0.01)]['delta_mean'] == pytest.approx(0.0275)
    tr = {t['variant']: t for t in trends(rows)}
    # on the seeds shared with the baseline (1, 2 for the variant; all three for the baseline itself)
    assert tr[BASELINE]['change'] == pytest.approx(-0.020) and tr[BASELINE]['n'] == 3 and tr[BASELINE]['sem'] == pytest.approx(0)
    assert tr[BASELINE]['effect'] == 0
    assert tr['sequential']['change'] == pytest.approx(0.0) and tr['sequential']['n'] == 2
    # differences +1 and -1 mm: standard deviation sqrt(2) mm, standard error sqrt(2)/sqrt(2) = 1 mm
    assert tr['sequential']['sem'] == pytest.approx(0.001)
    # the baseline falls by 20 mm on seeds 1 and 2 too: the variant removes the trend, effect +20 +- 1 mm
    assert tr['sequential']['baselineChange'] == pytest.approx(-0.020) and tr['sequential']['baselineSem'] == pytest.approx(0)
    assert tr['sequential']['effect'] == pytest.approx(0.020) and tr['sequential']['effectSem'] == pytest.approx(0.001)
    # the crushes of a run (a record's crushes.csv): 4 Hz, so the applied peak is at t = 0.125 s; 1 of 4
    # crushes after it, the largest ratio 2.5
    run = tmp_path / 'var' / 'runs' / 'Tc=0.01,maxPerCheck=1,seed=1'
    (run / 'crushes.csv').write_text('t,radius,ratio\n0.1,0.02,1.1\n0.11,0.02,2.5\n0.12,0.01,1.2\n0.13,0.01,1.0\n')
    (run / 'checks.csv').write_text('t,iter,nCrushed,maxStressRatio\n0.1,1,1,1.1\n0.11,2,1,9\n0.12,3,1,1.2\n0.13,4,1,1\n')
    rows = collect(str(tmp_path / 'base'), str(tmp_path / 'var'))
    st = {(r['variant'], r['Tc']): r for r in table(rows)}
    assert st[('sequential', 0.01)]['afterPeak_mean'] == pytest.approx(1 / 4)
    assert st[('sequential', 0.01)]['ratioAtCrushMax_mean'] == pytest.approx(2.5)
    assert np.isnan(st[(BASELINE, 0.0)]['afterPeak_mean'])  # no crushes recorded
    # the script writes the tables and the figure
    out = tmp_path / 'out'
    p = subprocess.run([sys.executable, os.path.join(ROOT, 'studies', 'tc_mechanisms.py'), str(tmp_path / 'base'), str(tmp_path / 'var'),
                        '--out', str(out)], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    with open(out / 'trends.csv', newline='') as fh:
        assert [r['variant'] for r in csv.DictReader(fh)] == [BASELINE, 'sequential']
    assert os.path.getsize(out / 'mechanisms.png') > 20000
    p = subprocess.run([sys.executable, os.path.join(ROOT, 'studies', 'tc_mechanisms.py'), str(tmp_path), '--out', str(out)],
                       capture_output=True, text=True)
    assert p.returncode == 2 and 'no study.json' in p.stderr
