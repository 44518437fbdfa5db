"""Scenes and helpers shared by the engine tests (tests/python/test_engines_*.py): a grain squeezed
between two walls, a settled box of grains, linear-law contacts, and adding an engine to the scene."""
import numpy as np
from yade import O, utils

from ballast.scenes import ballastMaterial, grainBetweenWalls, hertzEngines, steelMaterial


R = 0.02          # grain radius [m]
OVERLAP = 1e-4    # wall overlap [m]


def loadedGrain(overlap=OVERLAP, **kw):
    """Grain between two walls after one step: (grain id, top wall id, wall force F [N], arm [m], uN [m])."""
    g, w0, w1 = grainBetweenWalls(r=R, overlap=overlap, **kw)
    O.run(1, True)
    i = O.interactions[g, w1]
    F = abs(O.forces.f(w1)[2])
    arm = (i.geom.contactPoint - O.bodies[g].state.pos).norm()
    return g, w1, F, arm, i.geom.penetrationDepth


def add(engine):
    O.engines = O.engines + [engine]
    return engine


def packedBox(n=4, r=0.01, E=1e8, engines=None, spread=(0.8, 0.95), seed=5, wallE=10.0, listed=True):
    """n^3 grains of radii r * U(spread) settled under gravity in a box of walls wallE times stiffer
    (Hertz-Mindlin contacts unless engines are given); listed=False leaves the grains' material out of
    O.materials (YADE allows it: its id stays -1). Returns the box height [m]."""
    O.reset()
    steel, mat = steelMaterial(E=wallE * E), ballastMaterial(E=E)
    O.materials.append(steel)
    if listed:
        O.materials.append(mat)
    L = 2 * r * n
    for axis, pos, sense in ((0, 0, 1), (0, L, -1), (1, 0, 1), (1, L, -1), (2, 0, 1)):
        O.bodies.append(utils.wall(pos, axis=axis, sense=sense, material=steel))
    rng = np.random.default_rng(seed)
    for i in range(n):
        for j in range(n):
            for k in range(n):
                rr = r * (spread[0] + (spread[1] - spread[0]) * rng.random())
                O.bodies.append(utils.sphere(((2 * i + 1) * r, (2 * j + 1) * r, (2 * k + 1) * r), rr, material=mat))
    O.engines = engines or hertzEngines(gravity=(0, 0, -9.81), damping=0.4)
    O.dt = 0.3 * utils.PWaveTimeStep()
    for _ in range(100):
        O.run(1000, True)
        if utils.unbalancedForce() < 0.02:
            break
    return 2 * r * n


def linearEngines(**ip2):
    from yade.wrapper import (Ig2_Sphere_Sphere_ScGeom, Ig2_Wall_Sphere_ScGeom, InteractionLoop,
                              Ip2_FrictMat_FrictMat_FrictPhys, Law2_ScGeom_FrictPhys_CundallStrack)
    eng = hertzEngines(gravity=(0, 0, -9.81), damping=0.4)
    return [e if not isinstance(e, InteractionLoop) else InteractionLoop(
        [Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys(**ip2)],
        [Law2_ScGeom_FrictPhys_CundallStrack()]) for e in eng]


LINEAR_E = 1e8  # [Pa] packedBox's grains; its walls are 10 times stiffer
