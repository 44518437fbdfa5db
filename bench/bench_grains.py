"""Cost of a grain-step by grain kind (issue 47, items 4 and 6; docs/grains.md, "Polyhedra"): the same small bed of
equal grains (r_eq 16 mm, the mean of 20.5-44.5 mm) settling in a box of five steel walls under gravity, as spheres
(the linear law), clumps of 8 spheres (the default shape) and YADE's polyhedra of 14 vertices (the volumetric law),
each at 27 grains and the first two at 300 too, side by side in one run: CPU seconds per step over `steps` steps
after a warm-up in which the grains fall into contact, per grain-step, the contacts then, and the ratios to the
spheres of the same count; and the cost of a crushing check (the kind's crushing engine checking every step at a
strength no grain reaches, in blocks interleaved with the plain ones on the same bed). A benchmark, not a test;
about five minutes.

    yade -n -x bench/bench_grains.py [--steps 1000] [--out bench/grains.json]

The modulus is the preparation's (3e8 Pa; the polyhedra's volumetric modulus from it as in the experiments), so the
grains meet within the warm-up; the cost of a step follows the contacts, not the modulus. One OpenMP thread.
"""
import argparse
import json
import math
import os
import sys
import time

import numpy as np
from yade import O, Quaternion, Vector3, utils

from ballast import grainkinds
from ballast.engines import BallastCrushEngine, PolyhedronCrushEngine
from ballast.experiments.scene import engines, materials, polyhedronEngines, polyhedronMaterials
from ballast.grainkinds import clump, clumpshapes, polyhedron

R = 0.016            # [m] r_eq of every grain
P = {'dMin': 0.0205, 'dMax': 0.0445, 'poisson': 0.3, 'friction': 0.5, 'density': 2600.0, 'steelYoungRatio': 10.0,
     'steelPoisson': 0.25, 'steelFriction': 0.0, 'steelDensity': 7850.0, 'ft0': 3.1e6}
YOUNG = 3e8          # [Pa]
WARMUP = 0.2         # [s] of fall (20 cm): the lower layers land; the contacts then are in the JSON
SPACING = 3.4 * R    # lattice pitch: a polyhedron's vertices reach about 1.5 R, a clump's 1.55 R


def lattice(n):
    """n centres on a square lattice of side ceil(n^(1/3)), its lowest layer SPACING / 2 above the floor."""
    k = math.ceil(n ** (1 / 3) - 1e-9)
    return [((i - (k - 1) / 2) * SPACING, (j - (k - 1) / 2) * SPACING, (l + 0.5) * SPACING)
            for l in range(k) for j in range(k) for i in range(k)][:n], k * SPACING


def box(side, steel):
    for axis, pos, sense in ((2, 0.0, 1), (0, -side / 2, 1), (0, side / 2, -1), (1, -side / 2, 1), (1, side / 2, -1)):
        O.bodies.append(utils.wall(pos, axis=axis, sense=sense, material=steel))


def turn(rng):
    q = rng.normal(size=4)
    q /= np.linalg.norm(q)
    return Quaternion(*q.tolist())


def build(kind, n, seed=1):
    """The scene of n grains of the kind, its engines and step; returns the grains' ids."""
    O.reset()
    grainkinds.use(kind)
    rng = np.random.default_rng(seed)
    centres, side = lattice(n)
    if kind == 'polyhedron':
        ballast, steel = polyhedronMaterials(P, YOUNG)
        O.engines = polyhedronEngines(0.2)
        box(side, steel)
        for k, c in enumerate(centres):
            polyhedron.addPolyhedron(polyhedron.randomVertices(R, [seed, k]) + c, ballast)
        O.dt = 0.5 * grainkinds.current().pWaveTimeStep()
    else:
        ballast, steel = materials(P, YOUNG)
        O.engines = engines(0.2, 'linear')
        box(side, steel)
        if kind == 'sphere':
            for c in centres:
                O.bodies.append(utils.sphere(c, R, material=ballast))
        else:
            C, r, V, _ = clumpshapes.clumpMembers(1.0, seed=seed)   # one shape, turned at random per grain
            for c in centres:
                q = turn(rng)
                spheres = [utils.sphere(Vector3(*c) + q * (R * Vector3(*ci)), float(R * ri), material=ballast)
                           for ci, ri in zip(C.tolist(), r.tolist())]
                clump.appendClump(spheres, V * R ** 3)
        O.dt = 0.5 * utils.PWaveTimeStep()
    return grainkinds.current().ids()


def crushEngines(kind):
    """The kind's crushing engine checking every step at a strength no grain reaches (the check's cost alone)."""
    if kind == 'polyhedron':
        crush = PolyhedronCrushEngine(ft0=1e15, rMin=0.0, seed=1, adjustDt=False, iterPeriod=1, label='crush')
        crush.floor()
        return crush.engines()
    return [BallastCrushEngine(ft0=1e15, m=1.0, rMin=0.0, seed=1, adjustDt=False, iterPeriod=1, label='crush')]


def measure(kind, n, steps, blocks=5):
    """The bed's steps timed in `blocks` pairs of blocks, without and with a crushing check at every step (the kind's
    engine at a strength no grain reaches, dead in the first block of a pair), so that both see the same bed."""
    t0 = time.process_time()
    ids = build(kind, n)
    built = time.process_time() - t0
    O.run(int(WARMUP / O.dt), True)
    crush = crushEngines(kind)
    O.engines = list(O.engines) + crush
    cpu, wall, per = {False: 0.0, True: 0.0}, 0.0, max(steps // blocks, 1)
    for _ in range(blocks):
        for on in (False, True):
            for e in crush:
                e.dead = not on
            t0, w0 = time.process_time(), time.perf_counter()
            O.run(per, True)
            cpu[on] += time.process_time() - t0
            wall += 0.0 if on else time.perf_counter() - w0
    plain, check = cpu[False] / (per * blocks), (cpu[True] - cpu[False]) / (per * blocks)
    contacts = sum(1 for i in O.interactions if i.isReal)
    row = {'kind': kind, 'grains': len(ids), 'steps': per * blocks, 'dt': O.dt, 'cpuPerStep': plain,
           'cpuPerGrainStep': plain / len(ids), 'wallPerStep': wall / (per * blocks), 'contacts': contacts,
           'buildSeconds': built, 'lowestGrain': float(min(O.bodies[int(i)].state.pos[2] for i in ids)),
           'cpuPerCheck': check, 'cpuPerGrainCheck': check / len(ids)}
    print('%-10s %4d grains  %8.3f ms a step  %8.3f us a grain-step  %4d contacts  a crushing check %8.3f ms' % (
        kind, row['grains'], 1e3 * plain, 1e6 * row['cpuPerGrainStep'], contacts, 1e3 * check), flush=True)
    return row


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('--steps', type=int, default=1000, help='steps timed per case (default 1000; spheres 20 and clumps 5 times as many at 27 grains)')
    ap.add_argument('--out', default='bench/grains.json', help='the JSON written (default bench/grains.json: run it from '
                    'the repository)')
    a = ap.parse_args(argv)
    rows = [measure('sphere', 27, 20 * a.steps), measure('clump', 27, 5 * a.steps), measure('polyhedron', 27, a.steps),
            measure('sphere', 300, 5 * a.steps), measure('clump', 300, a.steps)]
    base = {r['grains']: r['cpuPerGrainStep'] for r in rows if r['kind'] == 'sphere'}
    for r in rows:
        r['overSpheres'] = r['cpuPerGrainStep'] / base[r['grains']]
    doc = {'what': __doc__.split('\n\n')[0].replace('\n', ' '), 'command': 'yade -n -x bench/bench_grains.py',
           'threads': os.environ.get('OMP_NUM_THREADS', 'yade default'), 'R': R, 'young': YOUNG, 'rows': rows}
    with open(a.out, 'w') as fh:
        json.dump(doc, fh, indent=1)
    for r in rows:
        print('%-10s %4d grains: %.3g times the spheres a grain-step' % (r['kind'], r['grains'], r['overSpheres']))
    print('written', a.out)


if __name__ == '__main__':
    main(sys.argv[1:])
