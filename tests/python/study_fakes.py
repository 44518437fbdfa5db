"""Helpers of the ballast.study and ballast.analysis tests: a fabricated study directory
(fabricateStudy), and a stand-in for yade for the tests that need no simulation (test_study_runner.py,
test_study_study.py): it keeps the oedometer's command-line contract,

    fake-yade -n -x SCRIPT --results DIR --runId ID --packingDir DIR   (YADE_BATCH=table:line)

builds the packing its row needs when it is not stored, and writes DIR/ID/summary.json, fd.csv and
seen.json (what it was given, its niceness and its scheduling group's). The environment variable FAKE (a '!FAKE'
column of the table) makes it fail (exit 3, leaving a partial output), hang (with a child process; both pids in
pids.json, and in the file FAKE_PIDS names if set; a state to resume from saved first), end without a summary, with
a summary cut in half (exit 0 both), or be killed by SIGKILL mid-run."""
import json
import os
import signal
import socket

import pytest

FAKE_YADE = r'''#!/usr/bin/python3
import json, os, signal, subprocess, sys, time
from ballast.experiments import declaration

argv = sys.argv[1:]
script = argv[argv.index('-x') + 1]
opts = dict(zip(argv[argv.index('-x') + 2::2], argv[argv.index('-x') + 3::2]))
oedometer = declaration('oedometer')
# the row split by hand: ballast.tables.tableRow would boot YADE's reader, 0.5 s a fake run
table, line = os.environ['YADE_BATCH'].rsplit(':', 1)
with open(table) as fh:
    lines = fh.read().split('\n')
rows = [l.split() for l in lines if l.strip() and not l.startswith('#')]
cells = dict(zip([h[:-1] if h.endswith('!') else h for h in rows[0]], lines[int(line) - 1].split()))
p = dict(oedometer.check({k: v for k, v in cells.items() if not k.startswith('!') and k != 'description'}, text=True))
out = os.path.join(opts['--results'], opts['--runId'])
os.makedirs(out, exist_ok=('--resume' in opts))   # a run that resumes finds its folder
with open(os.path.join(out, 'seen.json'), 'w') as fh:
    json.dump({'argv': argv, 'script': open(script).read(), 'OMP_NUM_THREADS': os.environ.get('OMP_NUM_THREADS'),
               'packings': sorted(os.listdir(opts['--packingDir'])), 'niceness': os.nice(0),
               'groupNice': (open('/proc/self/autogroup').read().split()[-1]
                             if os.path.exists('/proc/self/autogroup') else None)}, fh)
mode = os.environ.get('FAKE', 'ok')
print('fake yade: run %s, mode %s' % (opts['--runId'], mode), flush=True)
if mode == 'fail':
    open(os.path.join(out, 'partial.txt'), 'w').close()
    print('RuntimeError: the fake failed on purpose')
    sys.exit(3)
if mode == 'hang':
    # a state saved to go on from, as an experiment that declares resume leaves it (ballast.runfiles.killedRunState)
    open(os.path.join(out, 'state-1.gz'), 'w').close()
    with open(os.path.join(out, 'run.json'), 'w') as fh:
        json.dump({'status': 'running', 'lastState': 'state-1.gz'}, fh)
    helper = subprocess.Popen(['sleep', '120'])
    # FAKE_PIDS: a copy that outlives the run's folder (a stopped run's is removed)
    for path in filter(None, [os.path.join(out, 'pids.json'), os.environ.get('FAKE_PIDS')]):
        with open(path + '.tmp', 'w') as fh:
            json.dump({'yade': os.getpid(), 'helper': helper.pid}, fh)
        os.replace(path + '.tmp', path)
    time.sleep(120)
if mode == 'nosummary':
    sys.exit(0)
if mode == 'truncated':
    with open(os.path.join(out, 'summary.json'), 'w') as fh:
        fh.write(json.dumps({'params': p, 'peakForce': 1000.})[:20])
    sys.exit(0)
if mode == 'killed':
    print('step 1200, t = 0.12 s', flush=True)  # a progress line: not why it ended
    os.kill(os.getpid(), signal.SIGKILL)
packing = os.path.join(opts['--packingDir'], oedometer.sampleKey(p))
if not os.path.exists(packing):
    with open(packing + '.tmp', 'w') as fh:
        json.dump({'key': {'seed': p['seed']}, 'builtBy': opts['--runId']}, fh)
    os.replace(packing + '.tmp', packing)
with open(packing) as fh:
    builtBy = json.load(fh)['builtBy']
with open(os.path.join(out, 'fd.csv'), 'w') as fh:
    fh.write('t,F,delta,nCrushed,nAbraded\n0,0,0,0,0\n0.1,%r,0.001,1,0\n' % (1000. * p['f']))
with open(os.path.join(out, 'summary.json'), 'w') as fh:
    json.dump({'params': p, 'peakForce': 1000. * p['f'] + p['seed'], 'deltaAtPeak': 1e-3 * p['seed'], 'nCrushed': p['seed'],
               'packingFile': packing, 'packingBuiltBy': builtBy}, fh)
'''


# (seed, Tc [s], delta at peak [m], crushed) of fabricateStudy; seed 3 at Tc = 0.01 and seeds 2-3 at 0.04 did not finish
RUNS = [(1, 0, 0.050, 10), (2, 0, 0.056, 14), (3, 0, 0.047, 9), (1, 1e-4, 0.040, 7), (2, 1e-4, 0.031, 3), (3, 1e-4, 0.052, 12),
        (1, 0.01, 0.022, 2), (2, 0.01, 0.025, 4), (1, 0.04, 0.020, 1)]
MISSING = [(3, 0.01), (2, 0.04), (3, 0.04)]


def runId(seed, tc, **more):
    """The run id fabricateStudy gives a run: seed=1,Tc=0.01[,more...]."""
    return ','.join('%s=%s' % kv for kv in [('seed', seed), ('Tc', tc)] + sorted(more.items()))


def fabricateStudy(d, runs=RUNS, missing=MISSING, more=None, params=True, code=('a' * 40,)):
    """An oedometer study directory as Study.run leaves it, without a simulation (fabricate): per finished run a
    summary.json (deltaAtPeak, deltaMax = 2 deltaAtPeak, peakForce, nCrushed, nAbraded, the parameters unless
    params=False), the code sha1s of `code` in turn. `more` adds columns (name -> value of the i-th run). Returns
    the directory."""
    rows = []
    for i, (seed, tc) in enumerate([r[:2] for r in runs] + missing):
        extra = sorted((k, str(v(i))) for k, v in (more or {}).items())
        rows.append([dict([('seed', str(seed)), ('Tc', str(tc))] + extra), None])
    for i, (seed, tc, delta, crushed) in enumerate(runs):
        s = {'deltaAtPeak': delta, 'deltaMax': 2 * delta, 'peakForce': 1.5e6, 'nCrushed': crushed, 'nAbraded': 0}
        if params:
            s['params'] = dict({'seed': seed, 'Tc': float(tc)}, **{k: float(v(i)) for k, v in (more or {}).items()})
        rows[i][1] = s
    return fabricate(d, rows, ['seed', 'Tc'] + list(more or {}), code=code, table='Tc.table')


def fabricate(d, rows, columns, experiment=None, code=('a' * 40,), table='study.table'):
    """A study directory as Study.run leaves it, without a simulation: study.json (the experiment's name unless
    None: a folder older than the name, read as the oedometer's; the table's `columns`) and per row of `rows`
    ([(cells, summary)] in table order, cells {column: text}, a run id 'name=value,...' of them; summary None: a
    row not finished) runs/<run id>/summary.json and row.json (the code sha1s of `code` in turn). Returns d."""
    os.makedirs(str(d), exist_ok=True)
    info = []
    for i, (cells, summary) in enumerate(rows):
        rid = ','.join('%s=%s' % kv for kv in cells.items())
        info.append({'line': i + 2, 'runId': rid, 'row': dict(cells)})
        if summary is None:
            continue
        run = os.path.join(str(d), 'runs', rid)
        os.makedirs(run)
        with open(os.path.join(run, 'summary.json'), 'w') as fh:
            json.dump(summary, fh)
        with open(os.path.join(run, 'row.json'), 'w') as fh:
            json.dump({'codeSha1': code[i % len(code)]}, fh)
    study = dict({'experiment': experiment} if experiment else {}, table=table, columns=list(columns), rows=info)
    with open(os.path.join(str(d), 'study.json'), 'w') as fh:
        json.dump(study, fh)
    return str(d)


# (seed, ft0 [Pa m], settlement [m], resilient [m], crushed, abraded) of fabricateBox: two realizations of one bed
BOX_RUNS = [(1, 3.5e4, 0.0021, 0.0003, 7, 2), (2, 3.5e4, 0.0035, 0.0005, 11, 0)]


def fabricateBox(d, runs=BOX_RUNS):
    """A box-test study directory (fabricate) whose runs' summaries hold the box's results: settlement, resilient,
    nCrushed, nAbraded of `runs`, and maxStressRatio 1.5, maxDamage 0, cpuSecondsPerCycle 2 s, cpuSeconds 2 s a
    cycle over 10 cycles; columns seed and ft0."""
    rows = [({'seed': str(seed), 'ft0': '%g' % ft0},
             {'experiment': 'box', 'cycles': 10, 'settlement': s, 'resilient': r, 'nCrushed': c, 'nAbraded': a,
              'maxStressRatio': 1.5, 'maxDamage': 0.0, 'cpuSecondsPerCycle': 2.0, 'cpuSeconds': 20.0,
              'params': {'seed': seed, 'ft0': ft0}}) for seed, ft0, s, r, c, a in runs]
    return fabricate(d, rows, ['seed', 'ft0'], 'box')


# (seed, grains, crushed, smallest and largest F/d^2 at a crush [Pa]) of fabricateSingleParticle
SINGLE_PARTICLE_RUNS = [(1, 4, 4, 1.1e8, 1.3e8), (2, 4, 3, 0.9e8, 1.6e8)]


def fabricateSingleParticle(d, runs=SINGLE_PARTICLE_RUNS):
    """A single-particle study directory (fabricate) whose summaries hold its results (n, nCrushed,
    forceOverD2Min, forceOverD2Max, inertiaRatioMax 0.001, cpuSeconds 0.5 s a grain); columns seed and n."""
    rows = [({'seed': str(seed), 'n': str(n)},
             {'n': n, 'nCrushed': c, 'nNotCrushed': n - c, 'forceOverD2Min': lo, 'forceOverD2Max': hi,
              'inertiaRatioMax': 0.001, 'cpuSeconds': 0.5 * n, 'params': {'seed': seed, 'n': n}})
            for seed, n, c, lo, hi in runs]
    return fabricate(d, rows, ['seed', 'n'], 'single_particle')


def writeFakeYade(directory):
    """The fake yade as an executable in `directory`; returns its path."""
    path = os.path.join(str(directory), 'fake-yade')
    with open(path, 'w') as fh:
        fh.write(FAKE_YADE)
    os.chmod(path, 0o755)
    return path


def freePort():
    """A TCP port of 127.0.0.1 nobody listens on (for a scheduler to start there, or to find none)."""
    with socket.socket() as s:
        s.bind(('127.0.0.1', 0))
        return s.getsockname()[1]


@pytest.fixture
def ctrlC():
    """SIGINT raises KeyboardInterrupt during the test, as it does in a terminal: a process started in the
    background by a shell without job control (a CI script's `cmd &`) inherits SIGINT ignored, and a test
    that presses Ctrl-C with os.kill would then wait for ever."""
    old = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, old)
