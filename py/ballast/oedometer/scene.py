"""The oedometer of section 4 (Fig. 3) as YADE bodies: ballast and steel materials, the steel cylinder
of facets with a closed bottom, and the engine chain with the contact law."""
import math

from yade import O, Vector3, geom
from yade.wrapper import (Bo1_Facet_Aabb, Bo1_Sphere_Aabb, Bo1_Wall_Aabb, ForceResetter, FrictMat,
                          Ig2_Facet_Sphere_ScGeom, Ig2_Sphere_Sphere_ScGeom, Ig2_Wall_Sphere_ScGeom,
                          InsertionSortCollider, InteractionLoop, Ip2_FrictMat_FrictMat_MindlinPhys,
                          Law2_ScGeom_MindlinPhys_Mindlin, NewtonIntegrator)

GRAVITY = (0, 0, -9.81)  # [m/s^2]
STEEL_COLOR = (.6, .6, .6)


class Cylinder:
    """The steel cylinder: its facets' ids, their rest positions, the inner radius Rin [m] (the flat
    faces) and the vertex radius Rv [m] (facetCylinder's radius, pushed out so the faces are at Rin)."""

    def __init__(self, p, steel, height=None):
        self.Rin = p['diameter'] / 2
        self.Rv = self.Rin / math.cos(math.pi / p['segments'])
        height = height or p['height']
        # wallMask: up 1, down 2, side 4 -> closed bottom, open top
        facets = geom.facetCylinder((0, 0, height / 2), self.Rv, height, segmentsNumber=p['segments'], wallMask=6,
                                    material=steel, color=STEEL_COLOR)
        self.ids = O.bodies.append(facets)
        self.pos0 = [Vector3(O.bodies[i].state.pos) for i in self.ids]

    def state(self):
        return {'Rin': self.Rin, 'Rv': self.Rv, 'ids': list(self.ids), 'pos0': [list(x) for x in self.pos0]}

    @classmethod
    def fromState(cls, s):
        c = cls.__new__(cls)
        c.Rin, c.Rv, c.ids, c.pos0 = s['Rin'], s['Rv'], s['ids'], [Vector3(*x) for x in s['pos0']]
        return c


def materials(p, young):
    """(ballast, steel) FrictMat of section 4, appended to O.materials; steel is steelYoungRatio stiffer."""
    ballast = FrictMat(young=young, poisson=p['poisson'], frictionAngle=p['friction'], density=p['density'],
                       label='ballast')
    steel = FrictMat(young=p['steelYoungRatio'] * young, poisson=p['steelPoisson'], frictionAngle=p['steelFriction'],
                     density=p['steelDensity'], label='steel')
    O.materials.append(ballast)
    O.materials.append(steel)
    return ballast, steel


def engines(damping, beforeNewton=()):
    """ForceResetter, collider, interaction loop, `beforeNewton` (a plate control), Newton with gravity."""
    return [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb(), Bo1_Wall_Aabb()]),
        # Hertz-Mindlin: normal force kno uN^1.5 is the Hertz solution behind p0 of eq. 7 (docs/oedometer.md)
        InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],
                        [Ip2_FrictMat_FrictMat_MindlinPhys()], [Law2_ScGeom_MindlinPhys_Mindlin()]),
    ] + list(beforeNewton) + [NewtonIntegrator(damping=damping, gravity=GRAVITY, label='newton')]


def newton():
    return next(e for e in O.engines if isinstance(e, NewtonIntegrator))
