"""ballast.analysis.halfload and studies/halfload.py: the sweep read from a fabricated study folder
(hand-made summaries and per-check logs, values worked out by hand) and from a fabricated CSV of the
sweep before it was a study, the summary and the report of both, studies/halfload.table, and one
tiny real run of the sweep through scripts/study.py (5-9 grains, f = 100 Hz: a quarter period is
2.5 ms)."""
import csv
import json
import math
import os
import shutil
import subprocess
import sys

import numpy as np
import pytest

from ballast.analysis import halfload
from ballast.experiments import declaration
from ballast.experiments.oedometer.loadcurve import eq8

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
FMAX, TC = 1.5e6, 1e-4  # [N], [s] (the defaults)
STEP = 1e-4             # [s] the fabricated checks lie this far either side of t = 1/(4f)
ENV = dict(os.environ, PYTHONPATH=os.pathsep.join(p for p in sys.path if p), OMP_NUM_THREADS='1')


def writeRun(study, rows, seed, f, damping, checks, crushes=None, stopAt=0.25, Tc=TC, finished=True, **summary):
    """A run of a fabricated study folder: its row in `rows` (study.json), and if finished its
    summary.json (the parameters and the Final entries: Fapplied Fmax/2 + seed, F Fmax/2 - seed,
    delta 1e-4 f, unbalanced 1e-3 f, vRms 1e-3, 1000 loading steps among 1007, 1 s; `summary`
    replaces entries), checks.csv (rows (t, maxStressRatio), a grain crushed where `crushes` has a
    time) and crushes.csv."""
    runId = 'seed=%d,f=%g,damping=%g' % (seed, f, damping)
    rows.append({'line': len(rows) + 4, 'runId': runId,
                 'row': {'seed': str(seed), 'f': '%g' % f, 'damping': '%g' % damping, 'stopAt': '%g' % stopAt}})
    if not finished:
        return runId
    d = os.path.join(study, 'runs', runId)
    os.makedirs(d)
    s = {'params': {'seed': seed, 'f': f, 'damping': damping, 'stopAt': stopAt, 'Tc': Tc, 'Fmax': FMAX, 'Fmin': 0.0},
         'appliedFinal': FMAX / 2 + seed, 'forceFinal': FMAX / 2 - seed, 'deltaFinal': 1e-4 * f, 'unbalancedFinal': 1e-3 * f,
         'vRmsFinal': 1e-3, 'cpuSeconds': 1.0, 'steps': 1007, 'stepsByPhase': {'settle': 7, 'load': 1000}}
    s.update(summary)
    with open(os.path.join(d, 'summary.json'), 'w') as fh:
        json.dump(s, fh)
    crushes = crushes or []
    with open(os.path.join(d, 'checks.csv'), 'w') as fh:
        fh.write('t,iter,nCrushed,maxStressRatio,maxCrushableRatio\n')
        for k, (t, r) in enumerate(checks):
            fh.write('%r,%d,%d,%r,%r\n' % (t, 10 * k, sum(c == t for c in crushes), r, r))
    with open(os.path.join(d, 'crushes.csv'), 'w') as fh:
        fh.write('t,radius,ratio\n' + ''.join('%r,0.01,1.2\n' % t for t in crushes))
    return runId


def aroundHalf(f, below, above):
    """Checks at 1 ms, and STEP before and after t = 1/(4f) with the ratios below, above."""
    return [(1e-3, 0.01), (0.25 / f - STEP, below), (0.25 / f + STEP, above)]


def writeStudy(study, rows):
    with open(os.path.join(study, 'study.json'), 'w') as fh:
        json.dump({'experiment': 'oedometer', 'table': 'halfload.table', 'columns': ['seed', 'f', 'damping', 'stopAt'],
                   'rows': rows}, fh)
    return study


def fabricateStudy(study):
    """The sweep of fabricateCsv as a study folder: each ratio the mean of the two checks around Fmax/2
    (0.01 below and above it: eq. 8 is odd about t = 1/(4f), the two lie Fmax/2 sin(2 pi f STEP) either
    side of Fmax/2); seed 4's run at 8 Hz crushed a grain before the check after Fmax/2 (no ratio), and
    its run at 0.5 Hz, damping 0.6, did not finish."""
    rows = []
    for s, f, d, r in sweepRows():
        writeRun(study, rows, s, f, d, aroundHalf(f, r - 0.01, r + 0.01))
    writeRun(study, rows, 4, 8.0, 0.2, aroundHalf(8.0, 0.7, 0.9), crushes=[0.25 / 8.0 - STEP])
    writeRun(study, rows, 4, 0.5, 0.6, [], finished=False)
    return writeStudy(study, rows)


def sweepRows():
    # damping 0.2: seeds 1-3 rise along f = 0.5, 2, 8 Hz (every seed ranks them 1, 2, 3); seed 4 lacks 8 Hz
    rows = [(s, f, 0.2, 0.5 + 0.1 * s + 0.01 * k) for s in (1, 2, 3) for k, f in enumerate((0.5, 2.0, 8.0))]
    rows += [(4, 0.5, 0.2, 0.9), (4, 2.0, 0.2, 0.8)]
    # damping 0.6: seeds 1-3 flat along f (0.5 + 0.1 s): each rises 0.02 less than at damping 0.2
    return rows + [(s, f, 0.6, 0.5 + 0.1 * s) for s in (1, 2, 3) for f in (0.5, 2.0, 8.0)]


def fabricateCsv(path):
    """The CSV of the sweep before it was a study: the rows of sweepRows, Fapplied = F = Fmax/2, unbalanced 1e-3 f."""
    with open(path, 'w', newline='') as fh:
        w = csv.writer(fh)
        w.writerow(halfload.HEADER)
        for s, f, d, r in sweepRows():
            w.writerow([s, f, d, r, FMAX / 2, FMAX / 2, 1e-4, 1e-3 * f, 1e-3, 1000, 1.0])
    return path


def test_a_study_read_as_the_sweeps_table(tmp_path):
    runs = halfload.read(fabricateStudy(str(tmp_path)))
    assert list(runs.columns) == [c for c, _ in halfload.COLUMNS] and len(runs) == 21  # 21 finished of 22
    first = runs.iloc[0]
    # seed 1, 0.5 Hz, damping 0.2: (0.59 + 0.61) / 2; the summary's Final entries; the loading's steps, not all 1007
    assert first['stressRatioAtHalfLoad'] == pytest.approx(0.6, rel=1e-12)
    assert (first['seed'], first['f'], first['damping']) == (1, 0.5, 0.2)
    assert (first['Fapplied'], first['F'], first['delta'], first['unbalanced'], first['vRms']) == (
        FMAX / 2 + 1, FMAX / 2 - 1, 0.5e-4, 0.5e-3, 1e-3)
    assert (first['steps'], first['cpuSeconds']) == (1000, 1.0)
    crushed = runs[(runs['seed'] == 4) & (runs['f'] == 8.0)]
    assert len(crushed) == 1 and math.isnan(crushed['stressRatioAtHalfLoad'].iloc[0]) and crushed['F'].iloc[0] == FMAX / 2 - 4


def test_the_ratio_is_interpolated_in_the_applied_force(tmp_path):
    # checks 1e-4 s before and 3e-4 s after t = 1/(4f) at 2 Hz: eq. 8 is Fmax/2 (1 + sin(2 pi f x)) at x from there, so
    # Fmax/2 lies sin(θ) / (sin(θ) + sin(3θ)) = 1/4 (1 + θ^2 + ...) of the way, θ = 2 pi f 1e-4 = 1.26e-3
    rows = []
    writeRun(str(tmp_path), rows, 1, 2.0, 0.2, [(0.125 - 1e-4, 0.6), (0.125 + 3e-4, 0.64), (0.2, 0.9)])
    ratio = halfload.read(writeStudy(str(tmp_path), rows))['stressRatioAtHalfLoad'][0]
    assert ratio == pytest.approx(0.61, rel=1e-7) and ratio != pytest.approx(0.62, rel=1e-3)  # 1/4 of the way, not half


def test_runs_that_are_not_the_sweeps_are_refused(tmp_path):
    for k, (more, message) in enumerate([
            (dict(stopAt=0), r"run seed=1,f=8,damping=0.2: stopAt = 0, not the half-load sweep's 0\.25"),
            (dict(Tc=0.01), r'Tc = 0\.01 s checks too rarely at f = 8\.0 Hz.*Tc < 0\.00199 s'),
            (dict(vRmsFinal=None, appliedFinal=None), r'has no appliedFinal, vRmsFinal')]):
        study, rows = str(tmp_path / str(k)), []
        os.makedirs(study)
        summary = {key: v for key, v in more.items() if key.endswith('Final')}
        run = writeRun(study, rows, 1, 8.0, 0.2, aroundHalf(8.0, 0.5, 0.5), stopAt=more.get('stopAt', 0.25), Tc=more.get('Tc', TC))
        writeStudy(study, rows)
        if summary:  # a summary of an oedometer before the Final entries
            path = os.path.join(study, 'runs', run, 'summary.json')
            with open(path) as fh:
                s = json.load(fh)
            with open(path, 'w') as fh:
                json.dump({key: v for key, v in s.items() if key not in summary}, fh)
        with pytest.raises(ValueError, match=message):
            halfload.read(study)
    # every check, Tc = 0, is dense enough at any f
    halfload.checkRun({'stopAt': 0.25, 'Tc': 0.0, 'f': 1e3}, 'x')


def test_the_csv_written_from_a_study_reads_back_the_same(tmp_path):
    runs = halfload.read(fabricateStudy(str(tmp_path / 'study')))
    path = halfload.write(runs, str(tmp_path / 'runs.csv'))
    back = halfload.read(path)
    assert back.equals(runs)  # every bit, NaN where NaN
    with open(path) as fh:
        lines = fh.read().splitlines()
    assert lines[0] == ','.join(halfload.HEADER) and lines[1].startswith('1,0.5,0.2,') and lines[1].endswith(',1000,1.0')
    assert lines[-1].startswith('4,8.0,0.2,,')  # seed 4 at 8 Hz: no ratio, an empty cell


def test_the_committed_csv_reads_and_writes_back_byte_identical(tmp_path):
    committed = os.path.join(ROOT, 'docs', 'studies', 'halfload', 'runs.csv')
    runs = halfload.read(committed)
    assert len(runs) == 120
    with open(halfload.write(runs, str(tmp_path / 'runs.csv')), 'rb') as a, open(committed, 'rb') as b:
        assert a.read() == b.read()


@pytest.mark.parametrize('source', ['study', 'csv'])
def test_summary_by_hand(tmp_path, source):
    path = fabricateStudy(str(tmp_path)) if source == 'study' else fabricateCsv(str(tmp_path / 'runs.csv'))
    summary = halfload.summarize(halfload.read(path))
    s = summary[0.2]
    assert list(s['f']) == [0.5, 2.0, 8.0] and list(s['seeds']) == [1, 2, 3, 4]
    assert math.isnan(s['ratio'][3, 2]) and s['ratio'][3, 1] == pytest.approx(0.8, rel=1e-12)
    # means over the seeds that have the value: (0.6 + 0.7 + 0.8 + 0.9) / 4 at 0.5 Hz, (0.62 + 0.72 + 0.82) / 3 at 8 Hz
    assert s['ratioMean'] == pytest.approx([0.75, (0.61 + 0.71 + 0.81 + 0.8) / 4, 0.72], rel=1e-12)
    assert s['unbalancedMedian'] == pytest.approx([0.5e-3, 2e-3, 8e-3]) and s['vRmsMedian'] == pytest.approx([1e-3] * 3)
    # Page's test over the 3 complete seeds: L = 1*3 + 2*6 + 3*9 = 42, exact p of a rise (1/3!)^3 = 1/216, two-sided
    t = s['test']
    assert t['seeds'] == 3 and t['trend'] == 'rise' and t['pageL'] == 42 and t['pTrend'] == pytest.approx(2 / 216, rel=1e-9)
    # the rise at damping 0.2 minus at 0.6: 0.02 in each of 3 seeds; Wilcoxon's exact two-sided p = 2 (1/2)^3
    r = summary[0.6]['riseAgainstBase']
    assert (r['baseDamping'], r['seeds']) == (0.2, 3) and r['meanDifference'] == pytest.approx(0.02) and r['sem'] == pytest.approx(0, abs=1e-12)
    assert r['pWilcoxon'] == pytest.approx(0.25)
    assert 'riseAgainstBase' not in s
    assert halfload.tests(summary)['0.6']['riseAgainstBase'] == r and halfload.tests(summary)['0.2']['pTrend'] == t['pTrend']


def report(source, out):
    return subprocess.run([sys.executable, os.path.join(ROOT, 'studies', 'halfload.py'), 'report', source, '--out', out],
                          capture_output=True, text=True, env=ENV, timeout=120)


def test_report_command(tmp_path):
    for source in (fabricateStudy(str(tmp_path / 'study')), fabricateCsv(str(tmp_path / 'runs.csv'))):
        out = str(tmp_path / ('rep-' + os.path.basename(source)))
        r = report(source, out)
        assert r.returncode == 0, r.stderr
        with open(os.path.join(out, 'test.json')) as fh:
            t = json.load(fh)['0.2']
        assert t['pTrend'] == pytest.approx(2 / 216, rel=1e-9) and t['f'] == [0.5, 2.0, 8.0]
        assert os.path.getsize(os.path.join(out, 'halfload.png')) > 10000
        # the sweep's table is written from a study only (the CSV is its own)
        assert os.path.isfile(os.path.join(out, 'runs.csv')) == os.path.isdir(source)
    bad = report(str(tmp_path), str(tmp_path / 'x'))  # a folder without study.json
    assert bad.returncode == 2 and 'no study.json' in bad.stderr


def test_the_table_is_the_committed_sweep():
    from ballast.study import Table
    params = Table(os.path.join(ROOT, 'studies', 'halfload.table')).check(declaration('oedometer'))
    committed = halfload.read(os.path.join(ROOT, 'docs', 'studies', 'halfload', 'runs.csv'))
    assert sorted((p['seed'], p['f'], p['damping']) for p in params.values()) == sorted(
        zip(committed['seed'].astype(int), committed['f'], committed['damping']))
    for line, p in params.items():
        halfload.checkRun(p, line)  # stopped at Fmax/2, checked often enough there
        assert p['Tc'] == TC and p['Fmax'] == FMAX  # the defaults, as the committed sweep


@pytest.mark.skipif(shutil.which('yade') is None, reason='needs yade')
def test_a_real_run_of_the_sweep(tmp_path):
    # studies/ci.table's first row (5-9 grains, 100 Hz) at stopAt 0.25, strong grains: no crush before Fmax/2
    table = tmp_path / 'halfload.table'
    table.write_text('seed f diameter height Fmax vibTime depTime samples ft0 stopAt\n1 100 0.1 0.06 1.7e5 0 0.5 500 1e9 0.25\n')
    r = subprocess.run([sys.executable, os.path.join(ROOT, 'scripts', 'study.py'), 'run', str(table), '-j', '1', '--out',
                        str(tmp_path / 'study'), '--records', str(tmp_path / 'records'), '--packings', str(tmp_path / 'packings')],
                       capture_output=True, text=True, env=ENV, timeout=120)
    assert r.returncode == 0, r.stdout + r.stderr
    full, record = halfload.read(str(tmp_path / 'study')), halfload.read(str(tmp_path / 'records'))
    assert record.equals(full)  # the record keeps the two checks around Fmax/2
    run = full.iloc[0]
    # stopped a step past the check after t = 1/(4f), at most 1.5 Tc later
    assert 1.7e5 / 2 <= run['Fapplied'] <= eq8(1.7e5, 100, 0.25 / 100 + 1.5 * TC)
    assert 0 < run['stressRatioAtHalfLoad'] < 1e-2 and run['delta'] > 0 and run['steps'] > 0 and np.isfinite(run['unbalanced'])
