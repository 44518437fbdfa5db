"""Tests of ballast.study.study (class Study: checks before any run, which run builds a shared
packing, bookkeeping, restart, status) with a stand-in for yade (study_fakes.py): no simulation.
Every attempt in the journal (stopped, or left by a runner that died); a cut summary.json is no
finished run, for the study and the aggregation alike."""
import csv
import json
import os
import shutil
import signal
import threading

import pytest

from ballast.experiments import Declaration, declaration
from ballast.study import LocalExecutor, Study, StudyData, process, runner, status
from ballast.runfiles import codeSha1, writeAtomic
from ballast.study.options import StudyError
from study_fakes import ctrlC, writeFakeYade  # noqa: F401 (ctrlC is a fixture)

# lines 2 and 3 need the same packing (seed 1), f = 4 Hz has the shorter loading cycle: it builds it
TABLE = 'seed! f! !FAKE\n1 2 ok\n1 4 ok\n2 2 fail\n'
IDS = ['seed=1,f=2', 'seed=1,f=4', 'seed=2,f=2']


@pytest.fixture
def setup(tmp_path):
    (tmp_path / 'tiny.table').write_text(TABLE)
    (tmp_path / 'oedometer.py').write_text('# the oedometer\n')
    return {'table': str(tmp_path / 'tiny.table'), 'script': str(tmp_path / 'oedometer.py'), 'out': str(tmp_path / 'studies' / 'tiny'),
            'yade': writeFakeYade(tmp_path)}


def study(setup, **kw):
    return Study(**dict(setup, **kw))


def statusRows(out):
    with open(os.path.join(out, 'status.csv'), newline='') as fh:
        return {r['runId']: r for r in csv.DictReader(fh)}


def journal(out):
    with open(os.path.join(out, 'journal.jsonl')) as fh:
        return [json.loads(l)['runId'] for l in fh]


def rowJson(out, rid):
    return os.path.join(out, 'runs', rid, 'row.json')


def test_a_study_runs_its_rows_and_carries_on_where_it_stopped(setup, capsys):
    out = setup['out']
    assert study(setup).run(LocalExecutor(2)) == 1  # a run failed
    said = capsys.readouterr().out
    assert '3 rows, 0 finished before (skipped), 3 to run' in said
    assert '1 run(s) wait for the prepared sample one of 1 other run(s) builds first' in said and 'FAILED seed=2,f=2 (line 4)' in said
    st = statusRows(out)
    assert [st[r]['status'] for r in IDS] == ['finished', 'finished', 'failed']
    assert st[IDS[2]]['exitCode'] == '3' and st[IDS[2]]['error'] == 'RuntimeError: the fake failed on purpose'
    with open(os.path.join(out, 'runs', IDS[0], 'summary.json')) as fh:
        assert json.load(fh)['packingBuiltBy'] == IDS[1]  # the f = 4 Hz run built the packing, f = 2 Hz waited and read it
    assert os.listdir(os.path.join(os.path.dirname(out), 'packings'))  # default: 'packings' next to the study
    with open(os.path.join(out, 'study.json')) as fh:
        info = json.load(fh)
    assert info['codeSha1'] == codeSha1('# the oedometer\n') and [r['runId'] for r in info['rows']] == IDS
    assert info['experiment'] == 'oedometer'
    assert open(os.path.join(out, 'table')).read() == TABLE  # the table as run
    assert sorted(journal(out)) == sorted(IDS)

    # again: the finished runs are skipped, the failed one is tried again
    assert study(setup).run(LocalExecutor(2)) == 1
    assert '2 finished before (skipped), 1 to run' in capsys.readouterr().out
    assert journal(out).count(IDS[0]) == 1 and journal(out).count(IDS[2]) == 2
    assert study(setup, skipFailed=True).run(LocalExecutor(2)) == 0
    assert 'nothing to run' in capsys.readouterr().out

    status(out)
    said = capsys.readouterr().out
    assert '3 rows: 1 failed, 2 finished' in said and 'failed: seed=2,f=2: RuntimeError: the fake failed on purpose' in said
    study(setup).dryRun()
    said = capsys.readouterr().out
    assert '   2  seed=1,f=2' in said and 'finished (skipped)' in said and said.count('to run') == 1


def test_finished_runs_of_other_values_stop_the_study_and_other_code_is_named(setup, capsys):
    out = setup['out']
    study(setup, lines='2').run(LocalExecutor(1))
    with open(rowJson(out, IDS[0])) as fh:
        rr = json.load(fh)
    rr['codeSha1'] = '0' * 40  # made by another version of the code
    with open(rowJson(out, IDS[0]), 'w') as fh:
        json.dump(rr, fh)
    assert study(setup, lines='2').run(LocalExecutor(1)) == 0
    assert 'warning: 1 finished run(s) were made by another version' in capsys.readouterr().out
    rr['row']['!FAKE'] = 'hang'  # made from another row than the table now has
    with open(rowJson(out, IDS[0]), 'w') as fh:
        json.dump(rr, fh)
    with pytest.raises(StudyError, match=r'seed=1,f=2 \(line 2: !FAKE hang -> ok\)'):
        study(setup).run(LocalExecutor(1))


def test_bad_input_is_refused_before_anything_is_made(setup, tmp_path):
    (tmp_path / 'bad.table').write_text('seed f\n1 2\n2 -1\n')
    (tmp_path / 'afile').write_text('')
    for kw, words in [({'table': str(tmp_path / 'none.table')}, 'TABLE: no such file'),
                      ({'script': str(tmp_path / 'none.py')}, '--script: no such file'),
                      ({'table': str(tmp_path / 'bad.table')}, 'bad.table:3: column f, value -1'),
                      ({'lines': '2,9-10'}, '--lines: line.s. 9,10 of .*tiny.table hold no row; rows are on lines 2,3,4'),
                      ({'timeout': -1}, '--timeout: study: timeout = -1'),
                      ({'out': str(tmp_path / 'a:b')}, "--out: .* contains ':'"),
                      ({'packings': str(tmp_path / 'afile')}, '--packings: .* is not a directory')]:
        with pytest.raises(StudyError, match=words):
            study(setup, **kw)
    assert not os.path.exists(setup['out'])


def test_only_one_study_runs_in_a_directory(setup):
    a, b = study(setup), study(setup)
    a.lock()
    with pytest.raises(StudyError, match='being run by another study'):
        b.lock()


def test_a_stored_packing_needs_no_leader_and_goes_with_the_task(setup):
    s = study(setup)
    s.prepare()
    assert [t['leader'] for t in s.tasks(s.lines, 'local')] == [IDS[1], None, None]
    assert s.sampleName(2) == s.sampleName(3) != s.sampleName(4)
    with open(os.path.join(s.packings, s.sampleName(2)), 'w') as fh:
        fh.write('{"grains": []}')
    tasks = s.tasks(s.lines, 'local')
    assert [t['leader'] for t in tasks] == [None, None, None]
    assert tasks[0]['spec']['packingFiles'] == {s.sampleName(2): b'{"grains": []}'} and tasks[2]['spec']['packingFiles'] == {}
    assert tasks[2]['spec']['env'] == {'OMP_NUM_THREADS': '1', 'FAKE': 'fail'}  # yade-batch's !COLUMNS


def test_the_declaration_says_which_runs_share_a_sample_and_which_builds_it(setup, capsys):
    """The study knows the experiment by its declaration: with one whose cost is f (the oedometer's is
    cycles / f), the f = 2 Hz run of seed 1 builds the packing and the 4 Hz run waits; with one that
    names no sample, nothing waits."""
    oedometer = declaration('oedometer')
    cheapSlow = Declaration('slowfirst', oedometer.params, oedometer.check, 'x.py', oedometer.sets,
                            sampleKey=oedometer.sampleKey, cost=lambda p: p['f'])
    assert study(setup, experiment=cheapSlow).run(LocalExecutor(2)) == 1
    with open(os.path.join(setup['out'], 'runs', IDS[1], 'summary.json')) as fh:
        assert json.load(fh)['packingBuiltBy'] == IDS[0]
    with open(os.path.join(setup['out'], 'study.json')) as fh:
        assert json.load(fh)['experiment'] == 'slowfirst'
    none = Declaration('nosample', oedometer.params, oedometer.check, 'x.py', oedometer.sets)
    s = study(setup, out=setup['out'] + '2', experiment=none)
    s.prepare()
    assert s.sampleName(2) is None and [t['leader'] for t in s.tasks(s.lines, 'local')] == [None, None, None]
    with pytest.raises(StudyError, match="--experiment: experiment = 'sleeper' is not allowed"):
        study(setup, experiment='sleeper')


def test_a_stopped_run_and_one_a_dead_runner_left_are_in_the_journal(setup, tmp_path, capsys, ctrlC):
    """Ctrl-C while the run of line 2 goes on: the study stops it and journals it; a folder in work/
    (an attempt of a runner that died) is removed and journaled as started when the study starts."""
    (tmp_path / 'tiny.table').write_text('seed! f! !FAKE\n1 2 hang\n')
    dead = os.path.join(setup['out'], 'work', IDS[0] + '.deadbeef')
    os.makedirs(dead)
    with open(os.path.join(dead, 'run.log'), 'w') as fh:
        fh.write('fake yade: run seed=1,f=2\nstep 1200\n')

    def pressCtrlC(spec, leader):
        threading.Timer(0.5, os.kill, (os.getpid(), signal.SIGINT)).start()
        return runner.runRow(spec, leader)
    try:
        assert study(setup).run(LocalExecutor(1, runRow=pressCtrlC)) == 130
    finally:
        process.STOP.clear()
    said = capsys.readouterr().out
    assert 'removed 1 unfinished attempt(s)' in said and 'interrupted: 0 ok, 0 failed' in said
    with open(os.path.join(setup['out'], 'journal.jsonl')) as fh:
        records = [json.loads(l) for l in fh]
    assert [(r['runId'], r['line'], r['status']) for r in records] == [(IDS[0], 2, 'started'), (IDS[0], 2, 'stopped')]
    assert records[0]['error'].endswith('its log ends: step 1200')
    # the oedometer declares resume: the stopped run, which saved a state, is kept for the row's next start
    assert records[1]['error'] == 'stopped (the study was interrupted); kept to go on from its state-1.gz'
    assert os.path.isfile(os.path.join(setup['out'], 'resume', IDS[0], 'run', 'state-1.gz'))
    assert statusRows(setup['out'])[IDS[0]]['status'] == 'stopped'
    assert os.listdir(os.path.join(setup['out'], 'work')) == []


def test_a_cut_summary_is_not_finished_for_the_study_nor_the_aggregation(setup, capsys):
    out = setup['out']
    study(setup, lines='2,3').run(LocalExecutor(1))
    path = os.path.join(out, 'runs', IDS[0], 'summary.json')
    with open(path) as fh:
        text = fh.read()
    with open(path, 'w') as fh:
        fh.write(text[:len(text) // 2])  # as a crash before the data reached the disk leaves it
    assert study(setup).finishedRow(2) is None and study(setup).finishedRow(3) is not None
    assert StudyData(out, 'f').missing == [IDS[0], IDS[2]]
    capsys.readouterr()
    status(out)
    assert '3 rows: 1 finished, 1 not selected, 1 todo' in capsys.readouterr().out  # line 4 was not in --lines
    kept = os.path.join(out, 'resume', IDS[0], 'run')   # as the runner keeps a killed run that saved a state
    os.makedirs(kept)
    writeAtomic(os.path.join(kept, 'run.json'), '{"status": "running", "lastState": "state-1.gz"}')
    writeAtomic(os.path.join(kept, 'state-1.gz'), 'saved')
    status(out)
    assert 'kept: %s goes on from its state-1.gz at its next start' % IDS[0] in capsys.readouterr().out
    shutil.rmtree(os.path.join(out, 'resume'))
    assert study(setup, lines='2').run(LocalExecutor(1)) == 0  # run again: the cut one replaced
    with open(path) as fh:
        assert json.load(fh)['peakForce'] == 2001.0
