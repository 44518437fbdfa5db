"""Tests of ballast.study.runner: one run of a table row, with a stand-in for yade (study_fakes.py)
that keeps the oedometer's command-line contract, so no simulation runs. A run that finishes, one
that fails, one past its --timeout, one stopped; shipped to a worker that does not see the study
directory and written back; the log line that says why. Robustness: a runner killed (SIGKILL)
leaves no simulation running, a restart does not run a row another runner holds, a run killed by a
signal says so, a cut summary.json is no finished run, results are synced before they are renamed."""
import glob
import json
import os
import signal
import subprocess
import sys
import threading
import time

import pytest

from ballast.experiments import declaration
from ballast.study import attempts, process, runner
from ballast.runfiles import codeSha1, readSummary, writeAtomic
from study_fakes import writeFakeYade

TABLE = 'seed f\n1 2\n'
TIMEOUT = 5   # [s] of a run that hangs: well after the fake has started with its child, even on a loaded machine
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
            'env': {'OMP_NUM_THREADS': '1'}, 'out': str(out), 'token': 'token', 'sets': declaration('oedometer').sets,
            'packings': str(tmp_path / 'packings'), 'packingFiles': {}, 'timeout': None, 'executor': 'local', 'ship': False}


def test_the_command_line_sets_what_the_declaration_says():
    spec = {'yade': 'yade', 'nice': None, 'runId': 'r1', 'sets': {'results': 'out', 'runId': 'name', 'sampleStore': None}}
    assert runner.command(spec, 'a.py', '/res', '/samples') == ['yade', '-n', '-x', 'a.py', '--out', '/res', '--name', 'r1']
    spec = dict(spec, nice=5, sets=declaration('oedometer').sets)
    assert runner.command(spec, 'a.py', '/res', '/samples') == ['nice', '-n', '5', 'yade', '-n', '-x', 'a.py', '--results',
                                                              '/res', '--runId', 'r1', '--packingDir', '/samples']
    spec = dict(spec, nice=None, sets=declaration('box').sets)
    assert runner.command(spec, 'a.py', '/res', '/beds', resume=True)[-4:] == ['--bedDir', '/beds', '--resume', '1']


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
    assert s['argv'][:3] == ['-n', '-x', spec['scriptPath']]  # the client's own file: the same text
    assert s['niceness'] == min(19, os.nice(0) + 10)   # the run itself is niced (yade's own --nice is a no-op)
    if s['groupNice'] is not None:  # and its session's scheduling group: else it takes a full share beside others
        assert s['groupNice'] == '10'
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
    assert attempts.failedLog(log) and 'status  : 3 (FAILED)' in open(log).read()
    assert runner.runRow(spec)['status'] == 'ok'
    assert not os.path.exists(failed) and not attempts.failedLog(log)


def test_exit_zero_without_a_summary_is_a_failure(spec):
    os.makedirs(spec['packings'])
    res = runner.runRow(dict(spec, env={'FAKE': 'nosummary'}))
    assert res['status'] == 'failed' and res['rc'] == 0 and res['error'] == 'exit code 0 but no summary.json'


def test_a_cut_summary_is_not_a_finished_run(spec):
    os.makedirs(spec['packings'])
    res = runner.runRow(dict(spec, env={'FAKE': 'truncated'}))
    assert res['status'] == 'failed' and res['rc'] == 0 and res['summary'] is None, res
    assert res['error'].startswith('exit code 0 but summary.json is not JSON (cut short?): ')
    assert not os.path.exists(os.path.join(spec['out'], 'runs', spec['runId']))
    assert os.path.exists(os.path.join(spec['out'], 'failed', spec['runId'], 'summary.json'))


@pytest.mark.parametrize('text, why', [
    (None, 'no summary.json'),
    ('{"peakForce": 2001.0, "deltaAt',
     'summary.json is not JSON (cut short?): Unterminated string starting at: line 1 column 23 (char 22)'),
    ('[2001.0]', 'summary.json holds a list, not a JSON object'),
    ('{"peakForce": 2001.0}', None)])
def test_the_check_of_a_finished_run_says_why_it_fails(tmp_path, text, why):
    if text is not None:
        (tmp_path / 'summary.json').write_text(text)
    summary, said = readSummary(str(tmp_path))
    assert said == why and (summary == {'peakForce': 2001.0}) == (why is None)


def test_a_run_killed_by_a_signal_says_so_not_its_last_line(spec):
    os.makedirs(spec['packings'])
    res = runner.runRow(dict(spec, env={'FAKE': 'killed'}))
    assert res['status'] == 'failed' and res['rc'] == -9 and res['error'] == 'killed by signal 9', res
    assert os.path.isdir(os.path.join(spec['out'], 'failed', spec['runId']))
    assert 'status  : -9 (FAILED)' in open(os.path.join(spec['out'], 'logs', spec['runId'] + '.log')).read()


def processGone(pid):
    try:
        with open('/proc/%d/stat' % pid) as fh:
            return fh.read().split(')')[1].split()[0] == 'Z'  # a zombie nobody reaped: dead
    except FileNotFoundError:
        return True


@pytest.mark.parametrize('why', ['timeout', 'stopped'])
def test_a_run_past_its_timeout_or_stopped_is_killed_with_its_children(spec, why):
    """Killed once the fake runs with its child (its pid file written): on a loaded machine its start takes
    seconds, and a kill before it would leave nothing to check (the stop waits for the file; the timeout, TIMEOUT
    s, is long enough)."""
    os.makedirs(spec['packings'])
    pidFile = os.path.join(os.path.dirname(spec['out']), 'fake-pids.json')
    if why == 'stopped':
        threading.Thread(target=lambda: waitUntil(lambda: os.path.exists(pidFile), 60) and process.STOP.set(),
                         daemon=True).start()
    try:
        res = runner.runRow(dict(spec, env={'FAKE': 'hang', 'FAKE_PIDS': pidFile},
                                 timeout=TIMEOUT if why == 'timeout' else None))
        if why == 'stopped':
            assert runner.runRow(spec) is None  # the study stopped before this run's turn: it does not start
    finally:
        process.STOP.clear()
    assert res['status'] == why and res['rc'] < 0, res  # killed by a signal
    assert ('--timeout of %g s' % TIMEOUT if why == 'timeout' else 'interrupted') in res['error']
    log = open(os.path.join(spec['out'], 'logs', spec['runId'] + '.log')).read()
    assert ('(FAILED)' if why == 'timeout' else '(STOPPED)') in log
    # a timeout is a failure (kept in failed/), a stopped run is simply redone
    assert os.path.isdir(os.path.join(spec['out'], 'failed', spec['runId'])) == (why == 'timeout')
    with open(pidFile) as fh:  # this run's own processes, not any 'sleep 120' on the machine
        pids = json.load(fh)
    assert waitUntil(lambda: all(processGone(pid) for pid in pids.values()), 5), pids


def childrenOf(pid):
    kids = []
    for d in os.listdir('/proc'):
        try:
            with open('/proc/%s/stat' % d) as fh:
                if int(fh.read().rsplit(')', 1)[1].split()[1]) == pid:
                    kids.append(int(d))
        except (OSError, ValueError, IndexError):
            pass
    return kids


def waitUntil(test, seconds):
    end = time.time() + seconds
    while not test() and time.time() < end:
        time.sleep(0.05)
    return test()


@pytest.mark.parametrize('killed', ['runner', 'runner and watchdog'])
def test_a_runner_killed_by_sigkill_leaves_no_simulation_running(spec, killed):
    """The runner, in a process of its own, runs a fake yade that hangs with a helper process, and is
    killed by SIGKILL: yade and its helper die with it (the helper by the watchdog). With the watchdog
    killed first, yade still dies, by its parent-death signal. A restart then clears what the dead
    attempt left and has a journal record of it."""
    os.makedirs(spec['packings'])
    code = 'import json, sys; from ballast.study import runner; runner.runRow(json.loads(sys.argv[1]))'
    proc = subprocess.Popen([sys.executable, '-c', code, json.dumps(dict(spec, env={'FAKE': 'hang'}))])
    pids = {}

    def found():
        return glob.glob(os.path.join(spec['out'], 'work', '*', 'results', '*', 'pids.json'))
    try:
        assert waitUntil(found, 20), 'the fake yade did not start'
        with open(found()[0]) as fh:
            pids = json.load(fh)
        watchdog = [p for p in childrenOf(proc.pid) if p != pids['yade']]
        assert len(watchdog) == 1 and pids['yade'] in childrenOf(proc.pid)
        if killed == 'runner and watchdog':
            os.kill(watchdog[0], signal.SIGKILL)
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait(10)
        assert waitUntil(lambda: processGone(pids['yade']), 5), 'yade outlived its runner'
        if killed == 'runner':
            assert waitUntil(lambda: processGone(pids['helper']), 5), "yade's helper outlived the runner"
            work = os.path.join(spec['out'], 'work')
            [rec] = attempts.clearWork(work)
            assert rec['runId'] == spec['runId'] and rec['status'] == 'started'
            assert rec['error'].endswith('its log ends: fake yade: run seed=1,f=2, mode hang')
            assert os.listdir(work) == []
    finally:
        for pid in [proc.pid] + list(pids.values()):
            if not processGone(pid):
                os.kill(pid, signal.SIGKILL)


def test_a_restart_does_not_run_a_row_another_runner_holds(spec):
    """Another runner holds the row's lock (a process of its own): the row is not run and the folder of
    its attempt stays, also when the study starts again and clears what dead attempts left."""
    os.makedirs(spec['packings'])
    work = os.path.join(spec['out'], 'work')
    code = ('import sys; from ballast.study import attempts; lock = attempts.rowLock(*sys.argv[1:]); print(bool(lock), flush=True); '
            'sys.stdin.read()')
    holder = subprocess.Popen([sys.executable, '-c', code, work, spec['runId']], stdin=subprocess.PIPE, stdout=subprocess.PIPE)
    try:
        assert holder.stdout.readline() == b'True\n'
        os.makedirs(os.path.join(work, spec['runId'] + '.held1234'))  # the attempt going on there
        os.makedirs(os.path.join(work, 'seed=2,f=2.dead1234'))  # one of a runner that died, and its lock
        open(os.path.join(work, 'seed=2,f=2.lock'), 'w').close()
        res = runner.runRow(spec)
        assert res['status'] == 'elsewhere' and res['error'] == 'running elsewhere: another runner holds %s' % os.path.join(
            work, spec['runId'] + '.lock')
        assert sorted(os.listdir(spec['out'])) == ['.study-token', 'work']  # nothing run, no log, no result
        assert [r['runId'] for r in attempts.clearWork(work)] == ['seed=2,f=2']
        assert sorted(os.listdir(work)) == [spec['runId'] + '.held1234', spec['runId'] + '.lock']
    finally:
        holder.stdin.close()
        holder.wait(10)
    assert runner.runRow(spec)['status'] == 'ok'  # let go: the row runs
    assert os.listdir(work) == [spec['runId'] + '.held1234']  # its lock removed as it let go; the rest is the next start's


def test_results_are_synced_before_they_are_renamed_into_place(spec, tmp_path, monkeypatch):
    """Every file and directory of a run and its log are fsynced before the rename, the directory
    they go to after it; so are the files written atomically."""
    events = []
    fsync, replace = os.fsync, os.replace

    def recordFsync(fd):
        events.append(('fsync', os.readlink('/proc/self/fd/%d' % fd)))
        fsync(fd)

    def recordReplace(src, dst):
        replace(src, dst)
        events.append(('replace', src, dst))
    monkeypatch.setattr(os, 'fsync', recordFsync)
    monkeypatch.setattr(os, 'replace', recordReplace)
    attempt = tmp_path / 'attempt'
    (attempt / 'run' / 'vtk').mkdir(parents=True)
    files = [attempt / 'run' / 'summary.json', attempt / 'run' / 'vtk' / 'a.vtu', attempt / 'run.log']
    for f in files:
        f.write_text('{}')
    out = spec['out']
    runner.finalize(out, spec['runId'], {'status': 'ok'}, str(attempt / 'run'), str(attempt / 'run.log'))
    writeAtomic(os.path.join(out, 'status.csv'), 'line\n')

    def at(event):
        return events.index(event)
    run, log = os.path.join(out, 'runs', spec['runId']), os.path.join(out, 'logs', spec['runId'] + '.log')
    moved = at(('replace', str(attempt / 'run'), run))
    for p in files[:2] + [attempt / 'run' / 'vtk', attempt / 'run']:
        assert at(('fsync', str(p))) < moved, p
    assert at(('fsync', os.path.join(out, 'runs'))) > moved
    assert at(('fsync', str(files[2]))) < at(('replace', str(files[2]), log)) < at(('fsync', os.path.join(out, 'logs')))
    tmp = [e[1] for e in events if e[0] == 'replace' and e[2] == os.path.join(out, 'status.csv')]
    assert at(('fsync', tmp[0])) < at(('replace', tmp[0], os.path.join(out, 'status.csv'))) < at(('fsync', out))


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


def test_a_stopped_run_of_a_resuming_experiment_is_kept_and_the_next_attempt_resumes(spec):
    """sets with resume (the box test's): the run stopped after it saved a state is kept in resume/; the next run of
    the row is given its folder and --resume 1, and its row.json says where it went on from."""
    os.makedirs(spec['packings'])
    spec = dict(spec, sets=dict(spec['sets'], resume='resume'))
    pidFile = os.path.join(os.path.dirname(spec['out']), 'fake-pids.json')
    threading.Thread(target=lambda: waitUntil(lambda: os.path.exists(pidFile), 60) and process.STOP.set(),
                     daemon=True).start()
    try:
        res = runner.runRow(dict(spec, env={'FAKE': 'hang', 'FAKE_PIDS': pidFile}))
    finally:
        process.STOP.clear()
    assert res['status'] == 'stopped' and res['error'].endswith('kept to go on from its state-1.gz'), res
    kept = os.path.join(spec['out'], attempts.KEEP, spec['runId'])
    assert os.path.isfile(os.path.join(kept, 'run', 'state-1.gz'))
    res = runner.runRow(spec)
    assert res['status'] == 'ok' and res['resumedFrom'] == 'state-1.gz', res
    run = os.path.join(spec['out'], 'runs', spec['runId'])
    assert seen(run)['argv'][-2:] == ['--resume', '1'] and os.path.isfile(os.path.join(run, 'state-1.gz'))
    with open(os.path.join(run, 'row.json')) as fh:
        assert json.load(fh)['resumedFrom'] == 'state-1.gz'
    assert not os.path.exists(kept)
    assert runner.runRow(dict(spec, runId='other'))['resumedFrom'] is None   # nothing kept: starts afresh
