"""One run of a study: one table row, run as yade-batch runs it,

    YADE_BATCH=table:line OMP_NUM_THREADS=1 yade -n -x SCRIPT --results DIR --runId ID --packingDir DIR

in a thread of the study (local) or on a Dask worker. A worker that sees the study directory (a
shared file system) writes the run there; one that does not gets the script, the table and the
packing with the task and sends the run's files back (:func:`finalizeShipped` writes them).
:func:`runRow` never raises: a failure is a result like any other.
"""
import json
import os
import re
import shlex
import shutil
import signal
import socket
import subprocess
import tempfile
import threading
import time
import traceback

from .files import codeSha1, readFiles, sha1, writeAtomic

# Set on Ctrl-C by the local executor: every running run kills its yade and returns.
STOP = threading.Event()
POLL = 0.2        # [s] how often a run checks its yade, the --timeout and STOP
ASK_DASK = 5.0    # [s] how often a run on a Dask worker asks whether the study was stopped
KILL_WAIT = 10.0  # [s] after SIGTERM, before SIGKILL


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


def failedLog(path):
    """True if the log ends a failed attempt (yade-batch's trailer says FAILED)."""
    try:
        with open(path, errors='replace') as fh:
            return '(FAILED)' in fh.read()
    except OSError:
        return False


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
    asked = [time.time()]

    def stopped():
        if time.time() - asked[0] < ASK_DASK:
            return False
        asked[0] = time.time()
        try:
            return event.is_set()
        except Exception:
            return False
    return stopped


def runYade(cmd, env, cwd, logPath, deadline, stopped):
    """Run cmd with its output in logPath; kill it (and its children: its own process group) past
    the deadline or when stopped(). Returns (exit code, None or 'timeout' or 'stopped')."""
    with open(logPath, 'w') as log:
        proc = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL, env=env, cwd=cwd,
                                start_new_session=True)
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


def runRow(spec, leader=None):
    """Run one table row. spec (see Study.tasks): runId, line, row, tableText, tableName, scriptPath,
    scriptText, yade, nice, env, out, token, packings, packingFiles, timeout [s], executor, ship,
    stopEvent. leader: the result of the run that built the packing this one needs (its new
    packings), or None. Returns a dict; status 'ok', 'failed', 'timeout' or 'stopped'."""
    runId, line = spec['runId'], spec['line']
    host = socket.gethostname()
    started = time.time()
    res = {'runId': runId, 'line': line, 'host': host, 'started': started, 'status': 'failed', 'rc': None, 'error': '',
           'shared': False, 'files': None, 'packings': {}, 'log': None, 'summary': None}
    work = None
    try:
        shared = not spec.get('ship') and seesStudy(spec['out'], spec['token'])
        res['shared'] = shared
        work, table, script, pdir, given = workDir(spec, shared, leader)
        results = os.path.join(work, 'results')
        cmd = [spec['yade']] + (['--nice=%d' % spec['nice']] if spec['nice'] is not None else []) + [
            '-n', '-x', script, '--results', results, '--runId', runId, '--packingDir', pdir]
        env = dict(os.environ)
        env.update(spec['env'])
        env.update({'YADE_BATCH': '%s:%d' % (table, line), 'DISPLAY': ''})
        res['command'] = ' '.join('%s=%s' % kv for kv in sorted(spec['env'].items())) + ' YADE_BATCH=%s:%d ' % (table, line) + \
            ' '.join(shlex.quote(c) for c in cmd)
        logPath = os.path.join(work, 'run.log')
        code = codeSha1(spec['scriptText'])  # as the run starts, before yade imports the package
        rc, why = runYade(cmd, env, work, logPath, spec['timeout'] and started + spec['timeout'], stopRequested(spec))
        finished = time.time()
        res.update(rc=rc, finished=finished, wall=finished - started)
        runDir = os.path.join(results, runId)
        if os.path.exists(os.path.join(runDir, 'summary.json')):
            with open(os.path.join(runDir, 'summary.json')) as fh:
                res['summary'] = json.load(fh)
        ok = why is None and rc == 0 and res['summary'] is not None
        res['status'] = 'ok' if ok else (why or 'failed')
        if why == 'timeout':
            res['error'] = 'killed after the --timeout of %g s' % spec['timeout']
        elif why == 'stopped':
            res['error'] = 'stopped (the study was interrupted)'
        elif not ok:
            res['error'] = lastError(logPath) or ('exit code %d, no summary.json' % rc)
        with open(logPath, 'a') as log:
            log.write(batchTrailer(runId, rc, 'OK' if ok else ('STOPPED' if why == 'stopped' else 'FAILED'),
                                   int(finished - started), res['command'], started, finished))
        if ok:
            with open(os.path.join(runDir, 'row.json'), 'w') as fh:
                json.dump({'line': line, 'row': spec['row'], 'table': spec['tableName'], 'tableSha1': sha1(spec['tableText']),
                           'script': spec['scriptPath'], 'codeSha1': code, 'host': host,
                           'executor': spec['executor'], 'command': res['command'], 'started': started,
                           'wallSeconds': finished - started}, fh, indent=1)
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
    return res


def finalize(out, runId, res, runDir, logPath):
    """Move a run's output into the study: runs/<id>/ if it finished, failed/<id>/ if not; its log
    to logs/<id>.log. Renames within one file system, so a run directory is never half there."""
    os.makedirs(os.path.join(out, 'logs'), exist_ok=True)
    os.replace(logPath, os.path.join(out, 'logs', runId + '.log'))
    res['finalized'] = True
    failed = os.path.join(out, 'failed', runId)
    if res['status'] == 'stopped':
        return  # interrupted, not failed: redone next time, even with --skip-failed
    shutil.rmtree(failed, ignore_errors=True)
    if res['status'] == 'ok':
        final = os.path.join(out, 'runs', runId)
        os.makedirs(os.path.dirname(final), exist_ok=True)
        if os.path.exists(final):
            res['duplicate'] = True  # a worker lost and its task rerun elsewhere: keep the first
        else:
            os.rename(runDir, final)
    elif os.path.isdir(runDir):
        os.makedirs(os.path.dirname(failed), exist_ok=True)
        os.rename(runDir, failed)


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
