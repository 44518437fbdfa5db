"""Why YADE's polyhedra do not come to rest in the oedometer (issue 47, item 4; docs/grains.md, "Polyhedra"): two
measurements on a few grains, at fractions of the kind's step (grainkinds.polyhedron.pWaveTimeStep), one JSON.

* drop: one polyhedron (r_eq 16 mm) dropped 3 cm onto a steel wall, no damping, 0.3 s: the largest translational
  plus potential energy over the start's (above 1: the step feeds energy in) and the energy at the end;
* stack: `n` polyhedra (r_eq 12 mm) dropped in a 6 cm square box of walls with Newton's damping 0.3, 1 s: the largest
  grain speed at every 0.1 s (grains at rest fall to zero).

    yade -n -x bench/polyhedra_rest.py [--out bench/polyhedra-rest.json]   # about ten minutes
"""
import argparse
import json
import sys

from yade import O, utils

from ballast import grainkinds
from ballast.experiments.scene import polyhedronEngines, polyhedronMaterials
from ballast.grainkinds import polyhedron

P = {'poisson': 0.3, 'friction': 0.5, 'density': 2600.0, 'steelYoungRatio': 10.0, 'steelPoisson': 0.25,
     'steelFriction': 0.0, 'steelDensity': 7850.0, 'ft0': 3.1e6, 'dMin': 0.0205, 'dMax': 0.0445}
G = 9.81


def scene(young, damping):
    O.reset()
    grainkinds.use('polyhedron')
    ballast, steel = polyhedronMaterials(P, young)
    O.engines = polyhedronEngines(damping)
    O.bodies.append(utils.wall(0, axis=2, material=steel))
    return ballast, steel


def drop(young, frac):
    ballast, _ = scene(young, 0.0)
    v = polyhedron.randomVertices(0.016, [1, 0])
    b = O.bodies[polyhedron.addPolyhedron(v - v.mean(axis=0) + (0, 0, 0.03), ballast)]
    O.dt = frac * grainkinds.current().pWaveTimeStep()

    def energy():
        return 0.5 * b.state.mass * b.state.vel.squaredNorm() + b.state.mass * G * b.state.pos[2]
    e0, largest, steps = energy(), energy(), int(0.3 / O.dt)
    for _ in range(300):
        O.run(max(steps // 300, 1), True)
        largest = max(largest, energy())
    return {'case': 'drop', 'young': young, 'stepFraction': frac, 'dt': O.dt, 'largestOverStart': largest / e0,
            'endOverStart': energy() / e0}


def stack(young, frac, n):
    ballast, steel = scene(young, 0.3)
    for axis in (0, 1):
        O.bodies.append(utils.wall(-0.03, axis=axis, sense=1, material=steel))
        O.bodies.append(utils.wall(0.03, axis=axis, sense=-1, material=steel))
    ids = []
    for k in range(n):
        v = polyhedron.randomVertices(0.012, [1, k])
        ids.append(polyhedron.addPolyhedron(v - v.mean(axis=0) + (0.004 * (k % 2), 0, 0.02 + 0.035 * k), ballast))
    O.dt = frac * grainkinds.current().pWaveTimeStep()
    speeds = []
    for _ in range(10):
        O.run(int(0.1 / O.dt), True)
        speeds.append(max(O.bodies[i].state.vel.norm() for i in ids))
    return {'case': 'stack', 'young': young, 'stepFraction': frac, 'dt': O.dt, 'grains': n, 'largestSpeed': speeds}


def main(argv):
    ap = argparse.ArgumentParser(prog='bench/polyhedra_rest.py', description=__doc__.split('\n\n')[0])
    ap.add_argument('--out', default='bench/polyhedra-rest.json')
    a = ap.parse_args(argv)
    rows = [drop(y, f) for y in (3e8, 3e11) for f in (0.5, 0.2, 0.05)]
    rows += [stack(3e8, f, n) for n in (2, 4) for f in (0.5, 0.1)]
    for r in rows:
        print(json.dumps(r), flush=True)
    with open(a.out, 'w') as fh:
        json.dump({'what': __doc__.split('\n\n')[0].replace('\n', ' '), 'rows': rows}, fh, indent=1)
    print('written', a.out)


if __name__ == '__main__':
    main(sys.argv[1:])
