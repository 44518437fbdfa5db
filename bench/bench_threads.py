#!/usr/bin/python3
"""YADE's OpenMP threads on a cyclic experiment (issue 45, item 3; docs/performance.md, "Threads"): a saved state
reopened in `yade -n -j N` for each N, the same load cycles run in each, alternately, `--repeat` times; wall and CPU
seconds per step side by side and the wall ratio against -j1 in one JSON, with YADE's own timing of every engine
(O.timingEnabled: which loops the threads share and which stay serial). Run on an idle machine: a busy core makes
the threads wait on each other.

    /usr/bin/python3 bench/bench_threads.py [--experiment box] [--state docs/studies/qs-box-scaled/runs/
        qs-scaled-seed1-c20/state-end.yade.gz] [--cycles 1] [--threads 1 2] [--repeat 3] [--out FILE.json]

The triaxial specimen: --experiment triaxial --state docs/studies/triax-calib-e/runs/e-s1-c300/state-end.yade.gz
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_STATE = os.path.join(HERE, '..', 'docs', 'studies', 'qs-box-scaled', 'runs', 'qs-scaled-seed1-c20',
                             'state-end.yade.gz')
CYCLIC = ('box', 'oedometer', 'triaxial')   # the experiments with a load cycle to time
# what one child does in YADE: reopen the state in a scratch folder, time its next cycles (the experiment's own load)
CHILD = r'''
import importlib, json, sys, tempfile, time
from yade import O
state, cycles, name = sys.argv[1], int(sys.argv[2]), sys.argv[3]
module = importlib.import_module('ballast.experiments.%s.experiment' % name)
cls = next(c for c in vars(module).values() if isinstance(c, type) and getattr(c, 'NAME', None) == name)
exp = cls.reopen(state, results=tempfile.mkdtemp(prefix='bench_threads_'), runId='bench', progress=1e6)
O.timingEnabled = True
w, c, n = time.perf_counter(), time.process_time(), O.iter
exp.load(cycles)
w, c, n = time.perf_counter() - w, time.process_time() - c, O.iter - n
print('BENCH ' + json.dumps({'wall': w, 'cpu': c, 'steps': n, 'bodies': len(O.bodies), 'threads': O.numThreads,
                             'engines': {'%s:%s' % (type(e).__name__, getattr(e, 'label', '') or i): e.execTime * 1e-9
                                         for i, e in enumerate(O.engines)}}))
'''


def positive(text):
    if not text.isdigit() or int(text) < 1:
        raise argparse.ArgumentTypeError('%r; allowed: a whole number from 1' % text)
    return int(text)


def child(state, cycles, threads, experiment):
    """One timed run in `yade -j threads`: its BENCH record."""
    with tempfile.NamedTemporaryFile('w', suffix='.py', delete=False) as fh:
        fh.write(CHILD)
    env = dict(os.environ, OMP_NUM_THREADS=str(threads))
    try:
        r = subprocess.run(['yade', '-n', '-j', str(threads), '-x', fh.name, state, str(cycles),
                            experiment], capture_output=True,
                           text=True, env=env)
    finally:
        os.unlink(fh.name)
    lines = [line[6:] for line in r.stdout.splitlines() if line.startswith('BENCH ')]
    if r.returncode != 0 or not lines:
        sys.exit('bench_threads: yade -j %d failed (exit %d):\n%s' % (threads, r.returncode, r.stderr[-2000:]))
    return json.loads(lines[-1])


def main(argv=None):
    ap = argparse.ArgumentParser(prog='bench/bench_threads.py', description=__doc__.split('\n\n')[0])
    ap.add_argument('--experiment', choices=CYCLIC, default='box', help='the experiment that saved the state '
                    '(default box)')
    ap.add_argument('--state', default=None, help='a state the experiment saved (default for the box: the default '
                    'box at 3 Hz after 20 cycles under quasiStatic 1e-3, seed 1; the others have none)')
    ap.add_argument('--cycles', type=positive, default=1, help='load cycles timed in each run (default 1)')
    ap.add_argument('--threads', type=positive, nargs='+', default=[1, 2])
    ap.add_argument('--repeat', type=positive, default=3)
    ap.add_argument('--out', default=os.path.join(tempfile.gettempdir(), 'bench_threads.json'))
    a = ap.parse_args(argv)
    if a.state is None:
        if a.experiment != 'box':
            ap.error('--state: required with --experiment %s (the default state is a box\'s)' % a.experiment)
        a.state = DEFAULT_STATE
    if not os.path.isfile(a.state):
        ap.error('--state: %s: no such file' % a.state)
    runs = {n: [] for n in a.threads}
    for k in range(a.repeat):   # alternately, so a change of the machine's load touches every N alike
        for n in a.threads:
            runs[n].append(child(a.state, a.cycles, n, a.experiment))
            r = runs[n][-1]
            print('bench: -j%d run %d: %.2f us wall and %.2f us CPU a step (%d bodies)' % (
                n, k + 1, 1e6 * r['wall'] / r['steps'], 1e6 * r['cpu'] / r['steps'], r['bodies']), flush=True)
    def perStep(rs, key):
        return statistics.median(r[key] / r['steps'] for r in rs)
    base = perStep(runs[a.threads[0]], 'wall')
    out = {'experiment': a.experiment, 'state': os.path.relpath(a.state), 'cycles': a.cycles, 'repeat': a.repeat,
           'threads': {}}
    for n, rs in runs.items():
        wall = perStep(rs, 'wall')
        out['threads'][str(n)] = {
            'wallPerStep': wall, 'cpuPerStep': perStep(rs, 'cpu'), 'speedup': base / wall, 'bodies': rs[0]['bodies'],
            'steps': rs[0]['steps'],
            'engines': {e: statistics.median(r['engines'][e] / r['steps'] for r in rs) for e in rs[0]['engines']}}
        print('bench: -j%d median %.2f us wall a step, x%.2f against -j%d' % (n, 1e6 * wall, base / wall, a.threads[0]))
    with open(a.out, 'w') as fh:
        json.dump(out, fh, indent=1)
    print('bench: wrote %s' % a.out)


if __name__ == '__main__':
    main()
