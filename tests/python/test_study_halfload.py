"""ballast.study.halfload and scripts/halfload.py: realizations loaded only to Fmax/2 on the reduced
sample of test_oedometer_experiment (about 20 grains, f = 20 Hz: a quarter period is 12.5 ms), and the
summary of a sweep by hand on a fabricated CSV."""
import csv
import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest

from ballast.oedometer.loadcurve import eq8
from ballast.params import ParamError
from ballast.study import halfload

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SMALL = dict(diameter=0.15, height=0.08, samples=1000, progress=60, strength=1e15)
F, FMAX, TC = 20.0, 1.5e6, 1e-4  # [Hz], [N], [s] (the default crushing period)
TOL_QUASI_STATIC = 0.05  # [-] of Fmax: the grains' force on the plate against the applied one (servo-free plate, slips)
TOL_SCALE = 1e-9         # [-] relative: sigma/f_t = sigma r / ft0 exactly, the trajectory is the same (no crush)
TOL_INTERPOLATION = 1e-3  # [-] relative: a chord over 0.6 % of Fmax against the step at Fmax/2


def test_plan_checks_every_run_first():
    runs = halfload.plan([1, 2], [0.5, 8.0], [0.2], Fmax=FMAX)
    assert [(p['seed'], p['f'], p['damping']) for p in runs] == [(1, 0.5, 0.2), (1, 8.0, 0.2), (2, 0.5, 0.2), (2, 8.0, 0.2)]
    with pytest.raises(ParamError, match=r"f.*-1"):
        halfload.plan([1], [8.0, -1.0], [0.2])
    with pytest.raises(ParamError, match=r"damping.*1\.5"):
        halfload.plan([1], [8.0], [0.2, 1.5])


@pytest.fixture(scope='module')
def sweep(tmp_path_factory):
    pytest.importorskip('yade')
    root = str(tmp_path_factory.mktemp('halfload'))
    path = os.path.join(root, 'runs.csv')
    common = dict(SMALL, results=os.path.join(root, 'results'), packingDir=os.path.join(root, 'packings'), Fmax=FMAX)
    runs = halfload.plan([1], [F], [0.2], ft0=1e9, **common) + halfload.plan([1], [F], [0.4], ft0=2e9, **common)
    n = halfload.sweep(path, runs, say=lambda s: None)
    return path, runs, n


def test_a_run_stops_just_past_half_the_peak_load(sweep):
    path, runs, n = sweep
    c = halfload.read(path)
    assert n == 2 and len(c['seed']) == 2
    # the loading ran past t = 1/(4f) to the check after it, at most 1.5 Tc later: eq. 8 between Fmax/2 and there
    assert np.all(c['Fapplied'] >= FMAX / 2) and np.all(c['Fapplied'] <= eq8(FMAX, F, 0.25 / F + 1.5 * TC + 1e-6))
    assert np.all(np.abs(c['F'] - c['Fapplied']) < TOL_QUASI_STATIC * FMAX)
    assert np.all(c['delta'] > 0) and np.all(c['steps'] > 0) and np.all(np.isfinite(c['unbalanced']))


def test_the_ratio_scales_as_one_over_ft0(sweep):
    # the two runs differ in ft0 (1e9, 2e9 Pa m) and damping (0.2, 0.4): damping changes the trajectory, so
    # compare with a run at damping 0.4 and ft0 1e9 (what sigma/f_t = sigma r / ft0 predicts: twice)
    path, runs, _ = sweep
    c = halfload.read(path)
    other = os.path.join(os.path.dirname(path), 'ft0.csv')
    halfload.sweep(other, [dict(runs[1], ft0=1e9)], say=lambda s: None)
    assert halfload.read(other)['stressRatioAtHalfLoad'][0] == pytest.approx(2 * c['stressRatioAtHalfLoad'][1], rel=TOL_SCALE)
    assert 0 < c['stressRatioAtHalfLoad'][0] < 1  # no crush before Fmax/2 at these strengths


def test_checks_every_step_give_the_same_ratio(sweep):
    # the crush check only reads stresses until a grain crushes: checked every step (Tc = 0) the run is the
    # same, and the ratio differs only by the interpolation across Tc = 1e-4 s (9 kN of eq. 8 at 20 Hz)
    path, runs, _ = sweep
    other = os.path.join(os.path.dirname(path), 'every-step.csv')
    halfload.sweep(other, [dict(runs[0], Tc=0)], say=lambda s: None)
    assert halfload.read(other)['stressRatioAtHalfLoad'][0] == pytest.approx(halfload.read(path)['stressRatioAtHalfLoad'][0],
                                                                             rel=TOL_INTERPOLATION)


def test_a_sweep_resumes_from_its_csv(sweep):
    path, runs, _ = sweep
    before = open(path).read()
    assert halfload.sweep(path, runs, say=lambda s: None) == 0 and open(path).read() == before


def test_rare_checks_are_refused_before_any_run():
    # eq. 8 rises by pi f Fmax Tc between two checks: 5 % of Fmax at f = 20 Hz takes Tc < 7.96e-4 s
    with pytest.raises(ValueError, match=r'Tc = 0\.01 s.*f = 20.*Tc < 0\.000796'):
        halfload.plan([1, 2], [F], [0.2], Tc=0.01, **SMALL)
    assert len(halfload.plan([1], [F], [0.2], Tc=7.9e-4, **SMALL)) == 1 and len(halfload.plan([1], [F], [0.2], Tc=0, **SMALL)) == 1


def fabricate(path):
    # damping 0.2: seeds 1-3 rise along f = 0.5, 2, 8 Hz (every seed ranks them 1, 2, 3); seed 4 lacks 8 Hz
    rows = [(s, f, 0.2, 0.5 + 0.1 * s + 0.01 * k) for s in (1, 2, 3) for k, f in enumerate((0.5, 2.0, 8.0))]
    rows += [(4, 0.5, 0.2, 0.9), (4, 2.0, 0.2, 0.8)]
    # damping 0.6: seeds 1-3 flat along f (0.5 + 0.1 s): each rises 0.02 less than at damping 0.2
    rows += [(s, f, 0.6, 0.5 + 0.1 * s) for s in (1, 2, 3) for f in (0.5, 2.0, 8.0)]
    with open(path, 'w', newline='') as fh:
        w = csv.writer(fh)
        w.writerow(halfload.HEADER)
        for s, f, d, r in rows:
            w.writerow([s, f, d, r, FMAX / 2, FMAX / 2, 1e-4, 1e-3 * f, 1e-3, 1000, 1.0])  # unbalanced 1e-3 f, vRms 1e-3
    return path


def test_summary_by_hand(tmp_path):
    s = halfload.summarize(fabricate(str(tmp_path / 'runs.csv')))[0.2]
    assert list(s['f']) == [0.5, 2.0, 8.0] and list(s['seeds']) == [1, 2, 3, 4]
    assert math.isnan(s['ratio'][3, 2]) and s['ratio'][3, 1] == 0.8
    # means over the seeds that have the value: (0.6 + 0.7 + 0.8 + 0.9) / 4 at 0.5 Hz, (0.62 + 0.72 + 0.82) / 3 at 8 Hz
    assert s['ratioMean'] == pytest.approx([0.75, (0.61 + 0.71 + 0.81 + 0.8) / 4, 0.72])
    assert s['unbalancedMedian'] == pytest.approx([0.5e-3, 2e-3, 8e-3]) and s['vRmsMedian'] == pytest.approx([1e-3] * 3)
    # Page's test over the 3 complete seeds: L = 1*3 + 2*6 + 3*9 = 42, exact p of a rise (1/3!)^3 = 1/216, two-sided
    t = s['test']
    assert t['seeds'] == 3 and t['trend'] == 'rise' and t['pageL'] == 42 and t['pTrend'] == pytest.approx(2 / 216, rel=1e-9)
    # the rise at damping 0.2 minus at 0.6: 0.02 in each of 3 seeds; Wilcoxon's exact two-sided p = 2 (1/2)^3
    r = halfload.summarize(fabricate(str(tmp_path / 'runs.csv')))[0.6]['riseAgainstBase']
    assert (r['baseDamping'], r['seeds']) == (0.2, 3) and r['meanDifference'] == pytest.approx(0.02) and r['sem'] == pytest.approx(0, abs=1e-12)
    assert r['pWilcoxon'] == pytest.approx(0.25)
    assert 'riseAgainstBase' not in s


def test_report_command(tmp_path):
    path = fabricate(str(tmp_path / 'runs.csv'))
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(p for p in sys.path if p))
    r = subprocess.run([sys.executable, os.path.join(ROOT, 'scripts', 'halfload.py'), 'report', path, '--out', str(tmp_path / 'rep')],
                       capture_output=True, text=True, env=env, timeout=120)
    assert r.returncode == 0, r.stderr
    with open(str(tmp_path / 'rep' / 'test.json')) as fh:
        t = json.load(fh)['0.2']
    assert t['pTrend'] == pytest.approx(2 / 216, rel=1e-9) and t['f'] == [0.5, 2.0, 8.0]
    assert os.path.getsize(str(tmp_path / 'rep' / 'halfload.png')) > 10000
    bad = subprocess.run([sys.executable, os.path.join(ROOT, 'scripts', 'halfload.py'), 'run', '--seeds', '1', '--f', 'fast',
                          '--csv', str(tmp_path / 'x.csv')], capture_output=True, text=True, env=env, timeout=120)
    assert bad.returncode == 2 and "argument --f" in bad.stderr and 'fast' in bad.stderr
