"""Tests of ballast.study.executors with a stand-in for runner.runRow (no process starts): a run that
builds a packing goes before the runs waiting for it, which get its result, locally and through an
in-process Dask cluster; the executor the command line asks for, its options checked; stopped
(Ctrl-C), the result of the run it stopped goes to onDone (the journal), the runs queued do not start."""
import os
import signal
import threading
import time

import pytest

from ballast.study import process, runner
from ballast.study.executors import DaskExecutor, LocalExecutor, makeExecutor
from ballast.study.options import StudyError
from study_fakes import ctrlC, freePort  # noqa: F401 (ctrlC is a fixture)

# Debian's distributed 2022.12 with its tornado: not ours
pytestmark = pytest.mark.filterwarnings('ignore:make_current is deprecated:DeprecationWarning')
EVENTS = []  # (event, run id, leader packings); module-level: Dask finds runRow and this list by name
LOCK = threading.Lock()


def runRow(spec, leader):
    with LOCK:
        EVENTS.append(('start', spec['runId'], (leader or {}).get('packings')))
    time.sleep(0.05)
    with LOCK:
        EVENTS.append(('end', spec['runId'], None))
    return {'runId': spec['runId'], 'status': 'ok', 'packings': {'packing-of-' + spec['runId']: b'grains'}, 'files': None}


def tasks():
    """A builds the packing B and C need; D needs none."""
    return [{'spec': {'runId': r, 'line': n}, 'leader': lead} for n, (r, lead) in enumerate(
        [('A', None), ('B', 'A'), ('C', 'A'), ('D', None)], 2)]


def runAll(executor):
    EVENTS.clear()
    started, done = [], []
    executor.run(tasks(), lambda t, res: done.append(res['runId']), lambda t, quiet=False: started.append(t['spec']['runId']))
    assert sorted(started) == sorted(done) == ['A', 'B', 'C', 'D']
    order = [(e, r) for e, r, _ in EVENTS]
    for r in 'BC':
        assert order.index(('end', 'A')) < order.index(('start', r)), order  # after the leader, never before
        assert [p for e, x, p in EVENTS if (e, x) == ('start', r)] == [{'packing-of-A': b'grains'}]  # its packing
    assert [p for e, x, p in EVENTS if e == 'start' and x in 'AD'] == [None, None]


def test_local_executor_runs_the_leader_first_and_hands_its_packing_on():
    runAll(LocalExecutor(2, runRow=runRow))


def test_dask_executor_does_the_same_through_a_scheduler():
    distributed = pytest.importorskip('distributed')
    with distributed.LocalCluster(n_workers=1, threads_per_worker=2, processes=False, dashboard_address=None) as cluster:
        ex = DaskExecutor(cluster.scheduler_address, 10, runRow=runRow)
        assert ex.slots == 2 and ex.describe().startswith('1 workers, 2 threads')
        runAll(ex)


def stoppingRow(spec, leader):
    """A presses Ctrl-C and runs until the stop reaches it; B, queued behind it, must not start."""
    stopped = process.stopRequested(spec)
    if stopped():
        return None
    with LOCK:
        EVENTS.append(('start', spec['runId'], None))
    time.sleep(0.3)  # the executor is waiting for results by then
    os.kill(os.getpid(), signal.SIGINT)
    deadline = time.time() + 30  # a stop that never comes fails the test instead of hanging it
    while True:
        if stopped():
            return {'runId': spec['runId'], 'status': 'stopped', 'packings': {}, 'files': None}
        if time.time() > deadline:
            return {'runId': spec['runId'], 'status': 'never stopped', 'packings': {}, 'files': None}
        time.sleep(0.02)


@pytest.mark.parametrize('kind', ['local', 'dask'])
def test_a_stopped_study_hands_on_the_runs_it_stopped(kind, monkeypatch, ctrlC):
    EVENTS.clear()
    done = []
    twoRuns = [{'spec': {'runId': r, 'line': n}, 'leader': None} for n, r in enumerate('AB', 2)]
    try:
        if kind == 'local':
            with pytest.raises(KeyboardInterrupt):
                LocalExecutor(1, runRow=stoppingRow).run(twoRuns, lambda t, res: done.append(res), lambda t, quiet=False: None)
        else:
            distributed = pytest.importorskip('distributed')
            monkeypatch.setattr(process, 'ASK_DASK', 0.05)  # the workers are threads of this process
            with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=False, dashboard_address=None) as cluster:
                with pytest.raises(KeyboardInterrupt):
                    DaskExecutor(cluster.scheduler_address, 10, runRow=stoppingRow).run(
                        twoRuns, lambda t, res: done.append(res), lambda t, quiet=False: None)
    finally:
        process.STOP.clear()
    assert [(r['runId'], r['status']) for r in done] == [('A', 'stopped')]
    assert EVENTS == [('start', 'A', None)]


@pytest.mark.parametrize('kw, words', [
    ({'kind': 'local', 'scheduler': 'tcp://h:1'}, '--scheduler: only with --executor dask'),
    ({'kind': 'local', 'yade': '/no/yade'}, '--yade: /no/yade'),
    ({'kind': 'local', 'jobs': 0}, "--jobs: study: jobs = 0 is not allowed: expected an integer >= 1"),
    ({'kind': 'dask'}, '--scheduler: --executor dask needs the address'),
    ({'kind': 'dask', 'jobs': 2, 'scheduler': 'tcp://h:1'}, '--jobs: only with --executor local'),
    ({'kind': 'dask', 'schedulerFile': '/no/dask.json'}, '--scheduler-file: no such file: /no/dask.json'),
    ({'kind': 'dask', 'scheduler': 'tcp://127.0.0.1:%d' % freePort(), 'connectTimeout': 0.2}, 'no Dask scheduler answers'),
])
def test_the_executor_options_are_checked_naming_the_option(kw, words):
    with pytest.raises(StudyError, match=words):
        makeExecutor(**kw)


def test_local_executor_defaults_to_the_cores_of_this_machine():
    import os
    assert makeExecutor('local', yade='python3').jobs == len(os.sched_getaffinity(0))
