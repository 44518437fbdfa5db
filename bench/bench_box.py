"""Cost of the box test per option (issue 26, item 4; docs/box.md, "Cost"): one seed, a few cycles, once
per fast-step option on the same stored bed, steps (exact), grains and CPU per cycle side by side in one
JSON. The default size is a reduced box (0.45 x 0.2 m, 0.15 m of the paper's grains, a 0.15 m sleeper);
--full runs the defaults of the experiment (0.7 x 0.3 m, 0.3 m of ballast).

    yade -n -x bench/bench_box.py [--seed 1] [--cycles 2] [--f 3] [--full] [--out FILE.json]
"""
import argparse
import json
import os
import sys
import tempfile

from ballast.experiments.box import BoxTest

# under `yade -x` __file__ is yade's own; sys.argv[0] is this script
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0] if sys.argv[0].endswith('.py') else __file__)))
from timing import optionList  # noqa: E402

OPTIONS = {'paper': {}, 'stiffness': {'timeStep': 'stiffness'}, 'density1.2e-6': {'densityStep': 1.2e-6}}
REDUCED = dict(boxLength=0.45, boxWidth=0.2, bedDepth=0.15, layers=2, sleeperWidth=0.15, sleeperHeight=0.1,
               sleeperMass=15.0, peakLoad=20e3, seatLoad=1.5e3)   # about the default's pressure under the sleeper


def main(argv):
    ap = argparse.ArgumentParser(prog='bench/bench_box.py', description=__doc__.split('\n\n')[0])
    ap.add_argument('--seed', type=int, default=1)
    ap.add_argument('--cycles', type=int, default=2)
    ap.add_argument('--f', type=float, default=3.0, help='[Hz] the loading frequency (default 3, the experiment\'s)')
    ap.add_argument('--full', action='store_true', help='the experiment\'s default box instead of the reduced one')
    ap.add_argument('--options', type=optionList(OPTIONS), default=list(OPTIONS),
                    help='comma-separated, of: ' + ', '.join(OPTIONS))
    ap.add_argument('--bedDir', default=os.path.join('results', 'beds'))
    ap.add_argument('--out', default=os.path.join(tempfile.gettempdir(), 'bench_box.json'))
    a = ap.parse_args(argv)
    names = a.options
    size = {} if a.full else REDUCED
    results = {}
    for name in names:
        test = BoxTest(seed=a.seed, cycles=a.cycles, f=a.f, bedDir=a.bedDir, progress=120,
                       results=tempfile.mkdtemp(prefix='bench_box_'), **size, **OPTIONS[name])
        s = test.run()
        results[name] = {k: s[k] for k in ('nGrainsInitial', 'nGrains', 'nCrushed', 'settlement', 'resilient', 'dt',
                                           'stepsPerCycle', 'cpuSecondsPerCycle', 'cpuSeconds')}
        results[name]['options'] = OPTIONS[name]
        print('bench: %-14s %d grains, %d crushed, %.0f steps and %.1f s CPU per cycle, settlement %.3f mm' % (
            name, s['nGrainsInitial'], s['nCrushed'], s['stepsPerCycle'], s['cpuSecondsPerCycle'],
            1e3 * s['settlement']), flush=True)
    with open(a.out, 'w') as fh:
        json.dump({'seed': a.seed, 'cycles': a.cycles, 'f': a.f, 'size': size or 'default', 'options': results}, fh,
                  indent=1)
    print('bench: wrote %s' % a.out)


if __name__ == '__main__':
    main(sys.argv[1:])
