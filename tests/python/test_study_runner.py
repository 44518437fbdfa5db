"""Tests of ballast.study.runner: one run of a table row, with a stand-in for yade (study_fakes.py)
that keeps the oedometer's command-line contract, so no simulation runs. A run that finishes, one
that fails, one past its --timeout, one stopped; shipped to a worker that does not see the study
directory and written back; the log line that says why."""
import json
import os

import pytest

from ballast.study import runner
from ballast.study.files import codeSha1
from study_fakes import writeFakeYade

TABLE = 'seed f\n1 2\n'
SCRIPT = '# the oedometer, as the client read it\n'


@pytest.fixture
def spec(tmp_path):
    """What Study.tasks gives runRow for line 2 of TABLE, in a study directory this process sees."""
    out = tmp_path / 'study'
    out.mkdir()
    (out / '.study-token').write_text('token')
    (tmp_path / 'oedometer.py').write_text(SCRIPT)
    return {'runId': 'seed=1,f=2', 'line': 2, 'row': {'seed': '1', 'f': '2'}, 'tableText': TABLE, 'tableName': 'tiny.table',
            'scriptPath': str(tmp_path / 'oedometer.py'), 'scriptText': SCRIPT, 'yade': writeFakeYade(tmp_path), 'nice': 10,
            'env': {'OMP_NUM_THREADS': '1'}, 'out': str(out), 'token': 'token', 'packings': str(tmp_path / 'packings'),
            'packingFiles': {}, 'timeout': None, 'executor': 'local', 'ship': False}


def seen(d):
    with open(os.path.join(d, 'seen.json')) as fh:
        return json.load(fh)


def test_a_finished_run_goes_to_runs_with_its_row_and_log(spec):
    os.makedirs(spec['packings'])
    res = runner.runRow(spec)
    assert res['status'] == 'ok' and res['rc'] == 0 and res['shared'], res
    run = os.path.join(spec['out'], 'runs', spec['runId'])
    with open(os.path.join(run, 'row.json')) as fh:
        row = json.load(fh)
    assert row['row'] == spec['row'] and row['line'] == 2 and row['codeSha1'] == codeSha1(SCRIPT)
    assert res['summary']['peakForce'] == 2001.0  # what the run wrote, read back
    s = seen(run)
    assert s['OMP_NUM_THREADS'] == '1' and s['script'] == SCRIPT
    assert s['argv'][:4] == ['--nice=10', '-n', '-x', spec['scriptPath']]  # the client's own file: the same text
    assert s['argv'][-2:] == ['--packingDir', spec['packings']]  # shared: the study's packings
    assert len(os.listdir(spec['packings'])) == 1
    log = open(os.path.join(spec['out'], 'logs', spec['runId'] + '.log')).read()
    assert 'fake yade: run seed=1,f=2' in log and 'status  : 0 (OK)' in log and 'YADE_BATCH=' in log
    assert os.listdir(os.path.join(spec['out'], 'work')) == []  # the attempt's directory is gone


def test_a_failed_run_keeps_what_it_left_until_it_succeeds(spec):
    os.makedirs(spec['packings'])
    res = runner.runRow(dict(spec, env={'FAKE': 'fail'}))
    assert res['status'] == 'failed' and res['rc'] == 3
    assert res['error'] == 'RuntimeError: the fake failed on purpose'  # the line of the log that says why
    failed = os.path.join(spec['out'], 'failed', spec['runId'])
    assert os.path.exists(os.path.join(failed, 'partial.txt'))
    assert not os.path.exists(os.path.join(spec['out'], 'runs', spec['runId']))
    log = os.path.join(spec['out'], 'logs', spec['runId'] + '.log')
    assert runner.failedLog(log) and 'status  : 3 (FAILED)' in open(log).read()
    assert runner.runRow(spec)['status'] == 'ok'
    assert not os.path.exists(failed) and not runner.failedLog(log)


def test_exit_zero_without_a_summary_is_a_failure(spec):
    os.makedirs(spec['packings'])
    res = runner.runRow(dict(spec, env={'FAKE': 'nosummary'}))
    assert res['status'] == 'failed' and res['rc'] == 0 and 'fake yade' in res['error']


def processGone(pid):
    try:
        with open('/proc/%d/stat' % pid) as fh:
            return fh.read().split(')')[1].split()[0] == 'Z'  # a zombie nobody reaped: dead
    except FileNotFoundError:
        return True


@pytest.mark.parametrize('why', ['timeout', 'stopped'])
def test_a_run_past_its_timeout_or_stopped_is_killed_with_its_children(spec, why):
    os.makedirs(spec['packings'])
    if why == 'stopped':
        runner.STOP.set()
    try:
        res = runner.runRow(dict(spec, env={'FAKE': 'hang'}, timeout=0.3 if why == 'timeout' else None))
    finally:
        runner.STOP.clear()
    assert res['status'] == why and res['rc'] < 0, res  # killed by a signal
    assert ('--timeout of 0.3 s' if why == 'timeout' else 'interrupted') in res['error']
    log = open(os.path.join(spec['out'], 'logs', spec['runId'] + '.log')).read()
    assert ('(FAILED)' if why == 'timeout' else '(STOPPED)') in log
    # a timeout is a failure (kept in failed/), a stopped run is simply redone
    assert os.path.isdir(os.path.join(spec['out'], 'failed', spec['runId'])) == (why == 'timeout')
    ps = [l.split() for l in os.popen('ps -eo pid,args').read().splitlines()[1:]]
    assert not [p for p in ps if p[1:] == ['sleep', '120'] and not processGone(int(p[0]))]


def test_shipped_run_comes_back_and_is_written_by_the_client(spec, tmp_path):
    """A worker that does not see the study: script, table and the stored packing go with the task,
    the run's files and the packings it built come back."""
    stored = {'packing-seed9-old.json': b'{"builtBy": "another study"}'}
    res = runner.runRow(dict(spec, ship=True, scriptPath='/nowhere/oedometer.py', packingFiles=stored))
    assert res['status'] == 'ok' and not res['shared'] and not res.get('finalized')
    assert not os.path.exists(os.path.join(spec['out'], 'runs'))  # nothing written by the worker
    assert set(res['files']) == {'summary.json', 'fd.csv', 'seen.json', 'row.json'}
    s = json.loads(res['files']['seen.json'])
    assert s['script'] == SCRIPT and s['argv'][3] != '/nowhere/oedometer.py'  # the copy that was sent
    assert s['packings'] == ['packing-seed9-old.json']
    assert list(res['packings']) == [os.path.basename(res['summary']['packingFile'])]  # only the new one
    os.makedirs(os.path.join(spec['out'], 'work'))
    os.makedirs(spec['packings'])
    runner.finalizeShipped(spec['out'], spec['packings'], res)
    run = os.path.join(spec['out'], 'runs', spec['runId'])
    assert seen(run) == s and os.path.exists(os.path.join(run, 'row.json'))
    assert os.listdir(spec['packings']) == [os.path.basename(res['summary']['packingFile'])]
    assert 'status  : 0 (OK)' in open(os.path.join(spec['out'], 'logs', spec['runId'] + '.log')).read()


def test_a_waiting_run_gets_the_packing_its_leader_built(spec):
    lead = runner.runRow(dict(spec, ship=True))
    res = runner.runRow(dict(spec, ship=True, runId='seed=1,f=2.again'), {'packings': lead['packings']})
    assert res['status'] == 'ok' and res['summary']['packingBuiltBy'] == spec['runId'] and res['packings'] == {}


def test_last_error_prefers_the_bad_parameter_line(tmp_path):
    log = tmp_path / 'x.log'
    log.write_text('start\noedometer.py: bad parameter f: f = -1 is not allowed\nTraceback ...\n  File x\nexit\n')
    assert runner.lastError(str(log)) == 'oedometer.py: bad parameter f: f = -1 is not allowed'
    log.write_text('Traceback (most recent call last):\n  File "x"\nValueError: no\n\n')
    assert runner.lastError(str(log)) == 'ValueError: no'
    assert runner.lastError(str(tmp_path / 'none.log')) == ''
