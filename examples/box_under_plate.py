"""Grains in a box under a plate: a first scene of your own with both ballast engines.

    yade -n -x examples/box_under_plate.py [STEPS]

Sixty-four grains settle in a box of YADE Walls, then a free steel plate (a Box body) presses them
with a constant force. Hertz-Mindlin contacts; the crushing engine (eqs. 2-4) and the abrasion engine
(eqs. 6-7) check every 50 steps. Notes for your own scene:
* every shape pair needs its Ig2 functor and every shape its Bo1: Box bodies (utils.box, the boxes of
  utils.aabbWalls) need Bo1_Box_Aabb and Ig2_Box_Sphere_ScGeom, which ballast.scenes.hertzEngines()
  leaves out, so its grains fall through such boxes;
* append materials to O.materials; the engines go after NewtonIntegrator.
"""
import argparse
import sys

from yade import O, utils
from yade.wrapper import (Bo1_Box_Aabb, Bo1_Sphere_Aabb, Bo1_Wall_Aabb, ForceResetter, Ig2_Box_Sphere_ScGeom,
                          Ig2_Sphere_Sphere_ScGeom, Ig2_Wall_Sphere_ScGeom, InsertionSortCollider, InteractionLoop,
                          Ip2_FrictMat_FrictMat_MindlinPhys, Law2_ScGeom_MindlinPhys_Mindlin, NewtonIntegrator)

from ballast import BallastAbrasionEngine, BallastCrushEngine
from ballast.scenes import ballastMaterial, steelMaterial

ap = argparse.ArgumentParser(prog='yade -n -x examples/box_under_plate.py', description=__doc__.split('\n\n')[0])
ap.add_argument('steps', nargs='?', type=int, default=20000, help='steps the plate presses (default %(default)s)')
STEPS = ap.parse_args(sys.argv[1:]).steps
if STEPS < 1:
    ap.error('steps = %d; allowed: an integer >= 1' % STEPS)
N, R, F = 4, 0.01, 400.0            # grains per side, radius [m], force on the plate [N]

grains, steel = ballastMaterial(E=1e8), steelMaterial(E=1e9)   # soft grains: a large time step
O.materials.append(grains)
O.materials.append(steel)
L = 2 * R * N
for axis, pos, sense in ((0, 0, 1), (0, L, -1), (1, 0, 1), (1, L, -1), (2, 0, 1)):
    O.bodies.append(utils.wall(pos, axis=axis, sense=sense, material=steel))
for i in range(N):
    for j in range(N):
        for k in range(N):
            O.bodies.append(utils.sphere(((2 * i + 1) * R, (2 * j + 1) * R, (2 * k + 1) * R), R * (0.8 + 0.03 * ((i + j + k) % 5)),
                                         material=grains))
plate = O.bodies.append(utils.box((L / 2, L / 2, L + 0.5 * R), (L / 2, L / 2, 0.25 * R), fixed=False, material=steel))
O.bodies[plate].state.blockedDOFs = 'xyXYZ'   # it only moves up and down

O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb(), Bo1_Box_Aabb()]),
    InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom(), Ig2_Box_Sphere_ScGeom()],
                    [Ip2_FrictMat_FrictMat_MindlinPhys()], [Law2_ScGeom_MindlinPhys_Mindlin()]),
    NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.4),
    BallastCrushEngine(ft0=4500.0, pattern=6, rMin=0.004, iterPeriod=50, label='crush'),       # f_t = ft0 / r [Pa]
    BallastAbrasionEngine(strength=1.5e7, gamma=0.95, rMin=0.007, iterPeriod=50, label='abrasion'),  # p0 [Pa]
]
O.dt = 0.3 * utils.PWaveTimeStep()
O.forces.setPermF(plate, (0, 0, -F))
O.run(STEPS, True)

crush, abrasion = O.engines[-2], O.engines[-1]
print('box_under_plate: %d steps, plate at z = %.4f m, %d crushed, %d abraded, largest sigma_e/f_t %.3f, p0/strength %.3f'
      % (O.iter, O.bodies[plate].state.pos[2], crush.nCrushed, abrasion.nAbraded, crush.maxStressRatio,
         abrasion.maxPressureRatio))
