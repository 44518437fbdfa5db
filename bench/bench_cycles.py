"""Cost of many load cycles per option (issue 25, item 5; docs/performance.md, "Many cycles"): one seed,
a few cycles between Fmin and Fmax at the default set-up, once per option, steps (exact) and CPU per
cycle side by side in one JSON.

    yade -n -x bench/bench_cycles.py [--seed 2] [--cycles 3] [--Fmin 150e3] [--out FILE.json]
"""
import argparse
import json
import os
import sys
import tempfile

from ballast.oedometer import Oedometer

# under `yade -x` __file__ is yade's own; sys.argv[0] is this script
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0] if sys.argv[0].endswith('.py') else __file__)))
from timing import optionList  # noqa: E402

OPTIONS = {'paper': {}, 'stiffness': {'timeStep': 'stiffness'}, 'density1.2e-6': {'densityStep': 1.2e-6},
           'density2e-6': {'densityStep': 2e-6}}


def main(argv):
    ap = argparse.ArgumentParser(prog='bench/bench_cycles.py', description=__doc__.split('\n\n')[0])
    ap.add_argument('--seed', type=int, default=2)
    ap.add_argument('--cycles', type=int, default=3)
    ap.add_argument('--Fmin', type=float, default=150e3, help='[N] the cycles run between Fmin and Fmax')
    ap.add_argument('--options', type=optionList(OPTIONS), default=list(OPTIONS),
                    help='comma-separated, of: ' + ', '.join(OPTIONS))
    ap.add_argument('--packingDir', default=os.path.join('results', 'packings'))
    ap.add_argument('--out', default=os.path.join(tempfile.gettempdir(), 'bench_cycles.json'))
    a = ap.parse_args(argv)
    names = a.options
    results = {}
    for name in names:
        run = Oedometer(seed=a.seed, cycles=a.cycles, Fmin=a.Fmin, packingDir=a.packingDir,
                        results=tempfile.mkdtemp(prefix='bench_cycles_'), progress=120, **OPTIONS[name])
        s = run.run()
        results[name] = {'nCrushed': s['nCrushed'], 'deltaFinal': s['deltaFinal'], 'dtFinal': s['dtFinal'],
                         'loadStepsPerCycle': s['stepsByPhase']['load'] / a.cycles,
                         'loadCpuPerCycle': s['wallSecondsByPhase']['load'] / a.cycles * s['cpuSeconds'] / s['wallSeconds'],
                         'nSpheresFinal': s['nSpheresFinal'], 'options': OPTIONS[name]}
        print('bench: %-14s %d crushed, %.0f loading steps and %.1f s CPU per cycle' % (
            name, s['nCrushed'], results[name]['loadStepsPerCycle'], results[name]['loadCpuPerCycle']), flush=True)
    with open(a.out, 'w') as fh:
        json.dump({'seed': a.seed, 'cycles': a.cycles, 'Fmin': a.Fmin, 'options': results}, fh, indent=1)
    print('bench: wrote %s' % a.out)


if __name__ == '__main__':
    main(sys.argv[1:])
