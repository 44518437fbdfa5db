"""Cost of saving a state as a run grows (cycle jumping saves two states a jump; docs/cycles.md, "Cost"): the
small Weibull cylinder of studies/jump-oedometer-weibull.table loaded for a few cycles, then the same scene
saved the way states were saved before (the records' rows written as JSON numbers, YADE's gzip) and the way
Experiment.save saves them (rows packed bitwise, gzip level 1), side by side; CPU seconds, sizes and the
ratio in one JSON. Both files load back to the same rows.

    yade -n -x bench/bench_save.py [--cycles 20] [--repeat 3] [--out FILE.json]
"""
import argparse
import json
import os
import sys
import tempfile
import time

from yade import O

from ballast import runtime
from ballast.oedometer import Oedometer

CYLINDER = dict(seed=2, diameter=0.15, height=0.08, vMax=5, samples=1000, f=20, Fmax=1.5e6, Fmin=1.5e5, ft0=2.5e7,
                strength=1e15, fatigue=True, fatigueExponent=10, weibullModulus=3, densityStep=8.1e-7)


def before(path):
    """A state as saved before: the document with every record as JSON numbers, compressed by YADE."""
    doc = runtime.document()
    for entry in doc['objects'].values():
        if entry['type'] == 'OedometerOutputs':
            for key in ('rows', 'checkRows'):
                entry['state'][key] = [list(r) for r in runtime.unpackRows(entry['state'][key])]
    O.tags[runtime.TAG] = json.dumps(doc)
    runtime.saveAsYade(path)   # without the runtime's flush, which would pack the rows again


def main(argv):
    ap = argparse.ArgumentParser(prog='bench/bench_save.py', description=__doc__.split('\n\n')[0])
    ap.add_argument('--cycles', type=int, default=20, help='load cycles before saving (the records grow with them)')
    ap.add_argument('--repeat', type=int, default=3, help='saves of each kind; the least CPU counts')
    ap.add_argument('--packingDir', default=os.path.join('results', 'packings'))
    ap.add_argument('--out', default=os.path.join(tempfile.gettempdir(), 'bench_save.json'))
    a = ap.parse_args(argv)
    for name, v in (('--cycles', a.cycles), ('--repeat', a.repeat)):
        if v < 1:
            ap.error('%s %d: at least 1' % (name, v))
    folder = tempfile.mkdtemp(prefix='bench_save_')
    run = Oedometer(cycles=a.cycles, packingDir=a.packingDir, results=folder, progress=120, **CYLINDER)
    run.run()
    rows = {k: len(v) for k, v in (('fd', run.outputs.rows), ('checks', run.outputs.checkRows))}
    out = {}
    for kind, save in (('before', before), ('now', run.save)):
        path = os.path.join(folder, 'bench-%s.yade.gz' % kind)
        cpu = []
        for _ in range(a.repeat):
            t = time.process_time()
            save(path)
            cpu.append(time.process_time() - t)
        out[kind] = {'cpuSeconds': min(cpu), 'bytes': os.path.getsize(path), 'path': path}
    loaded = {kind: Oedometer.reopen(out[kind]['path'], readOnly=True).outputs.rows for kind in out}
    result = {'cycles': a.cycles, 'rows': rows, 'before': out['before'], 'now': out['now'],
              'speedup': out['before']['cpuSeconds'] / out['now']['cpuSeconds'],
              'sameRows': loaded['before'] == loaded['now']}
    print('bench: %d cycles (%d fd rows): a save took %.3f s CPU before, %.3f s now (%.1f x), %.1f against %.1f MB; '
          'same rows: %s' % (a.cycles, rows['fd'], out['before']['cpuSeconds'], out['now']['cpuSeconds'],
                             result['speedup'], out['before']['bytes'] / 1e6, out['now']['bytes'] / 1e6,
                             result['sameRows']))
    with open(a.out, 'w') as fh:
        json.dump(result, fh, indent=1)
    print('bench: wrote %s' % a.out)


if __name__ == '__main__':
    main(sys.argv[1:])
