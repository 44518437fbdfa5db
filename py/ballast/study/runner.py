"""One run of a study: one table row, run as yade-batch runs it,

    YADE_BATCH=table:line OMP_NUM_THREADS=1 yade -n -x SCRIPT --results DIR --runId ID --packingDir DIR

(the options are the parameters the experiment's declaration has the study set, `sets`; these are
the oedometer's) in a thread of the study (local) or on a Dask worker. A worker that sees the study
directory (a shared file system) writes the run there; one that does not gets the script, the table
and the prepared sample with the task and sends the run's files back (:func:`finalizeShipped`
writes them).
:func:`runRow` never raises: a failure is a result like any other.

A run does not outlive its runner, however that ends: its yade process is :mod:`.process`'s. A run
of the study directory holds a lock there for the whole attempt, and a run killed or stopped after it
saved a state is kept for the next attempt of its row to go on from: :mod:`.attempts`.
"""
import json
import os
import shlex
import shutil
import socket
import tempfile
import time
import traceback

from ..runfiles import codeSha1, moveSynced, readFiles, readSummary, sha1, writeAtomic
from ..tables import TABLE_DIR
from .attempts import KEEP, keepToResume, lastError, releaseRow, rowLock, takeKept
from .process import runYade, stopRequested


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


def command(spec, script, results, samples, resume=False):
    """The yade command line of a run: [nice -n N] yade -n -x SCRIPT, then the parameters the study sets
    (spec['sets'], the declaration's): where the run writes, its id, where prepared samples are stored
    (left out for an experiment without them), and with resume that it goes on with the killed run there.
    Niced by coreutils' nice: yade 2023.02a reads its own --nice option and never applies it."""
    sets = spec['sets']
    return (['nice', '-n', str(spec['nice'])] if spec['nice'] is not None else []) + [spec['yade']] + [
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
                          [lock.fileno()] if lock else [], nice=spec['nice'])
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
