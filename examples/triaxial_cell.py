"""The ballast engines in a triaxial-like cell: YADE's TriaxialStressController on six boxes.

    yade -n -x examples/triaxial_cell.py [STEPS]

A cloud of grains in the six boxes of utils.aabbWalls is compacted to SIGMA3 on all sides, then
compressed along y at a constant strain rate with SIGMA3 kept on x and z, while the crushing and abrasion engines check every
100 steps. The boxes need Bo1_Box_Aabb and Ig2_Box_Sphere_ScGeom; the controller finds them as the
first six bodies (its default wall ids 0-5). Prints the axial and lateral stresses and the counters.
"""
import argparse
import sys

from yade import O, pack, utils
from yade.wrapper import (Bo1_Box_Aabb, Bo1_Sphere_Aabb, ForceResetter, Ig2_Box_Sphere_ScGeom, Ig2_Sphere_Sphere_ScGeom,
                          InsertionSortCollider, InteractionLoop, Ip2_FrictMat_FrictMat_MindlinPhys,
                          Law2_ScGeom_MindlinPhys_Mindlin, NewtonIntegrator, TriaxialStressController)

from ballast import BallastAbrasionEngine, BallastCrushEngine
from ballast.scenes import ballastMaterial, steelMaterial

ap = argparse.ArgumentParser(prog='yade -n -x examples/triaxial_cell.py', description=__doc__.split('\n\n')[0])
ap.add_argument('steps', nargs='?', type=int, default=10000, help='steps of the axial compression (default %(default)s)')
STEPS = ap.parse_args(sys.argv[1:]).steps
if STEPS < 1:
    ap.error('steps = %d; allowed: an integer >= 1' % STEPS)
SIGMA3, RATE = 1e5, -0.5           # confining stress [Pa], axial strain rate [1/s] (compression)

grains, steel = ballastMaterial(E=1e8, friction=0.5), steelMaterial(E=1e9)
O.materials.append(grains)
O.materials.append(steel)
lo, hi = (0, 0, 0), (0.1, 0.1, 0.1)
walls = utils.aabbWalls([lo, hi], thickness=0.01, material=steel)
O.bodies.append(walls)                       # ids 0-5: x-, x+, y-, y+, z-, z+
sp = pack.SpherePack()
sp.makeCloud(lo, hi, rMean=0.008, rRelFuzz=0.3, num=120, seed=1)
sp.toSimulation(material=grains)

triax = TriaxialStressController(thickness=0.01, stressMask=7, goal1=-SIGMA3, goal2=-SIGMA3, goal3=-SIGMA3,
                                 internalCompaction=False, max_vel=1.0, label='triax')
O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Box_Aabb()]),
    InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Box_Sphere_ScGeom()],
                    [Ip2_FrictMat_FrictMat_MindlinPhys()], [Law2_ScGeom_MindlinPhys_Mindlin()]),
    triax,
    NewtonIntegrator(damping=0.3),
    BallastCrushEngine(ft0=7000.0, rMin=0.006, iterPeriod=100, label='crush'),              # f_t = ft0 / r [Pa]
    BallastAbrasionEngine(strength=1.5e7, gamma=0.95, rMin=0.006, iterPeriod=100, label='abrasion'),  # p0 [Pa]
]
O.dt = 0.3 * utils.PWaveTimeStep()
while O.iter < 50000 and not (abs(triax.meanStress + SIGMA3) < 0.02 * SIGMA3 and utils.unbalancedForce() < 0.05):
    O.run(500, True)                          # isotropic compaction (the engines check already)
triax.stressMask, triax.goal2 = 5, RATE       # y: strain rate; x, z: SIGMA3
height = lambda: O.bodies[triax.wall_top_id].state.pos[1] - O.bodies[triax.wall_bottom_id].state.pos[1] - triax.thickness
h0 = height()
O.run(STEPS, True)

crush, abrasion = O.engines[-2], O.engines[-1]
print('triaxial_cell: %d steps, axial strain %.4f, sigma_axial %.4g Pa, sigma_lateral %.4g Pa, %d crushed, %d abraded'
      % (O.iter, 1 - height() / h0, -triax.stress(triax.wall_top_id)[1], -triax.stress(triax.wall_right_id)[0],
         crush.nCrushed, abrasion.nAbraded))
