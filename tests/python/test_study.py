"""End-to-end tests of scripts/study.py and scripts/aggregate.py (the command lines over
ballast.study; each module has its own test_study_<module>.py): a tiny study (two very short runs
of studies/ci.table and a row whose stored packing is damaged, a failure only the run finds) run on
this machine's cores AND through a real Dask scheduler with two workers on 127.0.0.1, started here
and stopped at the end.

Everything runs as the user runs it: the scripts as subprocesses, each with a bounded timeout.
SCRIPT (default scripts/oedometer.py) is the oedometer they run."""
import csv
import fcntl
import json
import math
import os
import shutil
import signal
import subprocess
import time

import pytest

from ballast.oedometer.parameters import check, packingKey
from study_fakes import freePort

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PY = '/usr/bin/python3'
STUDY = os.path.join(ROOT, 'scripts', 'study.py')
AGGREGATE = os.path.join(ROOT, 'scripts', 'aggregate.py')
CI_TABLE = os.path.join(ROOT, 'studies', 'ci.table')
ENV = dict(os.environ, OMP_NUM_THREADS='1')
RUN_TIMEOUT = 100  # [s] one study.py invocation; the runs take a few seconds each
SCRIPT = os.environ.get('STUDY_TEST_SCRIPT', os.path.join(ROOT, 'scripts', 'oedometer.py'))
GOOD = ['seed=1,f=200', 'seed=2,f=200']
BAD = 'seed=3,f=200'  # its stored packing is damaged: the run fails, the study does not
# summary.json entries that must agree whichever executor ran the row
COMPARED = ['peakForce', 'deltaAtPeak', 'deltaMax', 'deltaFinal', 'nCrushed', 'nAbraded', 'volumeLost', 'massFinal', 'nSpheresFinal']

pytestmark = [pytest.mark.skipif(shutil.which('yade') is None, reason='needs yade'),
              # Debian's distributed 2022.12 with its tornado: not ours
              pytest.mark.filterwarnings('ignore:make_current is deprecated:DeprecationWarning')]


def tinyTable(path, f='200'):
    """studies/ci.table cut to its f=200 rows (seeds 1 and 2) plus the same row with seed 3 (and f
    as given); returns that row's cells."""
    with open(CI_TABLE) as fh:
        lines = [l.rstrip('\n') for l in fh]
    body = [l for l in lines if l.strip() and not l.lstrip().startswith('#')]
    head = body[0].split()
    names = [h.rstrip('!') for h in head]
    rows = [l.split() for l in body[1:] if l.split()[names.index('f')] == '200']
    assert len(rows) == 2, 'studies/ci.table should have f=200 rows for seeds 1 and 2'
    third = list(rows[0])
    third[names.index('seed')], third[names.index('f')] = '3', f
    with open(path, 'w') as fh:
        fh.write('# test_study.py: from studies/ci.table\n' + ' '.join(head) + '\n')
        for r in rows + [third]:
            fh.write(' '.join(r) + '\n')
    return dict(zip(names, third))


def damagePacking(row, packings):
    """A stored packing cut short (a full disk, a killed copy) for this row: the study sees it stored,
    only the run that reads it finds it damaged."""
    os.makedirs(packings, exist_ok=True)
    with open(os.path.join(packings, packingKey(check(row, text=True))[1]), 'w') as fh:
        fh.write('{"key": {"seed": 3}, "grains": [[0.01, 0.0')


def run(args, timeout=RUN_TIMEOUT):
    """Run a script; past the timeout it gets SIGTERM, on which study.py kills its yade runs (they
    are in their own process groups, a plain kill would leave them running), then SIGKILL."""
    t0 = time.time()
    p = subprocess.Popen([PY] + args, env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    try:
        out, _ = p.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        p.terminate()
        try:
            out, _ = p.communicate(timeout=30)
        except subprocess.TimeoutExpired:
            p.kill()
            out, _ = p.communicate()
        pytest.fail('%s did not finish in %d s:\n%s' % (' '.join(args), timeout, out))
    p.stdout_text, p.seconds = out, time.time() - t0
    return p


def daskCommand(name):
    exe = shutil.which('dask-' + name)
    return [exe] if exe else [PY, '-m', 'distributed.cli.dask_' + name]


def stop(procs):
    for p in procs:
        if p.poll() is None:
            try:
                os.killpg(p.pid, signal.SIGTERM)
            except ProcessLookupError:
                pass
    for p in procs:
        try:
            p.wait(timeout=15)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            p.wait(timeout=5)


@pytest.fixture(scope='module')
def cluster(tmp_path_factory):
    """A Dask scheduler and two one-thread workers on loopback."""
    d = tmp_path_factory.mktemp('dask')
    port = freePort()
    address = 'tcp://127.0.0.1:%d' % port
    procs = []
    logs = []

    def start(cmd, name):
        log = open(d / (name + '.log'), 'w')
        logs.append(log)
        # own process group: stopping it stops the nanny's worker processes too
        procs.append(subprocess.Popen(cmd, cwd=d, env=ENV, stdout=log, stderr=subprocess.STDOUT, start_new_session=True))

    try:
        start(daskCommand('scheduler') + ['--host', '127.0.0.1', '--port', str(port), '--no-dashboard'], 'scheduler')
        for k in range(2):
            start(daskCommand('worker') + [address, '--nthreads', '1', '--nworkers', '1', '--host', '127.0.0.1', '--no-dashboard',
                                           '--local-directory', str(d / ('w%d' % k)), '--name', 'w%d' % k], 'worker%d' % k)
        Client = pytest.importorskip('distributed').Client
        deadline = time.time() + 60
        client = None
        while time.time() < deadline:
            try:
                client = client or Client(address, timeout='5s', set_as_default=False)
                if len(client.nthreads()) == 2:
                    break
            except OSError:
                pass
            assert all(p.poll() is None for p in procs), 'a Dask process died; see %s' % d
            time.sleep(0.5)
        else:
            pytest.fail('the Dask scheduler and its two workers did not come up in 60 s; logs in %s' % d)
        client.close()
        yield address
    finally:
        stop(procs)
        for log in logs:
            log.close()


@pytest.fixture(scope='module')
def study(tmp_path_factory, cluster):
    """The tiny study run locally, through Dask (sharing the local study's packings, as the
    default --packings does for studies side by side), through Dask with --ship and packings of
    its own, and locally again."""
    d = tmp_path_factory.mktemp('study')
    table = d / 'tiny.table'
    third = tinyTable(table)
    damagePacking(third, d / 'packings')  # the packings of the local and the Dask study
    damagePacking(third, d / 'ship-packings')
    out = {'dir': d, 'table': table, 'local': d / 'local', 'dask': d / 'dask', 'ship': d / 'ship'}
    common = ['--script', SCRIPT, '--timeout', '90', '--progress', '10']
    out['run1'] = run([STUDY, 'run', str(table), '--out', str(out['local']), '--jobs', '2'] + common)
    out['runDask'] = run([STUDY, 'run', str(table), '--out', str(out['dask']), '--executor', 'dask', '--scheduler', cluster] + common)
    # as on machines without a shared file system: script, table and packings go with the task,
    # the results come back through Dask; with packings of its own, built again on the workers
    out['runShip'] = run([STUDY, 'run', str(table), '--out', str(out['ship']), '--executor', 'dask', '--scheduler', cluster,
                          '--ship', '--packings', str(d / 'ship-packings')] + common)
    out['mtimes'] = {r: os.path.getmtime(out['local'] / 'runs' / r / 'summary.json') for r in GOOD
                     if (out['local'] / 'runs' / r / 'summary.json').exists()}
    out['run2'] = run([STUDY, 'run', str(table), '--out', str(out['local']), '--jobs', '2', '--script', SCRIPT, '--timeout', '90'])
    return out


def summary(d, rid):
    with open(d / 'runs' / rid / 'summary.json') as fh:
        return json.load(fh)


def statusRows(d):
    with open(d / 'status.csv', newline='') as fh:
        return {r['runId']: r for r in csv.DictReader(fh)}


@pytest.mark.parametrize('executor', ['local', 'dask', 'ship'])
def test_runs_finish_and_the_failing_run_fails_alone(study, executor):
    p = study[{'local': 'run1', 'dask': 'runDask', 'ship': 'runShip'}[executor]]
    d = study[executor]
    assert p.returncode == 1, p.stdout_text  # 1: some run failed
    st = statusRows(d)
    for rid in GOOD:
        assert (d / 'runs' / rid / 'summary.json').exists(), p.stdout_text
        assert (d / 'runs' / rid / 'fd.csv').exists()
        assert st[rid]['status'] == 'finished'
        assert 'status  : 0 (OK)' in (d / 'logs' / (rid + '.log')).read_text()
        with open(d / 'runs' / rid / 'row.json') as fh, open(d / 'study.json') as fs:
            assert json.load(fh)['codeSha1'] == json.load(fs)['codeSha1']  # the same code here and on the workers
    # the failing run: recorded with its log, which says why
    assert st[BAD]['status'] == 'failed' and st[BAD]['exitCode'] not in ('', '0'), st[BAD]
    log = (d / 'logs' / (BAD + '.log')).read_text()
    assert '(FAILED)' in log and 'Error' in st[BAD]['error'] and st[BAD]['error'] in log, st[BAD]
    assert not (d / 'runs' / BAD).exists()
    assert 'FAILED ' + BAD in p.stdout_text and '2 ok, 1 failed' in p.stdout_text


@pytest.mark.parametrize('other', ['dask', 'ship'])
def test_same_row_same_result_on_both_executors(study, other):
    for rid in GOOD:
        a, b = summary(study['local'], rid), summary(study[other], rid)
        paths = ('results', 'packingDir', 'runId')  # where each executor worked; not the physics
        assert {k: v for k, v in a['params'].items() if k not in paths} == {k: v for k, v in b['params'].items() if k not in paths}
        assert os.path.basename(a['packingFile']) == os.path.basename(b['packingFile'])  # same seed, same packing parameters
        if other == 'ship':  # built again on a worker, yet the same grains
            with open(a['packingFile']) as fa, open(study['dir'] / 'ship-packings' / os.path.basename(b['packingFile'])) as fb:
                assert json.load(fa)['grains'] == json.load(fb)['grains']
        diff = {k: (a[k], b[k]) for k in COMPARED if a[k] != b[k]}
        assert not diff, rid
        assert a['stepsByPhase']['settle'] == b['stepsByPhase']['settle']
        assert a['stepsByPhase']['load'] == b['stepsByPhase']['load']
        fa = (study['local'] / 'runs' / rid / 'fd.csv').read_bytes()
        assert fa == (study[other] / 'runs' / rid / 'fd.csv').read_bytes()


def test_second_invocation_skips_finished_runs(study):
    p = study['run2']
    assert '2 finished before (skipped), 1 to run' in p.stdout_text, p.stdout_text
    for rid in GOOD:
        assert os.path.getmtime(study['local'] / 'runs' / rid / 'summary.json') == study['mtimes'][rid]
    assert 'FAILED ' + BAD in p.stdout_text  # unfinished: tried again
    assert p.returncode == 1
    journal = [json.loads(l) for l in (study['local'] / 'journal.jsonl').read_text().splitlines()]
    assert [j['runId'] for j in journal].count(GOOD[0]) == 1
    assert [j['runId'] for j in journal].count(BAD) == 2


def test_status_says_what_finished_failed_and_how_far_a_started_run_has_come(study, tmp_path):
    d = tmp_path / 'copy'
    shutil.copytree(study['local'], d)
    shutil.rmtree(d / 'runs' / GOOD[1])   # as if it had not finished: started, its attempt in work/
    attempt = d / 'work' / (GOOD[1] + '.abc123')
    attempt.mkdir(parents=True)
    (attempt / 'run.log').write_text('[oedometer 12.0s] load  t=0.1 s  step 100  dt=1e-06 s   42.5% of loading  ETA 3m10s\n')
    lock = open(d / 'work' / (GOOD[1] + '.lock'), 'a')   # its runner alive: holding the row's lock
    fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
    p = run([STUDY, 'status', str(d)])
    assert p.returncode == 0, p.stdout_text
    lines = p.stdout_text.splitlines()
    assert lines[0].endswith('3 rows: 1 failed, 1 finished, 1 todo'), lines
    assert lines[1].startswith('  failed: %s: ' % BAD)
    assert lines[2].startswith('  running: %s: 42.5%% of loading, ETA 3m10s, its log written ' % GOOD[1]), lines
    lock.close()   # its runner killed: the lock file stays, nobody holds it (it said "started" before)
    lines = run([STUDY, 'status', str(d)]).stdout_text.splitlines()
    assert lines[2].startswith('  killed: %s: its runner ended without an end recorded' % GOOD[1]), lines


def test_aggregate_mean_and_std_by_hand(study, tmp_path):
    out = tmp_path / 'agg'
    p = run([AGGREGATE, str(study['local']), '--out', str(out), '--param', 'f'], timeout=60)  # f=200 in every row
    assert p.returncode == 0, p.stdout_text
    assert all((out / f).stat().st_size > 1000 for f in ('fd_curves.png', 'response.png', 'checks.png'))
    d = [summary(study['local'], r)['deltaAtPeak'] for r in GOOD]
    m = (d[0] + d[1]) / 2
    s = math.sqrt(((d[0] - m)**2 + (d[1] - m)**2) / (2 - 1))  # sample standard deviation
    with open(out / 'stats.csv', newline='') as fh:
        rows = list(csv.DictReader(fh))
    assert len(rows) == 1 and rows[0]['f'] == '200' and rows[0]['n'] == '2'  # the failed run is left out
    assert float(rows[0]['deltaAtPeak_mean [m]']) == pytest.approx(m, rel=1e-12)
    assert float(rows[0]['deltaAtPeak_std [m]']) == pytest.approx(s, rel=1e-12)
    c = [summary(study['local'], r)['nCrushed'] for r in GOOD]
    assert float(rows[0]['nCrushed_mean [-]']) == pytest.approx(sum(c) / 2)
    with open(out / 'runs.csv', newline='') as fh:
        runs = {r['runId']: r for r in csv.DictReader(fh)}
    assert set(runs) == set(GOOD)
    assert float(runs[GOOD[0]]['peakForce [N]']) == summary(study['local'], GOOD[0])['peakForce']


def test_bad_command_line_is_refused_before_any_work(tmp_path):
    table = tmp_path / 't.table'
    tinyTable(table)
    cases = [
        ([STUDY, 'run', str(tmp_path / 'missing.table')], 'TABLE'),
        ([STUDY, 'run', str(table), '--executor', 'dask'], '--scheduler'),
        ([STUDY, 'run', str(table), '--jobs', '0'], '--jobs'),
        ([STUDY, 'run', str(table), '--lines', '2-x'], '--lines'),
        ([STUDY, 'run', str(table), '--timeout', '-5'], '--timeout'),
        ([STUDY, 'run', str(table), '--time', '5'], '--time'),  # no abbreviations
        ([STUDY, 'run', str(table), '--experiment', 'sleeper'], "--experiment: invalid choice: 'sleeper'"),
        ([AGGREGATE, str(tmp_path / 'nothing')], 'STUDY'),
    ]
    for args, name in cases:
        p = run(args + ['--out', str(tmp_path / 'o')] if args[0] == STUDY else args, timeout=30)
        assert p.returncode == 2 and name in p.stdout_text, (args, p.stdout_text)
    assert not (tmp_path / 'o' / 'runs').exists()  # nothing started
    # a column that is no parameter of the oedometer is named before anything runs
    bad = tmp_path / 'b.table'
    bad.write_text('seed fq\n1 2\n')
    p = run([STUDY, 'run', str(bad), '--out', str(tmp_path / 'o')], timeout=30)
    assert p.returncode == 2 and 'fq' in p.stdout_text


def test_the_script_is_the_experiments_own_by_default(tmp_path):
    # no --script: the oedometer's declaration names scripts/oedometer.py of this repository, which exists
    table = tmp_path / 't.table'
    tinyTable(table)
    p = run([STUDY, 'run', str(table), '--dry-run', '--out', str(tmp_path / 'o')], timeout=30)
    assert p.returncode == 0 and p.stdout_text.count('to run') == 3, p.stdout_text


def test_a_value_out_of_range_is_refused_before_any_run(tmp_path):
    table = tmp_path / 'f.table'
    tinyTable(table, f='-1')  # the third row, on line 5
    p = run([STUDY, 'run', str(table), '--out', str(tmp_path / 'o'), '--script', SCRIPT], timeout=30)
    assert p.returncode == 2, p.stdout_text
    assert 'f.table:5: column f, value -1' in p.stdout_text and 'a finite number > 0' in p.stdout_text, p.stdout_text
    assert not (tmp_path / 'o').exists()  # no run started, no study directory made
