"""Where the every-step crushing check's time goes (issue 25, item 6; docs/performance.md, "The every-step
check"), inside the simulation loop: the stored default packing at the start of loading, the same steps
run again and again from a state saved in memory, each variant adding one more piece of the check in a
callback every step, rounds interleaved so that a disturbance of the machine hits all alike:

    plain   the oedometer's engines, the crushing engine dead
    pass    + a PyRunner whose command is 'pass' (YADE's cost of calling Python at all)
    noop    + the package's dispatcher calling an empty method (ballast.runtime)
    bst     + YADE's utils.bodyStressTensors()
    conv    + that list read into one array in C++ (ballast.matricesToArray)
    fire    + the crushing engine's whole check (BallastCrushEngine.fire, cached reads forgotten)

    yade -n -x bench/bench_every_step.py [--seed 1] [--steps 1500] [--repeat 3] [--out FILE.json]
"""
import argparse
import json
import os
import statistics
import sys
import tempfile
import time

from yade import O, PyRunner, utils

from ballast import _ballast, harvest, runtime
from ballast.engines import BallastCrushEngine
from ballast.oedometer import Oedometer

VARIANTS = ('plain', 'pass', 'noop', 'bst', 'conv', 'fire')


class Piece:
    """The callback of a variant: the pieces of the check up to its own."""

    def __init__(self, kind, engine):
        self.kind, self.engine = kind, engine

    def fire(self):
        if self.kind == 'bst':
            utils.bodyStressTensors()
        elif self.kind == 'conv':
            _ballast.matricesToArray(utils.bodyStressTensors())
        elif self.kind == 'fire':
            harvest.invalidate()
            self.engine.fire()


def main(argv):
    ap = argparse.ArgumentParser(prog='bench/bench_every_step.py', description=__doc__.split('\n\n')[0])
    ap.add_argument('--seed', type=int, default=1)
    ap.add_argument('--steps', type=int, default=1500)
    ap.add_argument('--repeat', type=int, default=3)
    ap.add_argument('--packingDir', default=os.path.join('results', 'packings'))
    ap.add_argument('--out', default=os.path.join(tempfile.gettempdir(), 'bench_every_step.json'))
    a = ap.parse_args(argv)
    run = Oedometer(seed=a.seed, results=tempfile.mkdtemp(prefix='bench_every_step_'), packingDir=a.packingDir,
                    progress=60, samples=100)
    run.prepare()
    run.startLoading()
    out = run.outputs
    O.engines = [e for e in O.engines if e.label not in (out.RECORDER, out.CHECKLOG, out.VTK)]
    O.run(500, True)
    O.saveTmp('everyStep')
    times = {k: [] for k in VARIANTS}
    for _ in range(a.repeat):
        for kind in VARIANTS:
            O.loadTmp('everyStep')
            runtime.restore()
            crush = next(e for e in O.engines if isinstance(e, BallastCrushEngine))
            crush.dead = True
            if kind == 'pass':
                O.engines = O.engines + [PyRunner(iterPeriod=1, command='pass')]
            elif kind != 'plain':
                O.engines = O.engines + [runtime.callback(Piece(kind, crush), 'fire', iterPeriod=1)]
            t0 = time.process_time()
            O.run(a.steps, True)
            times[kind].append((time.process_time() - t0) / a.steps)
    med = {k: statistics.median(v) for k, v in times.items()}
    result = {'seed': a.seed, 'steps': a.steps, 'repeat': a.repeat, 'bodies': len(O.bodies), 'secondsPerStep': med,
              'ratioToPlain': {k: med[k] / med['plain'] for k in VARIANTS},
              'addedMicroseconds': {k: 1e6 * (med[k] - med[prev]) for prev, k in zip(VARIANTS, VARIANTS[1:])}}
    with open(a.out, 'w') as fh:
        json.dump(result, fh, indent=1)
    print('bench: %d bodies, plain %.1f us/step; ' % (len(O.bodies), 1e6 * med['plain']) + ', '.join(
        '%s +%.1f us' % kv for kv in result['addedMicroseconds'].items()) + '; fire x%.2f' % result['ratioToPlain']['fire'])
    print('bench: wrote %s' % a.out)


if __name__ == '__main__':
    main(sys.argv[1:])
