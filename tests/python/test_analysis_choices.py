"""Tests of ballast.analysis.choices on fabricated onset studies (study.json, summary.json, checks.csv and
fd.csv written here, no yade): the strength that starts each criterion's crushing at the paper's
onset force, worked out by hand."""
import json
import os

import numpy as np
import pytest

from ballast.analysis.choices import onsetStrengths


def fabricate(d, slopes, crushed=0):
    """An onset study: per (seed, criterion) the largest stress ratio grows as slope * t over 1000
    checks in 0.1 s (run with ft0 = 1e9 Pa m), the applied force as 1e7 N/s * t."""
    rows = []
    for (seed, crit), slope in slopes.items():
        rid = 'seed=%d,criterion=%s' % (seed, crit)
        run = os.path.join(d, 'runs', rid)
        os.makedirs(run)
        t = np.linspace(0, 0.1, 1001)
        with open(os.path.join(run, 'checks.csv'), 'w') as fh:
            fh.write('t,iter,nCrushed,maxStressRatio\n')
            fh.writelines('%.9g,%d,0,%.9g\n' % (x, k, slope * x) for k, x in enumerate(t))
        with open(os.path.join(run, 'fd.csv'), 'w') as fh:
            fh.write('t,F,delta,nCrushed,nAbraded,Fapplied\n')
            fh.writelines('%.9g,0,0,0,0,%.9g\n' % (x, 1e7 * x) for x in t[::10])
        with open(os.path.join(run, 'summary.json'), 'w') as fh:
            json.dump({'params': {'seed': seed, 'criterion': crit, 'ft0': 1e9}, 'nCrushed': crushed}, fh)
        rows.append({'runId': rid, 'line': len(rows) + 2, 'row': {}})
    with open(os.path.join(d, 'study.json'), 'w') as fh:
        json.dump({'rows': rows, 'columns': ['seed', 'criterion']}, fh)
    return str(d)


def test_each_criterion_gets_the_strength_of_the_paper_onset(tmp_path):
    # seed 1: sigma_e r = 1e9 * 0.05 t / s... reaches ft0 = 3.1e6 at t = 3.1e6 / (1e9 * 0.05) = 0.062 s, F = 620 kN;
    # F/d^2 r grows at 0.6 of it there: 1.86e6; seed 2: sigma_e at 0.04 / s reaches it at 0.0775 s, F = 775 kN,
    # F/d^2 at 0.7 of it: 2.17e6. Mean 2.015e6, sample std |2.17 - 1.86|e6 / sqrt(2) = 2.192e5
    d = fabricate(tmp_path / 'onset', {(1, 'vonMises'): 0.05, (1, 'maxContactForce'): 0.03,
                                       (2, 'vonMises'): 0.04, (2, 'maxContactForce'): 0.028})
    res = onsetStrengths(d)
    s1, s2 = res['seeds'][1], res['seeds'][2]
    assert s1['onsetTime'] == pytest.approx(0.062, abs=1e-4) and s1['onsetForce'] == pytest.approx(6.2e5, rel=2e-3)
    assert s2['onsetTime'] == pytest.approx(0.0775, abs=1e-4) and s2['onsetForce'] == pytest.approx(7.75e5, rel=2e-3)
    # the check where the reference first reaches ft0 (a step of 1e-4 s: within 1e9 * 0.05 * 1e-4 = 5e3 Pa m)
    assert s1['vonMises'] == pytest.approx(3.1e6, abs=5e3) and s1['maxContactForce'] == pytest.approx(1.86e6, abs=3e3)
    assert s2['maxContactForce'] == pytest.approx(2.17e6, abs=3e3)
    assert res['mean']['maxContactForce'] == pytest.approx(2.015e6, abs=3e3)
    assert res['std']['maxContactForce'] == pytest.approx(0.31e6 / np.sqrt(2), abs=4e3)


def test_a_reference_that_never_reaches_its_strength_and_a_run_that_crushed(tmp_path):
    # sigma_e r reaches at most 1e9 * 0.01 * 0.1 = 1e6 < 3.1e6: no onset in the run, the seed is left out
    res = onsetStrengths(fabricate(tmp_path / 'a', {(1, 'vonMises'): 0.01, (1, 'majorPrincipal'): 0.02,
                                                     (2, 'vonMises'): 0.05, (2, 'majorPrincipal'): 0.06}))
    assert res['seeds'][1] == {'onsetForce': None}
    assert res['mean']['majorPrincipal'] == pytest.approx(3.1e6 * 1.2, abs=6e3) and np.isnan(res['std']['majorPrincipal'])
    with pytest.raises(ValueError, match='3 grains crushed; the onset study loads without crushing'):
        onsetStrengths(fabricate(tmp_path / 'b', {(1, 'vonMises'): 0.05}, crushed=3))


def test_each_comparison_run_is_named_by_the_one_option_it_changes():
    from ballast.analysis.choices import variant
    paper = {'keep': 'none', 'weibullModulus': 0.0, 'criterion': 'vonMises', 'ft0': 3.1e6}
    assert variant(paper) == (None, "paper's model")
    assert variant(dict(paper, keep='mass')) == ('keep', 'keep = mass')
    assert variant(dict(paper, weibullModulus=3.0)) == ('weibullModulus', 'Weibull k = 3')
    assert variant(dict(paper, criterion='maxContactForce', ft0=2.13e6)) == ('criterion', 'maxContactForce (ft0 = 2.13e+06 Pa m)')
    with pytest.raises(ValueError, match='one option of the paper at a time'):
        variant(dict(paper, keep='volume', weibullModulus=10.0))


def test_the_script_writes_the_comparison_and_its_figure(tmp_path):
    import csv
    import subprocess
    import sys
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    paper = {'keep': 'none', 'weibullModulus': 0.0, 'criterion': 'vonMises', 'ft0': 3.1e6}
    variants = [paper, dict(paper, keep='mass'), dict(paper, weibullModulus=3.0), dict(paper, criterion='majorPrincipal', ft0=3.58e6)]
    rows = []
    for seed in (1, 2):
        for k, p in enumerate(variants):
            rid = 'v%d,seed=%d' % (k, seed)
            run = tmp_path / 'study' / 'runs' / rid
            run.mkdir(parents=True)
            delta = 1e-3 * (10 * k + seed)  # [m] at the peak
            (run / 'summary.json').write_text(json.dumps({'params': dict(p, seed=seed), 'deltaAtAppliedPeak': delta,
                                                          'deltaMax': delta, 'nCrushed': k, 'Bg': 0.0, 'massLost': 0.0,
                                                          'cpuSeconds': 1.0}))
            (run / 'fd.csv').write_text('t,F,delta,nCrushed,nAbraded,Fapplied\n0,0,0,0,0,0\n0.06,1e6,%r,0,0,1.5e6\n' % delta)
            rows.append({'runId': rid, 'line': len(rows) + 2, 'row': {}})
    (tmp_path / 'study' / 'study.json').write_text(json.dumps({'rows': rows, 'columns': []}))
    script = os.path.join(root, 'studies', 'choices.py')
    p = subprocess.run([sys.executable, script, 'compare', str(tmp_path / 'study')], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    with open(tmp_path / 'study' / 'comparison.csv', newline='') as fh:
        got = list(csv.DictReader(fh))
    # the paper's runs first, then the options in the order of OPTIONS, seeds within
    assert [(r['option'], r['seed']) for r in got] == [('paper', '1'), ('paper', '2'), ('keep', '1'), ('keep', '2'),
                                                     ('weibullModulus', '1'), ('weibullModulus', '2'), ('criterion', '1'),
                                                     ('criterion', '2')]
    assert float(got[3]['deltaAtAppliedPeak_mm']) == pytest.approx(12.0)
    assert os.path.getsize(tmp_path / 'study' / 'choices.png') > 20000
    p = subprocess.run([sys.executable, script, 'compare', str(tmp_path)], capture_output=True, text=True)
    assert p.returncode == 2 and 'holds no study.json' in p.stderr
