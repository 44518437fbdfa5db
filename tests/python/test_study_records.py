"""Tests of ballast.study.records (the compact records a study keeps in the repository) and of the
study runner that goes on from them, with the stand-in for yade of study_fakes.py: no simulation."""
import csv
import json
import os

import numpy as np
import pytest

from ballast.experiments import Declaration, declaration
from ballast.study import LocalExecutor, Study, StudyData
from ballast.study.aggregate import stats
from ballast.study.options import StudyError
from ballast.study.records import MAX_FD_ROWS, hasRecord, keepRecord, recordPath, thinChecks, thinFd, writeRecord
from study_fakes import writeFakeYade

TABLE = 'seed! f!\n1 2\n1 4\n2 2\n'
IDS = ['seed=1,f=2', 'seed=1,f=4', 'seed=2,f=2']


def curve(n=100000):
    """One load cycle of eq. 8 (F = Fmax/2 (1 - cos 2 pi t)) on a sample that settles 60 mm in one jump at
    t = 0.4 (one crushed grain per 100 rows during the jump) and saws its measured force after it."""
    t = np.linspace(0, 1, n)
    Fa = 1.5e6 / 2 * (1 - np.cos(2 * np.pi * t))
    delta = 1e-4 * t + 0.06 * np.clip((t - 0.4) / 0.01, 0, 1)
    F = Fa * (1 + 0.3 * np.sin(2 * np.pi * 300 * t) * (t > 0.4))
    crushed = np.where(t > 0.4, np.minimum((t - 0.4) * n / 100, 10).astype(int), 0)
    return {'t': t, 'F': F, 'delta': delta, 'nCrushed': crushed, 'nAbraded': 0 * t, 'Fapplied': Fa}


def test_a_thinned_curve_keeps_every_step_of_its_quantities_within_its_resolution():
    c = curve()
    kept = thinFd(c)
    assert len(kept) <= MAX_FD_ROWS and kept[0] == 0 and kept[-1] == len(c['t']) - 1
    assert np.all(np.diff(kept) > 0)
    for q in ('delta', 'Fapplied', 'F'):
        assert np.argmax(c[q]) in kept and np.argmin(c[q]) in kept
    # every start of a crush is kept: the jump's steps are in the record
    starts = np.flatnonzero(np.diff(c['nCrushed']) != 0) + 1
    assert set(starts) <= set(kept)
    # between two kept rows a quantity stays within one step of its value at the first: the record drawn
    # as steps is off by less than a hundredth of each range (the step is 1/200 of it, doubled at most
    # once here: 2 quantities of ~200-400 levels each)
    prev = kept[np.searchsorted(kept, np.arange(len(c['t'])), side='right') - 1]
    for q in ('delta', 'Fapplied'):
        err = np.max(np.abs(c[q] - c[q][prev])) / np.ptp(c[q])
        assert err < 1 / 100, (q, err)
    # a short curve is kept whole
    short = {k: v[:MAX_FD_ROWS] for k, v in c.items()}
    assert np.array_equal(thinFd(short), np.arange(MAX_FD_ROWS))


def writeRun(d, n=20000):
    """A finished run as the oedometer leaves it: summary.json, row.json, fd.csv, checks.csv (checks 3
    and 7 of 10 crushed grains), psd.csv."""
    os.makedirs(d)
    c = curve(n)
    with open(os.path.join(d, 'fd.csv'), 'w') as fh:
        fh.write('t,F,delta,nCrushed,nAbraded,Fapplied\n')
        for k in range(n):
            fh.write('%.9g,%.9g,%.9g,%d,%d,%.9g\n' % tuple(c[q][k] for q in ('t', 'F', 'delta', 'nCrushed', 'nAbraded', 'Fapplied')))
    with open(os.path.join(d, 'checks.csv'), 'w') as fh:  # 1000 checks, the ratio a sine, crushes at 300 and 700
        fh.write('t,iter,crushes,maxStressRatio\n')
        for k in range(1000):
            fh.write('%g,%d,%d,%.9g\n' % (1e-3 * k, 100 * k, {300: 2, 700: 1}.get(k, 0), 0.8 + 0.6 * np.sin(np.pi * k / 1000)))
    for name, data in (('summary.json', {'params': {'seed': 1, 'f': 2.0}, 'deltaAtPeak': 0.06}), ('row.json', {'row': {'seed': 1}})):
        with open(os.path.join(d, name), 'w') as fh:
            json.dump(data, fh)
    with open(os.path.join(d, 'psd.csv'), 'w') as fh:
        fh.write('size,before,after\n0.0315,0,1\n')
    with open(os.path.join(d, 'events.csv'), 'w') as fh:  # the 3 crushes (value / strength 1.3, 1.25, 1.1) and an abrasion
        fh.write('kind,t,iter,id,x,y,z,radius,value,strength,newIds\n'
                 'crush,0.3,30000,5,0,0,0,0.02,2.6e8,2e8,9 10\ncrush,0.3,30000,6,0,0,0,0.01,5e8,4e8,11 12\n'
                 'abrasion,0.5,50000,7,0,0,0,0.01,3e11,2e11,\ncrush,0.7,70000,8,0,0,0,0.0125,3.52e8,3.2e8,13 14\n')
    return c


def test_a_record_is_small_and_keeps_what_the_figures_and_tables_need(tmp_path):
    run = str(tmp_path / 'run')
    c = writeRun(run)
    dest = keepRecord(run, str(tmp_path / 'rec'), 'seed=1,f=2')
    assert dest == recordPath(str(tmp_path / 'rec'), 'seed=1,f=2') and hasRecord(str(tmp_path / 'rec'), 'seed=1,f=2')
    for name in ('summary.json', 'row.json', 'psd.csv'):
        assert open(os.path.join(dest, name)).read() == open(os.path.join(run, name)).read()
    size = sum(os.path.getsize(os.path.join(dest, f)) for f in os.listdir(dest))
    assert size < 60e3 < os.path.getsize(os.path.join(run, 'fd.csv'))
    with open(os.path.join(dest, 'fd.csv'), newline='') as fh:
        rows = list(csv.DictReader(fh))
    assert list(rows[0]) == ['t', 'F', 'delta', 'nCrushed', 'nAbraded', 'Fapplied'] and len(rows) <= MAX_FD_ROWS
    assert max(float(r['F']) for r in rows) == pytest.approx(np.max(c['F']), rel=1e-8)  # the peak, to the CSV's digits
    with open(os.path.join(dest, 'checks.csv'), newline='') as fh:
        checks = list(csv.DictReader(fh))
    assert [(r['iter'], r['crushes']) for r in checks if r['crushes'] != '0'] == [('30000', '2'), ('70000', '1')]
    # the ratio's curve to a step of its range (0.6): 1/200, doubled once here (200 steps up and 200 down are
    # more than 400 rows), so its running maximum is off by less than 0.006 at any check
    t = np.array([float(r['t']) for r in checks])
    ratio = np.maximum.accumulate([float(r['maxStressRatio']) for r in checks])
    every = np.arange(1000)
    exact = np.maximum.accumulate(0.8 + 0.6 * np.sin(np.pi * every / 1000))
    fromRecord = ratio[np.searchsorted(t, 1e-3 * every + 1e-12, side='right') - 1]
    # (at most 400 rows, and the check at half the peak load on top)
    assert np.max(np.abs(fromRecord - exact)) < 0.6 / 100 and len(checks) <= 400 + 1
    with open(os.path.join(dest, 'record.json')) as fh:
        info = json.load(fh)
    assert info['fdRows'] == {'run': 20000, 'record': len(rows)}
    assert info['checks'] == {'run': 1000, 'record': len(checks), 'crushing': 2, 'maxStressRatio': pytest.approx(1.4)}
    assert len(thinChecks({'crushes': np.ones(1000), 'maxStressRatio': np.ones(1000)})) == 400  # crushes at every check
    # f = 2 Hz: the check at half the peak load, t = 1/(4f) = 0.125 s, is kept (what halfLoadRatio reads)
    assert '12500' in [r['iter'] for r in checks]
    # a flat log keeps its ends and the two checks around a time between checks
    flat = {'t': 1e-3 * np.arange(1000), 'crushes': np.zeros(1000), 'maxStressRatio': np.ones(1000)}
    assert list(thinChecks(flat, times=[0.1255])) == [0, 125, 126, 999]
    assert list(thinChecks(flat, times=[2.0])) == [0, 999]  # after the last check: nothing more
    # the crushes with the ratio each crushed at, from events.csv (the abrasion left out)
    with open(os.path.join(dest, 'crushes.csv'), newline='') as fh:
        crushes = list(csv.DictReader(fh))
    assert [(float(r['t']), float(r['radius'])) for r in crushes] == [(0.3, 0.02), (0.3, 0.01), (0.7, 0.0125)]
    assert [float(r['ratio']) for r in crushes] == pytest.approx([1.3, 1.25, 1.1], rel=1e-9)
    # an unfinished run has no record
    os.makedirs(str(tmp_path / 'cut'))
    with pytest.raises(ValueError, match='not a finished run: no summary.json'):
        keepRecord(str(tmp_path / 'cut'), str(tmp_path / 'rec'), 'cut')


def test_the_experiment_says_which_checks_a_record_keeps_and_a_record_may_cut_its_summary(tmp_path):
    # checks every 1 ms with a flat ratio: a record keeps the ends, the crushes at 0.3 and 0.7 s and the two
    # checks around each time the declaration names (here 0.4555 s: the checks at 0.455 and 0.456 s); the log of a
    # run of before 2026-12, whose count of crushes per check is named nCrushed
    run = str(tmp_path / 'run')
    writeRun(run)
    with open(os.path.join(run, 'checks.csv'), 'w') as fh:
        fh.write('t,iter,nCrushed,maxStressRatio\n' + ''.join('%g,%d,%d,1\n' % (1e-3 * k, k, k in (300, 700)) for k in range(1000)))
    oedometer = declaration('oedometer')
    other = Declaration('other', oedometer.params, oedometer.check, 'x.py', oedometer.sets, recordTimes=lambda p: [0.4555])
    dest = writeRecord(run, str(tmp_path / 'rec'), other, summaryKeys=('deltaAtPeak', 'notThere'))
    with open(os.path.join(dest, 'checks.csv'), newline='') as fh:
        assert [r['iter'] for r in csv.DictReader(fh)] == ['0', '300', '455', '456', '700', '999']
    with open(os.path.join(dest, 'summary.json')) as fh:
        assert json.load(fh) == {'deltaAtPeak': 0.06, 'params': {'seed': 1, 'f': 2.0}}
    with open(os.path.join(dest, 'record.json')) as fh:
        assert json.load(fh)['runId'] == 'rec'
    # the oedometer's: the checks around Fmax/2 at t = 1/(4f) = 0.125 s
    dest = writeRecord(run, str(tmp_path / 'oed'))
    with open(os.path.join(dest, 'checks.csv'), newline='') as fh:
        assert [r['iter'] for r in csv.DictReader(fh)] == ['0', '125', '300', '700', '999']


def test_an_experiment_that_names_its_record_files_gets_them_whole(tmp_path):
    """The box test's declaration names the files of its record: copied whole, and nothing else (its
    crushes.csv is its own, not the oedometer's events thinned)."""
    run = tmp_path / 'box'
    run.mkdir()
    files = {'summary.json': json.dumps({'settlement': 1e-4, 'params': {'seed': 1}}), 'row.json': '{}',
             'cycles.csv': 'cycle,settlement\n1,1e-4\n', 'grading.csv': 'cycle,Bg\n0,0\n', 'zones.csv': 'under\n0\n',
             'crushes.csv': 't,cycle,x,zone\n0.1,1,0.0,under\n', 'samples.csv': 't,F\n0,3000\n', 'fd.csv': 'x\n',
             'jumps.csv': 'jump,cycle\n1,12\n', 'state-jump0001-after.yade.gz': 'a state after a jump',
             'state-end.yade.gz': 'the end state', 'state-start.yade.gz': 'the start state'}
    for name, text in files.items():
        (run / name).write_text(text)
    dest = writeRecord(str(run), str(tmp_path / 'rec'), 'box')
    kept = set(os.listdir(dest))
    assert kept == set(declaration('box').recordFiles) | {'record.json'}
    for name in declaration('box').recordFiles:
        assert (tmp_path / 'rec' / name).read_text() == files[name], name


def test_a_file_too_large_for_git_stays_in_the_run_and_the_record_names_it(tmp_path, monkeypatch):
    """A clump specimen's end state (3.7 MB) is not committed: the record keeps the files under the limit, and
    record.json names the one left out with its size and SHA-1 (hashlib's of its bytes) and the run's folder."""
    import hashlib
    from ballast.study import records
    monkeypatch.setattr(records, 'MAX_RECORD_FILE', 100)
    run = tmp_path / 'triax'
    run.mkdir()
    big = bytes(range(256)) * 2   # 512 bytes > 100
    (run / 'summary.json').write_text(json.dumps({'params': {'seed': 1}}))
    (run / 'state-end.yade.gz').write_bytes(big)
    (run / 'cycles.csv').write_text('cycle\n' + '1\n' * 40)   # 86 bytes: kept
    dest = writeRecord(str(run), str(tmp_path / 'rec'), 'triaxial')
    assert sorted(os.listdir(dest)) == ['cycles.csv', 'record.json', 'summary.json']
    left = json.load(open(os.path.join(dest, 'record.json')))['leftOut']
    assert left == {'state-end.yade.gz': {'bytes': 512, 'sha1': hashlib.sha1(big).hexdigest(), 'run': str(run)}}


@pytest.fixture
def setup(tmp_path):
    (tmp_path / 'tiny.table').write_text(TABLE)
    (tmp_path / 'oedometer.py').write_text('# the oedometer\n')
    return {'table': str(tmp_path / 'tiny.table'), 'script': str(tmp_path / 'oedometer.py'), 'yade': writeFakeYade(tmp_path),
            'records': str(tmp_path / 'docs' / 'tiny')}


def test_a_study_goes_on_from_its_records_on_another_machine(setup, tmp_path, capsys):
    # session 1 runs two rows, with records
    assert Study(out=str(tmp_path / 'machine1'), lines=[2, 3], **setup).run(LocalExecutor(2)) == 0
    rec = setup['records']
    assert sorted(os.listdir(os.path.join(rec, 'runs'))) == IDS[:2]
    with open(os.path.join(rec, 'study.json')) as fh:
        index = json.load(fh)
    assert index['table'] == 'tiny.table' and 'script' not in index and [r['runId'] for r in index['rows']] == IDS
    # the records aggregate like a study directory; the row not run yet is missing
    data = StudyData(rec)
    assert data.param == 'f' and data.missing == [IDS[2]] and stats(data)[0]['deltaAtPeak_mean'] == pytest.approx(1e-3)
    capsys.readouterr()
    # session 2, a fresh clone on another machine: no study directory, only the records
    assert Study(out=str(tmp_path / 'machine2'), **setup).run(LocalExecutor(2)) == 0
    assert '3 rows, 2 finished before (skipped), 1 to run' in capsys.readouterr().out
    assert os.listdir(os.path.join(str(tmp_path / 'machine2'), 'runs')) == [IDS[2]] and hasRecord(rec, IDS[2])
    # a record made from other cells than the table now has is refused before any run
    rowJson = os.path.join(rec, 'runs', IDS[0], 'row.json')
    with open(rowJson) as fh:
        good = fh.read()
    made = json.loads(good)
    made['row']['f'] = 3
    with open(rowJson, 'w') as fh:
        json.dump(made, fh)
    with pytest.raises(StudyError, match='were made from other values than the table now gives: seed=1,f=2 .line 2: f 3'):
        Study(out=str(tmp_path / 'machine3'), **setup).run(LocalExecutor(1))
    # compared as parameters: a column the record has and the table dropped, at its default, changes nothing
    made = json.loads(good)
    made['row']['m'] = '1'   # eq. 4's m, whose default is 1
    with open(rowJson, 'w') as fh:
        json.dump(made, fh)
    assert Study(out=str(tmp_path / 'machine3'), **setup).run(LocalExecutor(1)) == 0
    made['row']['m'] = '2'
    with open(rowJson, 'w') as fh:
        json.dump(made, fh)
    with pytest.raises(StudyError, match=r'seed=1,f=2 \(line 2: m 2.0 -> 1.0\)'):
        Study(out=str(tmp_path / 'machine4'), **setup).run(LocalExecutor(1))
    with open(rowJson, 'w') as fh:
        fh.write(good)
    # runs finished before records were asked for get theirs when the study starts again
    other = str(tmp_path / 'docs' / 'other')
    Study(**dict(setup, out=str(tmp_path / 'machine1'), records=other)).run(LocalExecutor(2))
    assert sorted(os.listdir(os.path.join(other, 'runs'))) == sorted(IDS)
    with open(os.path.join(other, 'runs', IDS[0], 'summary.json')) as fh, \
            open(os.path.join(str(tmp_path / 'machine1'), 'runs', IDS[0], 'summary.json')) as fh2:
        assert fh.read() == fh2.read()
