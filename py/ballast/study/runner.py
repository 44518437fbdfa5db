"""One run of a study: one table row, run as yade-batch runs it,

    YADE_BATCH=table:line OMP_NUM_THREADS=1 yade -n -x SCRIPT --results DIR --runId ID --packingDir DIR

(the options are the parameters the experiment's declaration has the study set, `sets`; these are
the oedometer's) in a thread of the study (local) or on a Dask worker. A worker that sees the study
directory (a shared file system) writes the run there; one that does not gets the script, the table
and the prepared sample with the task and sends the run's files back (:func:`finalizeShipped`
writes them).
:func:`runRow` never raises: a failure is a result like any other.

A run does not outlive its runner, however that ends (a SIGKILL from the OOM killer or Slurm
too): yade gets a parent-death signal and a watchdog kills what is left of its process group. A
run of the study directory holds a lock there for the whole attempt: a runner started again beside
a live one does not run the row a second time nor remove its work folder.

A run killed or stopped after it saved a state (an experiment that declares ``resume``, the box test)
is kept in <out>/resume/<run id>/ with its row; the next attempt of the same row goes on from that
state in the same folder instead of starting again (:func:`keepToResume`, :func:`takeKept`).
"""
import ctypes
import fcntl
import functools
import json
import os
import re
import shlex
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time
import traceback

from ..runfiles import codeSha1, killedRunState, moveSynced, readFiles, readSummary, sha1, writeAtomic
from ..tables import TABLE_DIR

# Set on Ctrl-C by the local executor: every running run kills its yade and returns.
STOP = threading.Event()
POLL = 0.2        # [s] how often a run checks its yade, the --timeout and STOP
ASK_DASK = 5.0    # [s] how often a run on a Dask worker asks whether the study was stopped
KILL_WAIT = 10.0  # [s] after SIGTERM, before SIGKILL
PR_SET_PDEATHSIG = 1  # prctl option of Linux: the signal a process gets when its parent dies
PRCTL = ctypes.CDLL(None, use_errno=True).prctl  # looked up here, not between fork and exec

# The watchdog of one run (see runYade), in a session of its own: reads the process group of the
# run's yade, then waits for its stdin to close, which happens when the run is over or when the
# runner died, however it died, and kills what is left of the group: yade's children have no
# parent-death signal of their own. A zombie counts as gone: an orphan's waits for init to reap it.
WATCHDOG = r'''
import os, signal, sys, time

def alive(group):
    for pid in filter(str.isdigit, os.listdir('/proc')):
        try:
            with open('/proc/%s/stat' % pid) as fh:
                state, _, pgrp = fh.read().rsplit(')', 1)[1].split()[:3]
        except (OSError, ValueError):
            continue
        if int(pgrp) == group and state != 'Z':
            return True
    return False

line = sys.stdin.readline()
sys.stdin.read()
group = int(line) if line else None  # None: yade did not start
for sig in (signal.SIGTERM, signal.SIGKILL):
    if group is None or not alive(group):
        break
    try:
        os.killpg(group, sig)
    except ProcessLookupError:  # gone meanwhile
        break
    end = time.time() + float(sys.argv[1])
    while alive(group) and time.time() < end:
        time.sleep(0.05)
'''


def seesStudy(out, token):
    """True if this machine sees the study directory (a shared file system)."""
    try:
        with open(os.path.join(out, '.study-token')) as fh:
            return fh.read().strip() == token
    except OSError:
        return False


def batchTrailer(runId, rc, state, wall, cmd, started, finished):
    """The job summary yade-batch appends to each log."""
    return ('\n=================== JOB SUMMARY ================\nid      : %s\nstatus  : %d (%s)\nduration: %s\n'
            'command : %s\nstarted : %s\nfinished: %s\n' % (
                runId, rc, state, '%02d:%02d:%02d' % (wall // 3600, (wall % 3600) // 60, wall % 60),
                cmd, time.asctime(time.localtime(started)), time.asctime(time.localtime(finished))))


def lastError(logPath):
    """The line of a log that says why a run failed: the oedometer's 'bad parameter', else the
    exception, else the last line."""
    try:
        with open(logPath, errors='replace') as fh:
            lines = [l.rstrip() for l in fh if l.strip()]
    except OSError:
        return ''
    for l in reversed(lines):
        if 'bad parameter' in l or re.match(r'^[A-Za-z_.]*(Error|Exception)\b', l):
            return l[:300]
    return lines[-1][:300] if lines else ''


KEEP = 'resume'   # <out>/resume/<run id>/: a killed run's folder and row, to go on from (keepToResume)
PROGRESS = re.compile(r'(\d+(?:\.\d+)?)% of (\w+)\s+ETA (\S+)')  # a progress line of experiments/phases.py


def newestLog(work, runId):
    """The run.log of the newest attempt of a run in the study's work directory, or None."""
    try:
        tries = [os.path.join(work, n) for n in os.listdir(work) if n.rsplit('.', 1)[0] == runId]
        return max((os.path.join(t, 'run.log') for t in tries if os.path.isfile(os.path.join(t, 'run.log'))),
                   key=os.path.getmtime, default=None)
    except OSError:  # no work directory, or an attempt's folder went while we looked
        return None


def runProgress(work, runId):
    """How far the newest attempt of a run in the study's work directory has come, from the last
    progress line of its run.log ('24.8% of loading, ETA 23m32s'); '' when there is none yet."""
    log = newestLog(work, runId)
    if log is None:
        return ''
    try:
        with open(log, 'rb') as fh:
            fh.seek(max(0, os.fstat(fh.fileno()).st_size - 4096))  # a log grows to megabytes: its tail only
            tail = fh.read().decode('utf-8', 'replace')
    except OSError:  # the attempt ended and its folder went while we looked
        return ''
    found = PROGRESS.findall(tail)
    return '%s%% of %s, ETA %s' % found[-1] if found else ''


def failedLog(path):
    """True if the log ends a failed attempt (yade-batch's trailer says FAILED)."""
    try:
        with open(path, errors='replace') as fh:
            return '(FAILED)' in fh.read()
    except OSError:
        return False


def rowLock(work, runId):
    """The lock of a run in the study's work directory (work/<run id>.lock), taken: an open file,
    or None when another runner holds it (the run goes on there)."""
    os.makedirs(work, exist_ok=True)
    path = os.path.join(work, runId + '.lock')
    while True:
        fh = open(path, 'a')
        try:
            fcntl.flock(fh, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            fh.close()
            return None
        try:
            if os.fstat(fh.fileno()).st_ino == os.stat(path).st_ino:
                return fh
        except FileNotFoundError:
            pass
        fh.close()  # its holder removed this file as it let it go: take the file there now


def releaseRow(lock):
    """Let a run's lock go; the file is removed first, so nobody takes a lock on a name that is gone."""
    try:
        os.unlink(lock.name)
    except FileNotFoundError:  # work/ removed by hand: runRow still must not raise
        pass
    lock.close()


def keepToResume(attempt, runId, keep):
    """The run folder an attempt (a work folder) left, moved to keep/<run id>/run with the attempt's row.json
    if its run saved a state to go on from (runner.takeKept); returns the state's name or None."""
    runDir = os.path.join(attempt, 'results', runId)
    state = killedRunState(runDir)
    if state is None or not os.path.isfile(os.path.join(attempt, 'row.json')):
        return None
    kept = os.path.join(keep, runId)
    shutil.rmtree(kept, ignore_errors=True)
    os.makedirs(kept)
    moveSynced(os.path.join(attempt, 'row.json'), os.path.join(kept, 'row.json'))
    moveSynced(runDir, os.path.join(kept, 'run'))
    return os.path.basename(state)


def keptState(keep, runId):
    """The state the run kept in keep/<run id> (keepToResume) goes on from, or None."""
    return killedRunState(os.path.join(keep, runId, 'run'))


def takeKept(keep, runId, row, results):
    """The run kept in keep/<run id> (keepToResume) moved to results/<run id> if it was made from this row
    (else removed: the row has changed); returns the name of the state it goes on from, or None."""
    kept = os.path.join(keep, runId)
    if not os.path.isdir(kept):
        return None
    try:
        with open(os.path.join(kept, 'row.json')) as fh:
            same = json.load(fh) == json.loads(json.dumps(row))
    except (OSError, ValueError):
        same = False
    state = keptState(keep, runId) if same else None
    if state is not None:
        os.makedirs(results, exist_ok=True)
        moveSynced(os.path.join(kept, 'run'), os.path.join(results, runId))
    shutil.rmtree(kept, ignore_errors=True)
    return os.path.basename(state) if state else None


def clearWork(work, keep=None):
    """Clear a study's work directory as the study starts: remove what attempts of dead runners left,
    keep the locks and the folders of the runs another runner still holds. With keep (a folder), a run
    that saved a state to go on from is moved there first (keepToResume). Returns a journal record
    of each attempt removed ({runId, status 'started', error, kept}): it started, its end was never
    recorded; kept: the name of the state it goes on from, or None."""
    os.makedirs(work, exist_ok=True)
    names = os.listdir(work)
    held = set()
    for n in names:
        if n.endswith('.lock'):
            lock = rowLock(work, n[:-len('.lock')])
            if lock is None:
                held.add(n[:-len('.lock')])
            else:
                releaseRow(lock)
    records = []
    for n in names:
        runId = n.rsplit('.', 1)[0]  # an attempt's folder is <run id>.<random letters>
        path = os.path.join(work, n)
        if os.path.isdir(path) and runId not in held:
            said = lastError(os.path.join(path, 'run.log'))
            state = keepToResume(path, runId, keep) if keep else None
            records.append({'runId': runId, 'status': 'started', 'kept': state, 'error': 'no end recorded: its runner '
                            'ended first (killed, or its machine went down)' + ('; its log ends: ' + said if said else '') + (
                                '; kept to go on from its %s' % state if state else '')})
            shutil.rmtree(path, ignore_errors=True)
    return records


def workDir(spec, shared, leader):
    """A fresh directory for the run with the table, the script and the packings it reads:
    (directory, table, script, packing directory, names of the packings it was given)."""
    if shared:
        base = os.path.join(spec['out'], 'work')
        os.makedirs(base, exist_ok=True)
        work = tempfile.mkdtemp(prefix=spec['runId'] + '.', dir=base)
    else:
        work = tempfile.mkdtemp(prefix='study-%s.' % spec['runId'])
    table = os.path.join(work, 'table')
    with open(table, 'w') as fh:
        fh.write(spec['tableText'])
    # the script the client read, wherever this runs: its own file if identical, else the copy sent
    script = spec['scriptPath']
    try:
        with open(script) as fh:
            same = fh.read() == spec['scriptText']
    except OSError:
        same = False
    if not same:
        script = os.path.join(work, os.path.basename(spec['scriptPath']))
        with open(script, 'w') as fh:
            fh.write(spec['scriptText'])
    if shared:
        return work, table, script, spec['packings'], set()
    pdir = os.path.join(work, 'packings')
    os.makedirs(pdir)
    sent = dict(spec['packingFiles'])
    sent.update((leader or {}).get('packings') or {})
    for name, data in sent.items():
        with open(os.path.join(pdir, name), 'wb') as fh:
            fh.write(data)
    return work, table, script, pdir, set(sent)


def stopRequested(spec):
    """A function telling whether the study was stopped: Ctrl-C here, or the Dask event of the study."""
    if not spec.get('stopEvent'):
        return STOP.is_set
    try:
        from distributed import Event
        event = Event(spec['stopEvent'])
    except Exception:
        return STOP.is_set
    asked = [0.0]  # the first call asks: a run does not start once the study is stopped

    def stopped():
        if time.time() - asked[0] < ASK_DASK:
            return False
        asked[0] = time.time()
        try:
            return event.is_set()
        except Exception:
            return False
    return stopped


def dieWithParent(parent):
    """preexec_fn of a run's yade: SIGTERM when the runner's thread that started it ends, killed
    too; at once if the runner (pid `parent`) died before this was set."""
    if PRCTL(PR_SET_PDEATHSIG, int(signal.SIGTERM), 0, 0, 0) != 0:
        raise OSError(ctypes.get_errno(), 'prctl(PR_SET_PDEATHSIG, SIGTERM)')
    if os.getppid() != parent:
        os.kill(os.getpid(), signal.SIGTERM)


def runYade(cmd, env, cwd, logPath, deadline, stopped, keepFds=()):
    """Run cmd with its output in logPath; kill it (and its children: its own process group) past
    the deadline or when stopped(). keepFds: descriptors it inherits (the run's lock). Should this
    process die first, the run dies with it: yade by its parent-death signal, what it started by the
    watchdog. Returns (exit code, None or 'timeout' or 'stopped')."""
    watchdog = subprocess.Popen([sys.executable, '-I', '-S', '-c', WATCHDOG, str(KILL_WAIT)], stdin=subprocess.PIPE,
                                stdout=subprocess.DEVNULL, start_new_session=True)
    try:
        with open(logPath, 'w') as log:
            proc = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL, env=env, cwd=cwd,
                                    start_new_session=True, pass_fds=keepFds,
                                    preexec_fn=functools.partial(dieWithParent, os.getpid()))
        watchdog.stdin.write(b'%d\n' % proc.pid)
        watchdog.stdin.flush()
        while True:
            try:
                return proc.wait(timeout=POLL), None
            except subprocess.TimeoutExpired:
                pass
            why = 'timeout' if deadline and time.time() > deadline else ('stopped' if stopped() else None)
            if why:
                for sig in (signal.SIGTERM, signal.SIGKILL):
                    try:
                        os.killpg(proc.pid, sig)
                    except ProcessLookupError:
                        break
                    try:
                        proc.wait(timeout=KILL_WAIT)
                        break
                    except subprocess.TimeoutExpired:
                        continue
                return proc.wait(), why
    finally:
        watchdog.stdin.close()  # the run is over: the watchdog kills what is left of its group, if anything
        watchdog.wait()


def command(spec, script, results, samples, resume=False):
    """The yade command line of a run: yade [--nice=N] -n -x SCRIPT, then the parameters the study sets
    (spec['sets'], the declaration's): where the run writes, its id, where prepared samples are stored
    (left out for an experiment without them), and with resume that it goes on with the killed run there."""
    sets = spec['sets']
    return [spec['yade']] + (['--nice=%d' % spec['nice']] if spec['nice'] is not None else []) + [
        '-n', '-x', script, '--' + sets['results'], results, '--' + sets['runId'], spec['runId']] + (
        ['--' + sets['sampleStore'], samples] if sets.get('sampleStore') else []) + (
        ['--' + sets['resume'], '1'] if resume else [])


def runRow(spec, leader=None):
    """Run one table row. spec (see Study.tasks): runId, line, row, tableText, tableName, scriptPath,
    scriptText, yade, nice, env, out, token, sets (the declaration's), packings, packingFiles,
    timeout [s], executor, ship, stopEvent. leader: the result of the run that built the packing this one needs (its new
    packings), or None. Returns a dict, status 'ok', 'failed', 'timeout', 'stopped' or 'elsewhere'
    (another runner holds the run's lock); None if the study was stopped before this run started."""
    runId, line = spec['runId'], spec['line']
    host = socket.gethostname()
    started = time.time()
    res = {'runId': runId, 'line': line, 'host': host, 'started': started, 'status': 'failed', 'rc': None, 'error': '',
           'shared': False, 'files': None, 'packings': {}, 'log': None, 'summary': None}
    work = lock = None
    try:
        stopped = stopRequested(spec)
        if stopped():
            return None
        shared = not spec.get('ship') and seesStudy(spec['out'], spec['token'])
        res['shared'] = shared
        if shared:
            lock = rowLock(os.path.join(spec['out'], 'work'), runId)
            if lock is None:
                held = os.path.join(spec['out'], 'work', runId + '.lock')
                res.update(status='elsewhere', finished=time.time(), wall=0.0,
                           error='running elsewhere: another runner holds ' + held)
                return res
        work, table, script, pdir, given = workDir(spec, shared, leader)
        results = os.path.join(work, 'results')
        resumes = shared and spec['sets'].get('resume')
        if resumes:
            writeAtomic(os.path.join(work, 'row.json'), json.dumps(spec['row']))   # what a kept run was made from
            res['resumedFrom'] = takeKept(os.path.join(spec['out'], KEEP), runId, spec['row'], results)
        cmd = command(spec, script, results, pdir, resume=bool(res.get('resumedFrom')))
        env = dict(os.environ)
        env.update(spec['env'])
        # the row's relative paths start from the folder of the table the study read, not from this copy's
        env.update({'YADE_BATCH': '%s:%d' % (table, line), 'DISPLAY': '', TABLE_DIR: os.path.dirname(spec['tableName'])})
        res['command'] = ' '.join('%s=%s' % kv for kv in sorted(spec['env'].items())) + ' YADE_BATCH=%s:%d ' % (table, line) + \
            ' '.join(shlex.quote(c) for c in cmd)
        logPath = os.path.join(work, 'run.log')
        code = codeSha1(spec['scriptText'])  # as the run starts, before yade imports the package
        rc, why = runYade(cmd, env, work, logPath, spec['timeout'] and started + spec['timeout'], stopped,
                          [lock.fileno()] if lock else [])
        finished = time.time()
        res.update(rc=rc, finished=finished, wall=finished - started)
        runDir = os.path.join(results, runId)
        res['summary'], unfinished = readSummary(runDir)
        ok = why is None and rc == 0 and res['summary'] is not None
        res['status'] = 'ok' if ok else (why or 'failed')
        if why == 'timeout':
            res['error'] = 'killed after the --timeout of %g s' % spec['timeout']
        elif why == 'stopped':
            res['error'] = 'stopped (the study was interrupted)'
        elif rc < 0:  # the OOM killer, a kill: the log's last line says only where it was
            res['error'] = 'killed by signal %d' % -rc
        elif rc == 0 and not ok:
            res['error'] = 'exit code 0 but ' + unfinished
        elif not ok:
            res['error'] = lastError(logPath) or 'exit code %d' % rc
        with open(logPath, 'a') as log:
            log.write(batchTrailer(runId, rc, 'OK' if ok else ('STOPPED' if why == 'stopped' else 'FAILED'),
                                   int(finished - started), res['command'], started, finished))
        if ok:
            with open(os.path.join(runDir, 'row.json'), 'w') as fh:
                json.dump({'line': line, 'row': spec['row'], 'table': spec['tableName'], 'tableSha1': sha1(spec['tableText']),
                           'script': spec['scriptPath'], 'codeSha1': code, 'host': host,
                           'executor': spec['executor'], 'command': res['command'], 'started': started,
                           'wallSeconds': finished - started, 'resumedFrom': res.get('resumedFrom')}, fh, indent=1)
        if resumes and why == 'stopped':
            state = keepToResume(work, runId, os.path.join(spec['out'], KEEP))
            if state:
                res['error'] += '; kept to go on from its %s' % state
        if shared:
            finalize(spec['out'], runId, res, runDir, logPath)
        else:
            # no shared file system: everything goes back to the client with the result
            with open(logPath) as fh:
                res['log'] = fh.read()
            res['files'] = readFiles(runDir) if os.path.isdir(runDir) else {}
            res['packings'] = {}
            for n in os.listdir(pdir):
                if n.endswith('.json') and n not in given:
                    with open(os.path.join(pdir, n), 'rb') as fh:
                        res['packings'][n] = fh.read()
    except Exception as e:  # a failure of the machinery is recorded like a failed run
        res['status'] = 'failed'
        res['error'] = 'study on %s: %s: %s' % (host, type(e).__name__, e)
        res['log'] = (res.get('log') or '') + traceback.format_exc()
        res.setdefault('finished', time.time())
        res['wall'] = res['finished'] - started
    finally:
        if work and os.path.isdir(work):
            shutil.rmtree(work, ignore_errors=True)
        if lock:
            releaseRow(lock)
    return res


def finalize(out, runId, res, runDir, logPath):
    """Move a run's output into the study: runs/<id>/ if it finished, failed/<id>/ if not; its log
    to logs/<id>.log. Synced renames within one file system, so a run directory is never half there,
    not even after a crash."""
    os.makedirs(os.path.join(out, 'logs'), exist_ok=True)
    moveSynced(logPath, os.path.join(out, 'logs', runId + '.log'))
    res['finalized'] = True
    failed = os.path.join(out, 'failed', runId)
    if res['status'] == 'stopped':
        return  # interrupted, not failed: redone next time, even with --skip-failed
    shutil.rmtree(failed, ignore_errors=True)
    if res['status'] == 'ok':
        final = os.path.join(out, 'runs', runId)
        os.makedirs(os.path.dirname(final), exist_ok=True)
        if readSummary(final)[0] is not None:
            res['duplicate'] = True  # a worker lost and its task rerun elsewhere: keep the first
        else:
            shutil.rmtree(final, ignore_errors=True)  # not a finished run (a cut summary.json): replaced
            moveSynced(runDir, final)
    elif os.path.isdir(runDir):
        os.makedirs(os.path.dirname(failed), exist_ok=True)
        moveSynced(runDir, failed)


def finalizeShipped(out, packings, res):
    """The client's half of a run done where the study directory is not visible: write what came back."""
    for name, data in (res.get('packings') or {}).items():
        if not os.path.exists(os.path.join(packings, name)):
            writeAtomic(os.path.join(packings, name), data)
    work = tempfile.mkdtemp(prefix=res['runId'] + '.', dir=os.path.join(out, 'work'))
    try:
        runDir = os.path.join(work, res['runId'])
        for rel, data in (res.get('files') or {}).items():
            p = os.path.join(runDir, rel)
            os.makedirs(os.path.dirname(p), exist_ok=True)
            with open(p, 'wb') as fh:
                fh.write(data)
        logPath = os.path.join(work, 'run.log')
        with open(logPath, 'w') as fh:
            fh.write(res.get('log') or '')
        finalize(out, res['runId'], res, runDir, logPath)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    res['files'] = res['packings'] = res['log'] = None  # not kept in memory
