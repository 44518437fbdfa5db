"""Where the runs of a study run: on the cores of this machine (:class:`LocalExecutor`) or through a
Dask scheduler (:class:`DaskExecutor`). Both take the tasks of :meth:`Study.tasks` in order, a run
that builds a packing before the runs waiting for it, call onStart(task) and onDone(task, result),
and run each task with ``runRow(spec, leaderResult)`` (:func:`ballast.study.runner.runRow`, or any
function of that signature). Stopped (Ctrl-C), both hand the results of the runs it stopped to
onDone before they raise KeyboardInterrupt: every attempt is in the journal."""
import os
import re
import shutil
import time
import uuid

from . import process, runner
from .options import OPTIONS, StudyError, optionValue


class LocalExecutor:
    """jobs: runs at the same time (options.OPTIONS), a thread each waiting for its yade."""
    name = 'local'

    def __init__(self, jobs=None, runRow=runner.runRow):
        self.jobs = self.slots = optionValue('jobs', jobs) or len(os.sched_getaffinity(0))
        self.runRow = runRow

    def describe(self):
        return '%d parallel runs' % self.jobs

    def run(self, tasks, onDone, onStart):
        from concurrent.futures import FIRST_COMPLETED, ThreadPoolExecutor, wait
        process.STOP.clear()
        waiting = {}  # leader run id -> the tasks needing its packing
        for t in tasks:
            if t['leader']:
                waiting.setdefault(t['leader'], []).append(t)
        pool = ThreadPoolExecutor(self.jobs)
        running = {}

        def start(t, leaderRes):
            def job():
                if process.STOP.is_set():
                    return None
                onStart(t)
                return self.runRow(t['spec'], leaderRes)
            running[pool.submit(job)] = t

        try:  # a Ctrl-C while the runs are being queued stops them too
            for t in tasks:
                if not t['leader']:
                    start(t, None)
            while running:
                done, _ = wait(list(running), timeout=1.0, return_when=FIRST_COMPLETED)
                for fut in done:
                    t = running.pop(fut)
                    res = fut.result()
                    if res is not None:
                        onDone(t, res)
                        for d in waiting.pop(t['spec']['runId'], []):
                            start(d, res)
        except KeyboardInterrupt:
            process.STOP.set()  # every running run kills its yade, queued ones do not start
            for fut, t in running.items():
                if not fut.cancel():  # started: its result comes once its yade is killed
                    res = fut.result()
                    if res is not None:
                        onDone(t, res)
            raise
        finally:
            pool.shutdown(wait=True)


def leaderPackings(res):
    """What a run waiting for a leader's packing needs of the leader's result (None: the leader did
    not start, the study was stopped)."""
    return {'packings': (res or {}).get('packings') or {}}


def taskResult(fut, t):
    """The result of a Dask task of runRow; a failed run if the task failed in Dask, not in yade."""
    try:
        return fut.result()
    except Exception as e:  # e.g. KilledWorker: the worker died running it, too often
        return {'runId': t['spec']['runId'], 'line': t['spec']['line'], 'status': 'failed', 'rc': None, 'host': '?',
                'error': 'Dask: %s: %s' % (type(e).__name__, e), 'wall': None, 'shared': False, 'files': {}, 'packings': {},
                'log': 'the task failed in Dask, not in yade: %s: %s\n' % (type(e).__name__, e), 'summary': None}


class DaskExecutor:
    """address: the scheduler, e.g. tcp://127.0.0.1:8786 (or schedulerFile, the file dask-scheduler
    --scheduler-file wrote); connectTimeout [s] to wait for it. The workers need YADE and the same
    ballast package installed (they import ballast.study.runner), one thread each."""
    name = 'dask'

    def __init__(self, address=None, connectTimeout=OPTIONS['connectTimeout'].default, schedulerFile=None, runRow=runner.runRow):
        try:
            from distributed import Client
        except ImportError as e:
            raise StudyError('--executor dask: Dask distributed is not importable (%s); apt-get install python3-distributed' % e)
        what = '--scheduler-file' if schedulerFile else '--scheduler'
        connectTimeout = optionValue('connectTimeout', connectTimeout)
        if schedulerFile and not os.path.isfile(schedulerFile):  # Dask would wait for it forever
            raise StudyError('--scheduler-file: no such file: %s' % schedulerFile)
        try:
            self.client = Client(address, scheduler_file=schedulerFile, timeout='%gs' % connectTimeout, set_as_default=False)
        except (OSError, TimeoutError, ValueError, TypeError) as e:
            raise StudyError('%s: no Dask scheduler answers at %s within %g s (%s: %s)' % (
                what, schedulerFile or address, connectTimeout, type(e).__name__, e))
        self.slots = max(1, sum(self.client.nthreads().values()))
        self.runRow = runRow

    def describe(self):
        nt = self.client.nthreads()
        hosts = sorted(set(re.sub(r'^\w+://', '', a).rsplit(':', 1)[0] for a in nt))
        return '%d workers, %d threads, on %s' % (len(nt), sum(nt.values()),
                                                  ', '.join(hosts) or 'no machine yet (tasks wait for workers)')

    def processing(self):
        """Run ids the workers hold (running, or queued on a worker); None if Dask does not say."""
        try:
            keys = [k for ks in self.client.processing().values() for k in ks]
        except Exception:
            return None
        return [re.sub(r'^run-(.*)-[0-9a-f]{8}$', r'\1', str(k)) for k in keys]

    def run(self, tasks, onDone, onStart):
        from distributed import Event, as_completed
        session = uuid.uuid4().hex[:8]
        stopName = 'study-stop-' + session
        stop = Event(stopName, client=self.client)
        byId, packingsOf = {}, {}
        pending = {}  # future -> task: submitted, its result not yet handed to onDone
        try:  # a Ctrl-C while the tasks are being submitted stops the ones submitted so far too
            # leaders first and with priority: the runs waiting for their packings can then start sooner
            for t in sorted(tasks, key=lambda t: t['leader'] is not None):
                dep = None
                lead = t['leader']
                if lead:
                    # the waiting runs need only the leader's new packings, not all its files
                    if lead not in packingsOf:
                        packingsOf[lead] = self.client.submit(leaderPackings, byId[lead],
                                                              key='packings-%s-%s' % (lead, session), pure=False)
                    dep = packingsOf[lead]
                fut = self.client.submit(self.runRow, dict(t['spec'], stopEvent=stopName), dep, pure=False,
                                         key='run-%s-%s' % (t['spec']['runId'], session), priority=0 if lead else 10)
                pending[fut] = t
                byId[t['spec']['runId']] = fut
                onStart(t, quiet=True)
            for fut in as_completed(list(pending), loop=self.client.loop):
                t = pending.pop(fut)
                onDone(t, taskResult(fut, t))
                byId.pop(t['spec']['runId'], None)  # lets Dask forget results nobody needs any more
                fut.release()
        except KeyboardInterrupt:
            # the running tasks kill their yade within process.ASK_DASK seconds, the others do not start;
            # the runs stopped are attempts too: their results go to onDone, for as long as stopping takes
            stop.set()
            deadline = time.time() + process.ASK_DASK + process.KILL_WAIT + 5
            while pending and time.time() < deadline:
                for fut in [f for f in pending if f.done()]:
                    t = pending.pop(fut)
                    res = taskResult(fut, t)
                    if res is not None:  # None: it did not start
                        onDone(t, res)
                time.sleep(process.POLL)
            self.client.cancel(list(pending))
            raise
        finally:
            try:
                self.client.close()
            except Exception:
                pass


def makeExecutor(kind='local', jobs=None, scheduler=None, schedulerFile=None, connectTimeout=OPTIONS['connectTimeout'].default,
                 yade='yade'):
    """The executor scripts/study.py run asks for (kind 'local' or 'dask'), its options checked
    against each other; yade: the executable a local run starts."""
    if kind == 'local':
        if scheduler or schedulerFile:
            raise StudyError('--scheduler: only with --executor dask')
        if not shutil.which(yade):
            raise StudyError('--yade: %s is not an executable on this machine' % yade)
        return LocalExecutor(jobs)
    if jobs is not None:
        raise StudyError('--jobs: only with --executor local (Dask runs as many as its workers have threads)')
    if not (scheduler or schedulerFile):
        raise StudyError('--scheduler: --executor dask needs the address of a running scheduler, e.g. tcp://127.0.0.1:8786')
    return DaskExecutor(scheduler, connectTimeout, schedulerFile)
