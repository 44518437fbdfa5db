"""The attempts of a study's runs in its work directory (<out>/work/<run id>.<letters>/): the lock a run holds
there for the whole attempt (a runner started again beside a live one does not run the row a second time nor remove
its work folder), what an attempt's log says (why it failed, how far it has come), the work left by runners that
died, cleared as a study starts, and the runs killed or stopped after they saved a state, kept in
<out>/resume/<run id>/ with their row for the next attempt to go on from (an experiment that declares ``resume``)."""
import fcntl
import json
import os
import re
import shutil

from ..runfiles import killedRunState, moveSynced


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
PHASE_LINE = re.compile(r'\]\s+(\w+)\s+t=\S+ s\s+step \d+\s+dt=\S+ s([^\n]*)')  # any line of its phases


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
    phase line of its run.log: '24.8% of loading, ETA 23m32s', or a phase without an end known beforehand with its
    state ('settle: unbalanced 0.62 v_rms 0.018 m/s'); '' when there is none yet."""
    log = newestLog(work, runId)
    if log is None:
        return ''
    try:
        with open(log, 'rb') as fh:
            fh.seek(max(0, os.fstat(fh.fileno()).st_size - 4096))  # a log grows to megabytes: its tail only
            tail = fh.read().decode('utf-8', 'replace')
    except OSError:  # the attempt ended and its folder went while we looked
        return ''
    lines = PHASE_LINE.findall(tail)
    if not lines:
        return ''
    phase, rest = lines[-1]
    found = PROGRESS.search(rest)
    # a phase that ends on a condition (settling: the unbalanced force) has no ETA: its own line, not the last
    # phase's stale '98% ... ETA 1s'
    return '%s%% of %s, ETA %s' % found.groups() if found else '%s: %s' % (phase, ' '.join(rest.split()))


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


def rowHeld(work, runId):
    """Whether a live runner holds the run's lock (work/<run id>.lock): True, False (the file is there and nobody holds
    it: its runner died), or None (no lock file). Reads only: never creates the file."""
    path = os.path.join(work, runId + '.lock')
    try:
        fh = open(path, 'r')
    except FileNotFoundError:
        return None
    with fh:
        try:
            fcntl.flock(fh, fcntl.LOCK_SH | fcntl.LOCK_NB)
        except BlockingIOError:
            return True
        fcntl.flock(fh, fcntl.LOCK_UN)
        return False


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
