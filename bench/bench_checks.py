"""Cost of one crushing check and one abrasion check against one YADE step and against yade.bf,
for packings of about 200, 2 000 and 20 000 grains (a wider box of the same grains), and what a crushing
check spends where: YADE's per-body stress reader (utils.bodyStressTensors, C++ building a Python list of
Matrix3), the package's conversion of that list to one array (C++), the rest (the criterion in C++, fatigue
and bookkeeping in NumPy and Python).

    yade -n -x bench/bench_checks.py [out.json]          (one thread)
    yade -j2 -n -x bench/bench_checks.py [out.json]      (YADE's OpenMP threads)

The packing is a hexagonal close packing of ballast grains (radii 10.25-22.25 mm scaled to overlap
their neighbours slightly), so every grain carries Hertz contacts from the first step. Everything
is timed side by side in one process; ratios, not seconds, are the result.
"""
import json
import math
import os
import sys

import numpy as np
from yade import O, utils
from yade.bf import bf

from ballast import _ballast
from ballast.engines import BallastAbrasionEngine, BallastCrushEngine
from ballast.scenes import ballastMaterial, hertzEngines, steelMaterial

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))  # bench/, for timing.py
from timing import best, bestCheck, stamped  # noqa: E402

SIZES = (200, 2000, 20000)


def hcpBox(n, seed=1):
    """About n grains on a hexagonal close packing, 4 grains high, walls around: a wider box for more."""
    O.reset()
    steel, mat = steelMaterial(), ballastMaterial()
    O.materials.append(steel)
    O.materials.append(mat)
    rng = np.random.default_rng(seed)
    a = 0.0325                                  # lattice spacing: the mean grain diameter [m]
    layers = 4
    side = max(2, int(round(math.sqrt(n / layers))))
    pts = []
    for k in range(layers):
        for j in range(side):
            for i in range(side):
                x = a * (i + 0.5 * ((j + k) % 2))
                y = a * math.sqrt(3) / 2 * (j + (k % 3) / 3.0)
                z = a * math.sqrt(2.0 / 3.0) * k
                pts.append((x, y, z))
    pts = np.array(pts) + a
    for p in pts:
        r = 0.5 * a * (1.0 + 2e-3 * rng.random())  # slight overlaps: every contact loaded
        O.bodies.append(utils.sphere(tuple(p), r, material=mat))
    lo, hi = pts.min(0) - a / 2, pts.max(0) + a / 2
    for axis in range(3):
        O.bodies.append(utils.wall(lo[axis], axis=axis, sense=1, material=steel))
        if axis < 2:
            O.bodies.append(utils.wall(hi[axis], axis=axis, sense=-1, material=steel))
    O.engines = hertzEngines(gravity=(0, 0, -9.81), damping=0.2)
    O.dt = 0.5 * utils.PWaveTimeStep()
    O.run(20, True)
    return len(pts)


def measure(n):
    nGrains = hcpBox(n)
    nContacts = O.interactions.countReal()
    steps = 50
    step = min(stamped(steps) for _ in range(3)) / steps
    crush = BallastCrushEngine(ft0=1e30)          # never crushes: the cost of the check alone
    abrasion = BallastAbrasionEngine(strength=1e30, prefilter=False)  # every contact read
    bounded = BallastAbrasionEngine(strength=1e30)                   # the prefilter rules every grain out
    rep = 5 if nGrains > 5000 else 20
    tCrush = bestCheck(crush, rep)
    tRead = best(utils.bodyStressTensors, rep)
    tensors = utils.bodyStressTensors()
    tConvert = best(lambda: _ballast.matricesToArray(tensors), rep)
    tAbr = bestCheck(abrasion, rep)
    bounded.fire()  # its first check verifies the bounds with a full read
    tBounded = bestCheck(bounded, rep)
    grains = [b for b in O.bodies if b.dynamic]
    nBf = min(len(grains), 2000)                  # yade.bf is slow: time a sample, scale per grain

    def bfCheck():
        for b in grains[:nBf]:
            bf.stressTensor(b, stress_correction=True)
            bf.checkFailure(b, 1e30, 1e30, wei_m=3)
    tBf = best(bfCheck, 2) * len(grains) / nBf
    return {'grains': nGrains, 'contacts': nContacts, 'step_s': step, 'crush_check_s': tCrush,
            'abrasion_check_s': tAbr, 'abrasion_check_bounded_s': tBounded, 'bf_check_s': tBf,
            'abrasion_check_bounded_in_steps': tBounded / step,
            'crush_check_in_steps': tCrush / step, 'abrasion_check_in_steps': tAbr / step,
            'crush_per_grain_s': tCrush / nGrains, 'abrasion_per_contact_s': tAbr / max(nContacts, 1),
            'speedup_vs_bf': tBf / tCrush, 'crush_check_stress_read_s': tRead,
            'crush_check_stress_convert_s': tConvert, 'crush_check_stress_read_share': tRead / tCrush,
            'crush_check_rest_share': max(tCrush - tRead - tConvert, 0.0) / tCrush}


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else 'bench/results_checks.json'
    threads = O.numThreads
    rows = []
    for n in SIZES:
        r = measure(n)
        r['threads'] = threads
        rows.append(r)
        print('%6d grains %6d contacts | step %.3g ms | crush check %.3g ms (%.2f steps) | abrasion check, all contacts '
              'read %.3g ms (%.2f steps), all ruled out by the prefilter %.3g ms (%.2f steps) | yade.bf %.3g ms: ours %.0fx '
              'faster | of a crushing check: YADE\'s stress reader %.0f %%, the rest but the conversion %.0f %%'
              % (r['grains'], r['contacts'], 1e3 * r['step_s'], 1e3 * r['crush_check_s'], r['crush_check_in_steps'],
                 1e3 * r['abrasion_check_s'], r['abrasion_check_in_steps'], 1e3 * r['abrasion_check_bounded_s'],
                 r['abrasion_check_bounded_in_steps'], 1e3 * r['bf_check_s'], r['speedup_vs_bf'],
                 100 * r['crush_check_stress_read_share'], 100 * r['crush_check_rest_share']), flush=True)
    with open(out, 'w') as f:
        json.dump({'threads': threads, 'rows': rows}, f, indent=1)
    print('wrote', out)


if __name__ == '__main__':  # yade -x runs a script as __main__; profile_checks.py imports hcpBox
    main()
