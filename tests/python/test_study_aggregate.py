"""Tests of ballast.study.aggregate on fabricated study directories (study.json and summary.json
files written here, no yade): mean and sample standard deviation by hand, the studied parameter,
runs not finished, the axis of Fig. 5, the report. The figures are drawn by test_study.py."""
import csv
import json
import math
import os

import pytest

from ballast.study.aggregate import StudyData, aggregate, axisPositions, blockedTest, effectTest, halfLoadRatio, writeCsv
from ballast.study.options import StudyError

# (seed, Tc [s], delta at peak [m], crushed); seed 3 at Tc = 0.01 and seeds 2-3 at 0.04 did not finish
RUNS = [(1, 0, 0.050, 10), (2, 0, 0.056, 14), (3, 0, 0.047, 9), (1, 1e-4, 0.040, 7), (2, 1e-4, 0.031, 3), (3, 1e-4, 0.052, 12),
        (1, 0.01, 0.022, 2), (2, 0.01, 0.025, 4), (1, 0.04, 0.020, 1)]
MISSING = [(3, 0.01), (2, 0.04), (3, 0.04)]


def rid(seed, tc, **more):
    return ','.join('%s=%s' % kv for kv in [('seed', seed), ('Tc', tc)] + sorted(more.items()))


def fabricate(d, runs=RUNS, missing=MISSING, more=None, params=True, code=('a' * 40,)):
    """A study directory as Study.run leaves it: `more` adds columns (name -> value per run)."""
    os.makedirs(str(d), exist_ok=True)
    rows = []
    for i, (seed, tc) in enumerate([r[:2] for r in runs] + missing):
        extra = {k: str(v(i)) for k, v in (more or {}).items()}
        rows.append({'line': i + 2, 'runId': rid(seed, tc, **extra), 'row': dict({'seed': str(seed), 'Tc': str(tc)}, **extra)})
    for i, (seed, tc, delta, crushed) in enumerate(runs):
        run = os.path.join(d, 'runs', rows[i]['runId'])
        os.makedirs(run)
        s = {'deltaAtPeak': delta, 'deltaMax': 2 * delta, 'peakForce': 1.5e6, 'nCrushed': crushed, 'nAbraded': 0}
        if params:
            s['params'] = dict({'seed': seed, 'Tc': float(tc)}, **{k: float(v(i)) for k, v in (more or {}).items()})
        with open(os.path.join(run, 'summary.json'), 'w') as fh:
            json.dump(s, fh)
        with open(os.path.join(run, 'row.json'), 'w') as fh:
            json.dump({'codeSha1': code[i % len(code)]}, fh)
    with open(os.path.join(d, 'study.json'), 'w') as fh:
        json.dump({'table': 'Tc.table', 'columns': ['seed', 'Tc'] + list(more or {}), 'rows': rows}, fh)
    return str(d)


def byHand(xs):
    m = sum(xs) / len(xs)
    return m, math.sqrt(sum((x - m)**2 for x in xs) / (len(xs) - 1)) if len(xs) > 1 else None


def test_mean_and_sample_std_by_hand(tmp_path):
    data = StudyData(fabricate(tmp_path))
    assert data.param == 'Tc' and data.values == [0, 1e-4, 0.01, 0.04] and data.seeds == [1, 2, 3]
    assert sorted(data.missing) == sorted(rid(*m) for m in MISSING)
    for st in data.stats():
        mine = [r for r in RUNS if r[1] == st['value']]
        assert st['n'] == len(mine)
        m, s = byHand([r[2] for r in mine])
        assert st['deltaAtPeak_mean'] == pytest.approx(m, rel=1e-12)
        assert math.isnan(st['deltaAtPeak_std']) if s is None else st['deltaAtPeak_std'] == pytest.approx(s, rel=1e-12)
        assert st['nCrushed_mean'] == pytest.approx(byHand([r[3] for r in mine])[0])
        assert math.isnan(st['massLost_mean'])  # not in these summaries


def test_csv_tables(tmp_path):
    data = StudyData(fabricate(tmp_path / 's'))
    runsCsv, statsCsv = writeCsv(data, str(tmp_path))
    with open(statsCsv, newline='') as fh:
        rows = list(csv.DictReader(fh))
    assert [r['Tc'] for r in rows] == ['0', '0.0001', '0.01', '0.04'] and [r['n'] for r in rows] == ['3', '3', '2', '1']
    assert float(rows[2]['deltaAtPeak_mean [m]']) == pytest.approx(0.0235, rel=1e-12)
    assert float(rows[2]['deltaAtPeak_std [m]']) == pytest.approx(math.sqrt(2 * 0.0015**2), rel=1e-12)
    assert rows[3]['deltaAtPeak_std [m]'] == ''  # one run: no standard deviation
    with open(runsCsv, newline='') as fh:
        runs = list(csv.DictReader(fh))
    assert [r['line'] for r in runs] == [str(n) for n in range(2, 11)] and runs[0]['deltaAtPeak [m]'] == '0.05'


def test_the_studied_parameter(tmp_path):
    assert StudyData(fabricate(tmp_path / 'a', params=False)).values == [0, 1e-4, 0.01, 0.04]  # from the cells
    two = fabricate(tmp_path / 'b', more={'f': lambda i: i % 2 + 1})
    with pytest.raises(StudyError, match='--param: the table varies Tc, f; say which'):
        StudyData(two)
    assert StudyData(two, 'f').values == [1, 2]
    with pytest.raises(StudyError, match=r"--param: 'gamma' is not a column .*columns: seed, Tc, f"):
        StudyData(two, 'gamma')
    one = fabricate(tmp_path / 'c', runs=[r for r in RUNS if r[1] == 0], missing=[])
    with pytest.raises(StudyError, match='no column but the seed varies'):
        StudyData(one)
    with pytest.raises(StudyError, match='no finished run'):
        StudyData(fabricate(tmp_path / 'd', runs=[], missing=MISSING))
    with pytest.raises(StudyError, match=r'STUDY: .* \(no study.json\)'):
        StudyData(str(tmp_path))


def test_axis_of_fig5(tmp_path):
    data = StudyData(fabricate(tmp_path / 'a'))
    x, ticks, scale = axisPositions(data, 'auto')  # four decades with Tc = 0: log, 0 one step left
    assert scale == 'log' and ticks[0] == 'every step' and 0 < x[0] < x[1e-4] < x[0.01] < x[0.04]
    assert math.log(x[1e-4] / x[0]) == pytest.approx(math.log(0.04 / 1e-4) / 2)
    assert axisPositions(data, 'no')[2] == 'linear'
    data.numeric, data.values = False, [4, 'planar4']
    assert axisPositions(data, 'auto') == ({4: 0, 'planar4': 1}, ['4', 'planar4'], 'linear')


def test_report_names_missing_runs_and_code_versions(tmp_path, capsys):
    d = fabricate(tmp_path / 's', code=('a' * 40, 'b' * 40))
    aggregate(d, figures=False)
    said = capsys.readouterr().out
    assert 'studied parameter Tc (4 values), 3 realizations' in said and 'not finished (left out): 3' in said
    assert 'made by 2 versions of the code (sha1 aaaaaaaaaa, bbbbbbbbbb' in said
    assert os.path.exists(os.path.join(d, 'aggregate', 'stats.csv')) and not os.path.exists(os.path.join(d, 'aggregate', 'fd_curves.png'))
    (tmp_path / 'file').write_text('')
    with pytest.raises(StudyError, match='--out: .* not a directory'):
        aggregate(d, outDir=str(tmp_path / 'file'), figures=False)


def test_peak_is_the_applied_peak_when_every_run_has_it(tmp_path):
    """Runs of the plate load record delta at the peak of the applied force (t = T/2): Fig. 5 uses it; a
    study with a run that lacks it falls back to delta at the peak of the measured force."""
    d = fabricate(tmp_path / 'a')
    assert StudyData(d).peak == 'deltaAtPeak'
    applied = {}
    for r in RUNS:
        path = os.path.join(d, 'runs', rid(r[0], r[1]), 'summary.json')
        with open(path) as fh:
            s = json.load(fh)
        s['deltaAtAppliedPeak'] = applied[r[:2]] = 0.5 * r[2] + 0.001 * r[0]
        with open(path, 'w') as fh:
            json.dump(s, fh)
    data = StudyData(d)
    assert data.peak == 'deltaAtAppliedPeak'
    for st in data.stats():
        m, _ = byHand([v for k, v in applied.items() if k[1] == st['value']])
        assert st['deltaAtAppliedPeak_mean'] == pytest.approx(m, rel=1e-12)


def test_kruskal_wallis_and_the_detectable_difference_by_hand(tmp_path):
    # two values of Tc, displacements 1, 2, 3 mm and 4, 5, 6 mm: ranks 1-3 and 4-6, rank sums 6 and 15, N = 6:
    # H = 12 / (N (N + 1)) (6²/3 + 15²/3) - 3 (N + 1) = 12/42 * 87 - 21 = 3.857142...; chi² with 1 degree of
    # freedom: p = erfc(sqrt(H / 2)) = 0.049535; pooled standard deviation 1 mm, groups of 3:
    # (1.959964 + 0.841621) * 1 mm * sqrt(2/3) = 2.28747 mm
    runs = [(1, 0, 1e-3, 0), (2, 0, 2e-3, 0), (3, 0, 3e-3, 0), (1, 0.04, 4e-3, 0), (2, 0.04, 5e-3, 0), (3, 0.04, 6e-3, 0)]
    data = StudyData(fabricate(tmp_path / 's', runs=runs, missing=[]))
    t = effectTest(data)
    assert t['H'] == pytest.approx(12 / 42 * 87 - 21, rel=1e-12)
    assert t['p'] == pytest.approx(math.erfc(math.sqrt(t['H'] / 2)), rel=1e-9) and t['p'] == pytest.approx(0.049535, abs=1e-6)
    assert t['pooledStd [m]'] == pytest.approx(1e-3, rel=1e-12)
    assert t['detectableDifference [m]'] == pytest.approx(2.801585 * 1e-3 * math.sqrt(2 / 3), rel=1e-6)
    assert (t['groups'], t['runs'], t['smallestGroup']) == (2, 6, 3)
    # all the same: p = 1; one run per value: no test
    same = [(s, tc, 1e-3, 0) for s, tc, _, _ in runs]
    assert effectTest(StudyData(fabricate(tmp_path / 'same', runs=same, missing=[])))['p'] == 1.0
    assert effectTest(StudyData(fabricate(tmp_path / 'one', runs=runs[::3], missing=[]))) is None
    # aggregate writes it
    aggregate(str(tmp_path / 's'), outDir=str(tmp_path / 'agg'), figures=False)
    with open(str(tmp_path / 'agg' / 'test.json')) as fh:
        assert json.load(fh)['H'] == pytest.approx(t['H'])


def test_friedman_within_seeds_by_hand(tmp_path):
    # y = seed offset (0, 5, 10 mm) + Tc offset (0, 10, 20 mm) + residual +-1 mm with zero row and column sums:
    # every seed ranks the three values 1, 2, 3: rank sums 3, 6, 9, b = k = 3:
    # chi2 = 12 / (b k (k + 1)) (3² + 6² + 9²) - 3 b (k + 1) = 126/3 - 36 = 6; 2 degrees of freedom: p = exp(-3);
    # residual standard deviation sqrt(4 (1 mm)² / (2 * 2)) = 1 mm: detectable (1.959964 + 0.841621) 1 mm sqrt(2/3)
    e = {(1, 0): 1, (1, 0.01): -1, (2, 0): -1, (2, 0.01): 1}
    runs = [(s, tc, 1e-3 * (5 * (s - 1) + 10 * j + e.get((s, tc), 0)), 0) for s in (1, 2, 3) for j, tc in enumerate((0, 0.01, 0.04))]
    t = blockedTest(StudyData(fabricate(tmp_path / 's', runs=runs, missing=[])))
    assert t['chi2'] == pytest.approx(6.0, rel=1e-12) and t['p'] == pytest.approx(math.exp(-3), rel=1e-9)
    assert t['residualStd [m]'] == pytest.approx(1e-3, rel=1e-9)
    assert t['detectableDifference [m]'] == pytest.approx(2.801585e-3 * math.sqrt(2 / 3), rel=1e-6)
    assert (t['seeds'], t['values']) == (3, 3)
    # Page's trend test: every seed rises, L = 1*3 + 2*6 + 3*9 = 42, the largest there is; exact p of a rise =
    # P(all three seeds in order) = (1/3!)^3 = 1/216, two-sided 2/216
    assert t['trend'] == 'rise' and t['pageL'] == 42 and t['pTrend'] == pytest.approx(2 / 216, rel=1e-9)
    fall = blockedTest(StudyData(fabricate(tmp_path / 'fall', runs=[(s, tc, -d, c) for s, tc, d, c in runs], missing=[])))
    assert fall['trend'] == 'fall' and fall['pTrend'] == pytest.approx(2 / 216, rel=1e-9)
    # another quantity in its unit: the crushed grains are 0 everywhere, no evidence of any effect
    crushed = blockedTest(StudyData(fabricate(tmp_path / 'q', runs=runs, missing=[])), 'nCrushed', '-')
    assert crushed['quantity'] == 'nCrushed' and (crushed['chi2'], crushed['p'], crushed['residualStd [-]']) == (0.0, 1.0, 0.0)
    # a seed missing one value is not a block; with one complete seed left there is no test
    assert blockedTest(StudyData(fabricate(tmp_path / 'gap', runs=runs[:-1], missing=[])))['seeds'] == 2
    assert blockedTest(StudyData(fabricate(tmp_path / 'fig5', runs=RUNS, missing=MISSING))) is None
    # a value where no run has the quantity is left out (the others keep their test): deltaMax = 2 delta
    data = StudyData(fabricate(tmp_path / 'part', runs=runs + [(s, 0.1, 0.5, 0) for s in (1, 2, 3)], missing=[]))
    for r in data.runs:
        if r['value'] == 0.1:
            del r['summary']['deltaMax']
    part = blockedTest(data, 'deltaMax')
    assert part['valuesTested'] == [0.0, 0.01, 0.04] and part['seeds'] == 3 and part['chi2'] == pytest.approx(6.0, rel=1e-12)
    # two values only: Friedman needs three
    two = [r for r in runs if r[1] != 0.04]
    assert blockedTest(StudyData(fabricate(tmp_path / 'two', runs=two, missing=[]))) is None
    # aggregate writes it beside Kruskal-Wallis
    aggregate(str(tmp_path / 's'), outDir=str(tmp_path / 'agg'), figures=False)
    with open(str(tmp_path / 'agg' / 'test.json')) as fh:
        assert json.load(fh)['blocked']['chi2'] == pytest.approx(6.0)


def test_applied_force_at_the_first_crush(tmp_path):
    # f = 2 Hz, Fmax = 1.5 MN: first crush at t = 1/12 s, eq. 8: Fmax/2 (sin(pi/3 - pi/2) + 1) = Fmax/2 (1 - sin(pi/6))
    # = 375 kN, whatever the order of the crushes in the file; a run without its loading parameters has none
    d = fabricate(tmp_path / 's', more={'f': lambda i: 2.0, 'Fmax': lambda i: 1.5e6})
    runs = sorted(os.listdir(os.path.join(d, 'runs')))
    for run in runs[:2]:
        with open(os.path.join(d, 'runs', run, 'checks.csv'), 'w') as fh:
            fh.write('t,iter,nCrushed,maxStressRatio\n0.1,10,2,1.2\n')
        with open(os.path.join(d, 'runs', run, 'crushes.csv'), 'w') as fh:
            fh.write('t,radius,ratio\n0.2,0.02,1.1\n%r,0.02,1.2\n0.3,0.01,1.1\n' % (1 / 12))
    s = {r['runId']: r['summary'] for r in StudyData(d, param='Tc').runs}
    assert s[runs[0]]['forceAtFirstCrush'] == pytest.approx(375e3, rel=1e-12)
    assert s[runs[0]]['crushesAfterPeak'] == 1  # the applied peak is at 1/(2f) = 0.25 s: the crush at 0.3 s
    assert 'forceAtFirstCrush' not in s[runs[2]]  # no log
    bare = fabricate(tmp_path / 'bare')
    run = sorted(os.listdir(os.path.join(bare, 'runs')))[0]
    with open(os.path.join(bare, 'runs', run, 'checks.csv'), 'w') as fh:
        fh.write('t,iter,nCrushed,maxStressRatio\n0.1,10,1,1.2\n')
    with open(os.path.join(bare, 'runs', run, 'crushes.csv'), 'w') as fh:
        fh.write('t,radius,ratio\n0.1,0.02,1.2\n')
    assert {r['runId']: r['summary'] for r in StudyData(bare).runs}[run]['forceAtFirstCrush'] is None


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
    d = fabricate(tmp_path / 's', more={'f': lambda i: 2.0, 'Fmax': lambda i: 1.5e6})
    run = sorted(os.listdir(os.path.join(d, 'runs')))[0]
    with open(os.path.join(d, 'runs', run, 'checks.csv'), 'w') as fh:
        fh.write('t,iter,nCrushed,maxStressRatio\n0.122,10,0,0.4\n0.128,15,0,0.8\n0.3,30,1,1.2\n')
    with open(os.path.join(d, 'runs', run, 'crushes.csv'), 'w') as fh:
        fh.write('t,radius,ratio\n0.3,0.02,1.2\n')
    assert {r['runId']: r['summary'] for r in StudyData(d, param='Tc').runs}[run]['stressRatioAtHalfLoad'] == \
        pytest.approx(0.6, rel=1e-12)
    bare = fabricate(tmp_path / 'bare')
    run = sorted(os.listdir(os.path.join(bare, 'runs')))[0]
    with open(os.path.join(bare, 'runs', run, 'checks.csv'), 'w') as fh:
        fh.write('t,iter,nCrushed,maxStressRatio\n0.122,10,0,0.4\n0.128,15,0,0.8\n')
    assert {r['runId']: r['summary'] for r in StudyData(bare).runs}[run]['stressRatioAtHalfLoad'] is None


def test_runs_csv_carries_every_parameter_of_every_run(tmp_path):
    data = StudyData(fabricate(tmp_path / 's', more={'Fmax': lambda i: 1e6 + i}), 'Tc')
    runsCsv, _ = writeCsv(data, str(tmp_path))
    with open(runsCsv, newline='') as fh:
        runs = list(csv.DictReader(fh))
    assert [float(r['Fmax [N]']) for r in runs] == [1e6 + i for i in range(len(RUNS))]


def test_crushing_checks_from_the_per_check_log(tmp_path):
    # a run whose checks crushed 2 grains and 1 (and saw ratios up to 2.5 that include fragments below r_min):
    # 2 crushing checks, 1.5 grains each; its crushes (events.csv in a run, crushes.csv in a record) at
    # sigma/f_t = 1.3, 1.2 and 1.1: largest 1.3, mean 1.2; a run whose log has no crush: 0 checks
    d = fabricate(tmp_path / 's')
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
    s = {r['runId']: r['summary'] for r in data.runs}
    assert (s[runs[0]]['crushingChecks'], s[runs[0]]['crushesPerCrushingCheck']) == (2, 1.5)
    assert s[runs[0]]['ratioAtCrushMax'] == pytest.approx(1.3, rel=1e-12)
    assert s[runs[0]]['ratioAtCrushMean'] == pytest.approx(1.2, rel=1e-12)
    assert s[runs[1]]['crushingChecks'] == 0 and s[runs[1]]['ratioAtCrushMax'] is None
    assert s[runs[2]]['ratioAtCrushMax'] == s[runs[2]]['ratioAtCrushMean'] == 1.05
    assert 'crushingChecks' not in s[runs[3]]  # no log
