"""Cost of a load cycle per cyclic experiment (issue 45, item 4; docs/performance.md, "Cost"): each experiment at
its default size, with the quasi-static option (`--quasiStatic`, default 1e-3) for `--cycles` cycles and at the
paper's step for one, on the same stored sample, side by side in one run: the CPU seconds and steps of every cycle
(from its cycles.csv), the steady cost (the median over the cycles at the option's last step) against the goal, and
the grains, in one JSON. A benchmark, not a test: the paper's-step cycles take minutes each (the box's about 10).

    yade -n -x bench/bench_cost.py [--experiments box triaxial oedometer] [--cycles 8] [--paper 1] [--out FILE.json]
"""
import argparse
import importlib
import json
import os
import sys
import tempfile

import pandas as pd

# name: (module, class, its parameters here, where it stores its samples, the goal [s of CPU a cycle])
EXPERIMENTS = {
    'box': ('ballast.experiments.box', 'BoxTest', {}, 'bedDir', 30.0),                       # 3 Hz, 0.7 x 0.3 m
    # 5 Hz, 300 x 600 mm, at the calibration's contact modulus (docs/triaxial.md: young 3e9 Pa for a resilient modulus
    # of a few hundred MPa; the paper's 3e11 makes the specimen a hundred times too stiff and its step ten times shorter)
    'triaxial': ('ballast.experiments.triaxial', 'TriaxialTest', {'young': 3e9}, 'specimenDir', 10.0),
    'oedometer': ('ballast.oedometer', 'Oedometer', {'seed': 2, 'Fmin': 150e3}, 'packingDir', 5.0),   # quiet (issue 25)
}


def positive(kind):
    def read(text):
        try:
            v = kind(text)
        except ValueError:
            v = 0
        if not v > 0:
            raise argparse.ArgumentTypeError('%r; allowed: a number above 0' % text)
        return v
    return read


def measure(name, cycles, options, store):
    """One run of experiment `name` for `cycles` cycles with `options`: its cycles.csv's CPU and steps per cycle."""
    module, cls, own, storeParam, _ = EXPERIMENTS[name]
    Experiment = getattr(importlib.import_module(module), cls)
    exp = Experiment(cycles=cycles, results=tempfile.mkdtemp(prefix='bench_cost_'), progress=120,
                     **{storeParam: store}, **own, **options)
    s = exp.run()
    c = pd.read_csv(os.path.join(exp.out, 'cycles.csv'))
    last = c[c.dt == c.dt.iloc[-1]]   # the cycles at the last step: the option's steady choice
    return {'cpuSeconds': c.cpuSeconds.tolist(), 'stepsPerCycle': c.stepsPerCycle.tolist(), 'dt': c.dt.tolist(),
            'steadyCpuSeconds': float(last.cpuSeconds.median()), 'grains': int(c.nGrains.iloc[-1]),
            'cpuSecondsRun': float(s.get('cpuSeconds', float('nan')))}


def main(argv):
    ap = argparse.ArgumentParser(prog='bench/bench_cost.py', description=__doc__.split('\n\n')[0])
    ap.add_argument('--experiments', nargs='+', choices=sorted(EXPERIMENTS), default=['box', 'triaxial', 'oedometer'])
    ap.add_argument('--cycles', type=positive(int), default=8, help='cycles with the option (default 8)')
    ap.add_argument('--quasiStatic', type=positive(float), default=1e-3, help='the option\'s bound (default 1e-3)')
    ap.add_argument('--paper', type=int, choices=(0, 1), default=1, help='also a cycle at the paper\'s step (default 1)')
    ap.add_argument('--store', default=os.path.join('results', 'bench-samples'), help='where the samples are stored')
    ap.add_argument('--out', default=os.path.join(tempfile.gettempdir(), 'bench_cost.json'))
    a = ap.parse_args(argv)
    out = {'cycles': a.cycles, 'quasiStatic': a.quasiStatic, 'experiments': {}}
    for name in a.experiments:
        goal = EXPERIMENTS[name][4]
        r = {'goal': goal, 'quasiStatic': measure(name, a.cycles, {'quasiStatic': a.quasiStatic}, a.store)}
        if a.paper:
            r['paper'] = measure(name, 1, {}, a.store)
        q = r['quasiStatic']
        print('bench: %-9s %d grains: %.1f s of CPU a cycle with quasiStatic %g (steady; goal %g s; first cycles %s)%s' % (
            name, q['grains'], q['steadyCpuSeconds'], a.quasiStatic, goal,
            ', '.join('%.0f' % v for v in q['cpuSeconds'][:4]),
            ', %.0f s at the paper\'s step' % r['paper']['cpuSeconds'][0] if a.paper else ''), flush=True)
        out['experiments'][name] = r
        with open(a.out, 'w') as fh:   # written after each experiment: a long bench keeps what it measured
            json.dump(out, fh, indent=1)
    print('bench: wrote %s' % a.out)


if __name__ == '__main__':
    main(sys.argv[1:])
