"""A run's folder and its states: <results>/<run id>/, created when first needed and never reused, run.json
(the run's status), and the check of a state file before YADE meets it."""
import gzip
import json
import os
import time
import zlib

from yade import O

from .. import runtime
from ..names import runDirName
from ..runfiles import writeAtomic

STATUS_FILE = 'run.json'


class StateFileError(RuntimeError):
    """A state file that cannot be loaded: the message names the file and the cause, in one line."""


def checkStateFile(path, who='reopen'):
    """Raise StateFileError naming `path` and what is wrong with it, before O.load meets it (YADE's own errors
    name neither: 'gzip error', a bare MemoryError). Reads a gzip state through to its end (its CRC)."""
    def bad(why):
        raise StateFileError('%s: %s is not a loadable state: %s' % (who, path, why))
    if not os.path.isfile(path):
        raise FileNotFoundError('%s: no such state file: %s' % (who, path))
    size = os.path.getsize(path)
    if size == 0:
        bad('the file is empty (0 bytes: a save that was cut off?)')
    with open(path, 'rb') as fh:
        magic = fh.read(2)
    if path.endswith('.gz'):
        if magic != b'\x1f\x8b':
            bad('not gzip data (the name ends in .gz, the first bytes are %r)' % magic)
        try:
            with gzip.open(path, 'rb') as fh:
                head = fh.read(64)
                while fh.read(1 << 22):
                    pass
        except EOFError:
            bad('the gzip data is cut short (%d bytes: a save that was cut off?)' % size)
        except (OSError, zlib.error) as e:
            bad('damaged gzip data (%s)' % e)
    elif path.endswith('.xml'):
        with open(path, 'rb') as fh:
            head = fh.read(64)
    else:
        return
    if not (head.lstrip().startswith(b'<?xml') or b'serialization::archive' in head):
        bad('its content is not a YADE state (neither XML nor a boost archive: it starts with %r)' % head[:16])


TEMPORARY_PREFIX = '.tmp-'   # a state being written (Experiment.save): .tmp-<pid>-<name>, renamed when whole


def resumableState(folder, preferLast=True):
    """The state a killed run in `folder` goes on from: (path, what was wrong with the obvious one, or None), or
    (None, why not). The obvious one is run.json's lastState (preferLast; else the newest); when run.json is damaged
    or names none, or that state is damaged (checkStateFile), the newest intact state-*.yade.gz of the folder (by
    time). A finished run (run.json
    'finished', or summary.json beside no 'running') is not resumed. Temporary files of a save a kill cut off are
    removed."""
    from ..runfiles import runStatus
    if not os.path.isdir(folder):
        return None, 'no such folder'
    for name in os.listdir(folder):
        if name.startswith(TEMPORARY_PREFIX):
            os.remove(os.path.join(folder, name))
    doc = runStatus(folder)
    status = doc.get('status') if doc else None
    if status == 'finished' or (status != 'running' and os.path.exists(os.path.join(folder, 'summary.json'))):
        return None, 'the run finished'
    problems = []
    if doc is None:
        problems.append('run.json is missing or damaged')
    last = os.path.basename(doc['lastState']) if doc and isinstance(doc.get('lastState'), str) else None
    if doc is not None and last is None:
        problems.append('run.json names no last state')
    states = [n for n in os.listdir(folder) if n.startswith('state-') and n.endswith('.yade.gz')]
    order = sorted(states, key=lambda n: os.path.getmtime(os.path.join(folder, n)), reverse=True)
    if last in order and preferLast:
        order.remove(last)
        order.insert(0, last)
    elif last is not None:
        problems.append('its last state %s is not there' % last)
    for name in order:
        path = os.path.join(folder, name)
        try:
            checkStateFile(path, 'resume')
        except StateFileError as e:
            problems.append(str(e).split(': ', 1)[1])
            continue
        return path, ('; '.join(problems) + ': going on from %s' % name) if problems else None
    return None, '; '.join(problems + ['no intact state in it'])


def processAlive(pid):
    """True if pid (an int) is a live process of this machine other than this one."""
    if not isinstance(pid, int) or pid <= 0 or pid == os.getpid():
        return False
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:   # alive, another user's
        return True
    return True


@runtime.persistent('RunDirectory')
class RunDirectory:
    """<results>/<run id>/, created atomically when first needed; an existing one is never reused (a
    suffix -2, -3, ...). readOnly: never created (a reopened run that is only inspected)."""

    def __init__(self, results, runId, readOnly=False):
        self.results, self.wanted, self.readOnly = results, runId, readOnly
        self.runId = self.path = self.previous = None
        self.source = None   # the state file a reopened run goes on from (its provenance in run.json)

    def create(self):
        """The folder's path, made now if it is not yet."""
        if self.path is not None:
            return self.path
        if self.readOnly:
            raise RuntimeError('this run was reopened read-only (readOnly=True): it writes no files; reopen it with '
                               'readOnly=False to go on')
        rid = runDirName(self.wanted or O.tags['d.id'])
        os.makedirs(self.results, exist_ok=True)
        for k in range(1, 10000):
            name = rid if k == 1 else '%s-%d' % (rid, k)
            path = os.path.join(self.results, name)
            try:
                os.mkdir(path)
            except FileExistsError:
                continue
            self.runId, self.path = name, path
            return path
        raise RuntimeError('no free run directory for %s in %s' % (rid, self.results))

    def file(self, name):
        return os.path.join(self.create(), name)

    def goOnIn(self, path):
        """A killed run that goes on (Experiment.resumeKilled) writes into its own folder, not a new one."""
        self.path, self.runId = path, os.path.basename(path)

    def writeStatus(self, status, **info):
        """run.json: the status ('running', 'finished') and what else the experiment says, written atomically."""
        path = self.file(STATUS_FILE)
        doc = {}
        if os.path.exists(path):
            with open(path) as fh:
                doc = json.load(fh)
        doc.update(info, status=status, time=time.strftime('%Y-%m-%d %H:%M:%S'))
        writeAtomic(path, json.dumps(doc, indent=1) + '\n')

    def state(self):
        return {'results': self.results, 'wanted': self.wanted, 'runId': self.runId, 'path': self.path}

    @classmethod
    def fromState(cls, s, ref=None):
        """A run that goes on never writes into the folder of the run it continues: a new one, named after it."""
        d = cls(s['results'], s['runId'] or s['wanted'])
        d.previous = s['path']
        return d
