"""Tests of ballast.experiments.oedometer.checkstats: what the per-check log and the crushes of a run say, worked out by
hand on fabricated runs (study_fakes.fabricateStudy with checks.csv and crushes.csv or events.csv), as
a study reads them (the oedometer's declaration merges them into every summary)."""
import math
import os

import pytest

from ballast.experiments.oedometer.checkstats import halfLoadRatio
from ballast.study.data import StudyData
from study_fakes import fabricateStudy


def test_applied_force_at_the_first_crush(tmp_path):
    # f = 2 Hz, Fmax = 1.5 MN: first crush at t = 1/12 s, eq. 8: Fmax/2 (sin(pi/3 - pi/2) + 1) = Fmax/2 (1 - sin(pi/6))
    # = 375 kN, whatever the order of the crushes in the file; a run without its loading parameters has none
    d = fabricateStudy(tmp_path / 's', more={'f': lambda i: 2.0, 'Fmax': lambda i: 1.5e6})
    runs = sorted(os.listdir(os.path.join(d, 'runs')))
    for run, crushes in zip(runs[:2], ('crushes', 'nCrushed')):   # the log of today; a record's of before 2026-12
        with open(os.path.join(d, 'runs', run, 'checks.csv'), 'w') as fh:
            fh.write('t,iter,%s,maxStressRatio\n0.1,10,2,1.2\n' % crushes)
        with open(os.path.join(d, 'runs', run, 'crushes.csv'), 'w') as fh:
            fh.write('t,radius,ratio\n0.2,0.02,1.1\n%r,0.02,1.2\n0.3,0.01,1.1\n' % (1 / 12))
    s = {r.runId: r.summary for r in StudyData(d, param='Tc').runs}
    assert s[runs[0]]['forceAtFirstCrush'] == pytest.approx(375e3, rel=1e-12)
    assert s[runs[0]]['crushesAfterPeak'] == 1  # the applied peak is at 1/(2f) = 0.25 s: the crush at 0.3 s
    for run in runs[:2]:   # one check crushed 2 grains, under either name of the column
        assert s[run]['crushingChecks'] == 1 and s[run]['crushesPerCrushingCheck'] == 2
    assert 'forceAtFirstCrush' not in s[runs[2]]  # no log
    bare = fabricateStudy(tmp_path / 'bare')
    run = sorted(os.listdir(os.path.join(bare, 'runs')))[0]
    with open(os.path.join(bare, 'runs', run, 'checks.csv'), 'w') as fh:
        fh.write('t,iter,nCrushed,maxStressRatio\n0.1,10,1,1.2\n')
    with open(os.path.join(bare, 'runs', run, 'crushes.csv'), 'w') as fh:
        fh.write('t,radius,ratio\n0.1,0.02,1.2\n')
    assert {r.runId: r.summary for r in StudyData(bare).runs}[run]['forceAtFirstCrush'] is None


def test_stress_ratio_at_half_the_peak_load(tmp_path):
    # eq. 8 at f = 2 Hz, Fmax = 1.5 MN passes 750 kN at t = 1/(4f) = 0.125 s; at 0.125 +- d it carries
    # 750 (1 +- sin(4 pi d)) kN. Checks at 0.121 and 0.128 s (712.3 and 778.3 kN, 66 kN apart: within
    # 5 % of Fmax) with ratios growing in proportion to the load, F/Fmax, give exactly 0.5 when
    # interpolated in force (0.500002 in time)
    F = lambda t: 750e3 * (1 - math.cos(4 * math.pi * t))
    log = {'t': [0.121, 0.128], 'maxStressRatio': [F(0.121) / 1.5e6, F(0.128) / 1.5e6]}
    assert halfLoadRatio(log, 1.5e6, 0.0, 2.0, math.inf) == pytest.approx(0.5, rel=1e-12)
    # 0.122 and 0.128 s lie symmetric about 0.125 s in force (721.7 and 778.3 kN): the mean of 0.4 and 0.8
    log = {'t': [0.05, 0.122, 0.128, 0.3], 'maxStressRatio': [0.1, 0.4, 0.8, 1.2]}
    assert halfLoadRatio(log, 1.5e6, 0.0, 2.0, 0.3) == pytest.approx(0.6, rel=1e-12)
    assert halfLoadRatio(log, 1.5e6, 0.0, 2.0, 0.128) == pytest.approx(0.6, rel=1e-12)  # crushed at the later check
    assert halfLoadRatio(log, 1.5e6, 2e5, 2.0, 0.3) == pytest.approx(0.6, rel=1e-12)  # Fmin only shapes the cycles after
    assert halfLoadRatio(log, 1.5e6, 0.0, 2.0, 0.122) is None  # a grain crushed before: no longer the intact network
    assert halfLoadRatio({'t': [0.125], 'maxStressRatio': [0.7]}, 1.5e6, 0.0, 2.0, math.inf) == 0.7  # a check at 0.125 s
    assert halfLoadRatio({'t': [0.2, 0.3], 'maxStressRatio': [0.7, 0.9]}, 1.5e6, 0.0, 2.0, math.inf) is None  # none before
    assert halfLoadRatio({'t': [0.05, 0.1], 'maxStressRatio': [0.1, 0.4]}, 1.5e6, 0.0, 2.0, math.inf) is None  # none after
    # checks at 0.1 and 0.15 s are 463 kN apart, 31 % of Fmax: too far to interpolate
    assert halfLoadRatio({'t': [0.1, 0.15], 'maxStressRatio': [0.4, 0.8]}, 1.5e6, 0.0, 2.0, math.inf) is None
    # through StudyData: a run's log and crushes give it; a run without its loading parameters has none
    d = fabricateStudy(tmp_path / 's', more={'f': lambda i: 2.0, 'Fmax': lambda i: 1.5e6})
    run = sorted(os.listdir(os.path.join(d, 'runs')))[0]
    with open(os.path.join(d, 'runs', run, 'checks.csv'), 'w') as fh:
        fh.write('t,iter,nCrushed,maxStressRatio\n0.122,10,0,0.4\n0.128,15,0,0.8\n0.3,30,1,1.2\n')
    with open(os.path.join(d, 'runs', run, 'crushes.csv'), 'w') as fh:
        fh.write('t,radius,ratio\n0.3,0.02,1.2\n')
    assert {r.runId: r.summary for r in StudyData(d, param='Tc').runs}[run]['stressRatioAtHalfLoad'] == \
        pytest.approx(0.6, rel=1e-12)
    bare = fabricateStudy(tmp_path / 'bare')
    run = sorted(os.listdir(os.path.join(bare, 'runs')))[0]
    with open(os.path.join(bare, 'runs', run, 'checks.csv'), 'w') as fh:
        fh.write('t,iter,nCrushed,maxStressRatio\n0.122,10,0,0.4\n0.128,15,0,0.8\n')
    assert {r.runId: r.summary for r in StudyData(bare).runs}[run]['stressRatioAtHalfLoad'] is None


def test_crushing_checks_from_the_per_check_log(tmp_path):
    # a run whose checks crushed 2 grains and 1 (and saw ratios up to 2.5 that include fragments below r_min):
    # 2 crushing checks, 1.5 grains each; its crushes (events.csv in a run, crushes.csv in a record) at
    # sigma/f_t = 1.3, 1.2 and 1.1: largest 1.3, mean 1.2; a run whose log has no crush: 0 checks
    d = fabricateStudy(tmp_path / 's')
    runs = sorted(os.listdir(os.path.join(d, 'runs')))
    with open(os.path.join(d, 'runs', runs[0], 'checks.csv'), 'w') as fh:
        fh.write('t,iter,nCrushed,maxStressRatio\n0.1,10,0,0.5\n0.2,20,2,2.5\n0.3,30,0,0.9\n0.4,40,1,1.1\n')
    with open(os.path.join(d, 'runs', runs[0], 'events.csv'), 'w') as fh:
        fh.write('kind,t,iter,id,x,y,z,radius,value,strength,newIds\ncrush,0.2,20,5,0,0,0,0.02,2.6e8,2e8,9\n'
                 'crush,0.2,20,6,0,0,0,0.01,4.8e8,4e8,10\nabrasion,0.3,30,7,0,0,0,0.01,9e11,3e11,\n'
                 'crush,0.4,40,8,0,0,0,0.01,4.4e8,4e8,11\n')
    with open(os.path.join(d, 'runs', runs[1], 'checks.csv'), 'w') as fh:
        fh.write('t,iter,nCrushed,maxStressRatio\n0.1,10,0,0.5\n')
    with open(os.path.join(d, 'runs', runs[2], 'checks.csv'), 'w') as fh:
        fh.write('t,iter,nCrushed,maxStressRatio\n0.1,10,1,3\n')
    with open(os.path.join(d, 'runs', runs[2], 'crushes.csv'), 'w') as fh:
        fh.write('t,radius,ratio\n0.1,0.02,1.05\n')
    data = StudyData(d)
    s = {r.runId: r.summary for r in data.runs}
    assert (s[runs[0]]['crushingChecks'], s[runs[0]]['crushesPerCrushingCheck']) == (2, 1.5)
    assert s[runs[0]]['ratioAtCrushMax'] == pytest.approx(1.3, rel=1e-12)
    assert s[runs[0]]['ratioAtCrushMean'] == pytest.approx(1.2, rel=1e-12)
    assert s[runs[1]]['crushingChecks'] == 0 and s[runs[1]]['ratioAtCrushMax'] is None
    assert s[runs[2]]['ratioAtCrushMax'] == s[runs[2]]['ratioAtCrushMean'] == 1.05
    assert 'crushingChecks' not in s[runs[3]]  # no log
