"""Small YADE scenes used by the demo and the tests: a Hertz-Mindlin contact model, one grain between
two walls, and a loaded box of grains."""
import math

from yade import O, utils
from yade.wrapper import (Bo1_Sphere_Aabb, Bo1_Wall_Aabb, ForceResetter, FrictMat, Ig2_Sphere_Sphere_ScGeom,
                          Ig2_Wall_Sphere_ScGeom, InsertionSortCollider, InteractionLoop,
                          Ip2_FrictMat_FrictMat_MindlinPhys, Law2_ScGeom_MindlinPhys_Mindlin, NewtonIntegrator)


def hertzEngines(gravity=(0, 0, 0), damping=0.0):
    """ForceResetter, collider, Hertz-Mindlin interaction loop (consistent with eq. 7) and Newton."""
    return [ForceResetter(),
            InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()]),
            InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],
                            [Ip2_FrictMat_FrictMat_MindlinPhys()], [Law2_ScGeom_MindlinPhys_Mindlin()]),
            NewtonIntegrator(gravity=gravity, damping=damping)]


def ballastMaterial(E=3e11, nu=0.3, density=2600.0, friction=0.8):
    """Ballast of the paper, section 4: E [Pa], Poisson [-], density [kg/m^3], friction angle [rad]."""
    return FrictMat(young=E, poisson=nu, density=density, frictionAngle=friction, label='ballast')


def steelMaterial(E=3e12, nu=0.25, density=7850.0, friction=0.0):
    """Steel of the oedometer, section 4 (E ten times the ballast's)."""
    return FrictMat(young=E, poisson=nu, density=density, frictionAngle=friction, label='steel')


def grainBetweenWalls(r=0.02, overlap=1e-4, E=3e11, block=True):
    """A fresh scene: one grain of radius r [m] at the origin, pressed by two fixed walls z = +-(r - overlap).
    With block=True the grain can only move along z, where the two wall forces balance exactly, so
    the contact forces stay constant (blocking all DOFs would make it non-dynamic: not a grain).
    Returns (grain id, bottom wall id, top wall id)."""
    O.reset()
    steel, ballast = steelMaterial(E=10 * E), ballastMaterial(E=E)
    O.materials.append(steel)
    O.materials.append(ballast)
    g = O.bodies.append(utils.sphere((0, 0, 0), r, material=ballast))
    w0 = O.bodies.append(utils.wall(-(r - overlap), axis=2, sense=1, material=steel))
    w1 = O.bodies.append(utils.wall(r - overlap, axis=2, sense=-1, material=steel))
    if block:
        O.bodies[g].state.blockedDOFs = 'xyXYZ'
    O.engines = hertzEngines()
    O.dt = 0.5 * utils.PWaveTimeStep()
    return g, w0, w1


def squeezedStress(F, r, arm):
    """Von Mises stress [Pa] of a grain of radius r squeezed by two opposite forces F along a diameter,
    each applied at distance arm from the centre (eqs. 2-3): sigma_e = 2 F arm / V."""
    return 2 * F * arm / (4.0 / 3.0 * math.pi * r ** 3)
