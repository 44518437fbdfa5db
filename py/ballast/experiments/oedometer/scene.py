"""The oedometer of section 4 (Fig. 3) as YADE bodies: ballast and steel materials, the steel cylinder
of facets with a closed bottom, and the engine chain with the contact law (``law``: YADE's linear
``FrictPhys`` + ``CundallStrack``, or Hertz-Mindlin).

Group masks: grains GRAIN_MASK, steel (facets, plate) STEEL_MASK, and the collider's
avoidSelfInteractionMask = AVOID: steel bodies share a mask within AVOID, so the collider pairs them
with grains only. Without it the 144 cylinder facets and the plate held about 1 700 potential
interactions with each other, half of the scene's.
"""
import math

from yade import O, Vector3, geom, utils

from ... import runtime
from yade.wrapper import (Bo1_Box_Aabb, Bo1_Facet_Aabb, Bo1_Sphere_Aabb, Bo1_Wall_Aabb, CohFrictMat, ForceResetter,
                          FrictMat, Ig2_Box_Sphere_ScGeom, Ig2_Facet_Sphere_ScGeom, Ig2_Sphere_Sphere_ScGeom,
                          Ig2_Sphere_Sphere_ScGeom6D, Ig2_Wall_Sphere_ScGeom, InsertionSortCollider, InteractionLoop,
                          Ip2_CohFrictMat_CohFrictMat_CohFrictPhys, Ip2_FrictMat_FrictMat_FrictPhys,
                          Ip2_FrictMat_FrictMat_MindlinPhys, Law2_ScGeom6D_CohFrictPhys_CohesionMoment,
                          Law2_ScGeom_FrictPhys_CundallStrack, Law2_ScGeom_MindlinPhys_Mindlin, NewtonIntegrator)

GRAVITY = (0, 0, -9.81)  # [m/s^2]
STEEL_COLOR = (.6, .6, .6)
GRAIN_MASK, STEEL_MASK, AVOID = 0b101, 0b110, 0b010   # see the module doc
# contact laws: (Ip2, Law2, the stiffness attributes of the phys that scale with E)
LAWS = {'linear': (Ip2_FrictMat_FrictMat_FrictPhys, Law2_ScGeom_FrictPhys_CundallStrack, ('kn', 'ks')),
        'hertz': (Ip2_FrictMat_FrictMat_MindlinPhys, Law2_ScGeom_MindlinPhys_Mindlin, ('kno', 'kso'))}


class Cylinder:
    """The steel cylinder: the ids of its side facets and bottom wall and their rest positions, the inner
    radius Rin [m] (the flat faces) and the vertex radius Rv [m] (facetCylinder's radius, pushed out so
    the faces are at Rin)."""

    def __init__(self, p, steel, height=None):
        self.Rin = p['diameter'] / 2
        self.Rv = self.Rin / math.cos(math.pi / p['segments'])
        height = height or p['height']
        # the side (wallMask 4) of facets; the bottom a wall in the same plane: the facetCylinder's bottom triangles
        # reach from the axis to the rim, so their bounding boxes paired every bottom grain with many of them
        # (the preparation took twice the time)
        facets = geom.facetCylinder((0, 0, height / 2), self.Rv, height, segmentsNumber=p['segments'], wallMask=4,
                                    material=steel, color=STEEL_COLOR, mask=STEEL_MASK)
        self.ids = O.bodies.append(facets)
        self.bottom = O.bodies.append(utils.wall(0.0, axis=2, sense=1, material=steel, color=STEEL_COLOR,
                                                 mask=STEEL_MASK))
        self.ids.append(self.bottom)
        self.pos0 = [Vector3(O.bodies[i].state.pos) for i in self.ids]

    def state(self):
        return {'Rin': self.Rin, 'Rv': self.Rv, 'ids': list(self.ids), 'bottom': self.bottom,
                'pos0': [list(x) for x in self.pos0]}

    @classmethod
    def fromState(cls, s):
        c = cls.__new__(cls)
        c.Rin, c.Rv, c.ids, c.bottom = s['Rin'], s['Rv'], s['ids'], s['bottom']
        c.pos0 = [Vector3(*x) for x in s['pos0']]
        return c


@runtime.persistent('OedometerRig')
class Rig:
    """What the packing builds and the loading and the outputs use: the cylinder and the ballast and steel
    materials (FrictMat in O.materials)."""

    def __init__(self, cylinder, ballast, steel):
        self.cylinder, self.ballast, self.steel = cylinder, ballast, steel

    def state(self):
        return {'cylinder': self.cylinder.state(), 'ballast': self.ballast.id, 'steel': self.steel.id}

    @classmethod
    def fromState(cls, s, ref=None):
        return cls(Cylinder.fromState(s['cylinder']), O.materials[s['ballast']], O.materials[s['steel']])


def rolling(p):
    """Whether the grains resist rolling (rollingFriction > 0; the paper's spheres do not)."""
    return p.get('rollingFriction', 0.0) > 0


def materials(p, young):
    """(ballast, steel) of section 4, appended to O.materials; steel is steelYoungRatio stiffer. The ballast is a
    FrictMat, or with rolling resistance (rolling(p)) YADE's CohFrictMat without cohesion: the linear law's
    stiffnesses and friction between grains, and a rolling moment kr theta_r (kr = rollingStiffness ks R1 R2)
    limited to rollingFriction min(R1, R2) Fn (YADE's Law2_ScGeom6D_CohFrictPhys_CohesionMoment)."""
    kw = dict(young=young, poisson=p['poisson'], frictionAngle=p['friction'], density=p['density'], label='ballast')
    if rolling(p):
        ballast = CohFrictMat(isCohesive=False, momentRotationLaw=True, alphaKr=p['rollingStiffness'],
                              etaRoll=p['rollingFriction'], alphaKtw=0.0, etaTwist=0.0, **kw)
    else:
        ballast = FrictMat(**kw)
    steel = FrictMat(young=p['steelYoungRatio'] * young, poisson=p['steelPoisson'], frictionAngle=p['steelFriction'],
                     density=p['steelDensity'], label='steel')
    O.materials.append(ballast)
    O.materials.append(steel)
    return ballast, steel


def engines(damping, law, rollingResistance=False):
    """ForceResetter, collider, interaction loop with the contact law, Newton with gravity. With rolling
    resistance (linear law only) grain pairs get ScGeom6D and CohFrictPhys with the moment law; contacts
    with steel keep ScGeom, FrictPhys and CundallStrack."""
    ip2, law2, _ = LAWS[law]
    sphere, ip2s, law2s = Ig2_Sphere_Sphere_ScGeom(), [ip2()], [law2()]
    if rollingResistance:
        sphere = Ig2_Sphere_Sphere_ScGeom6D()
        ip2s.append(Ip2_CohFrictMat_CohFrictMat_CohFrictPhys())
        law2s.append(Law2_ScGeom6D_CohFrictPhys_CohesionMoment(useIncrementalForm=True, always_use_moment_law=True))
    return [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb(), Bo1_Wall_Aabb(), Bo1_Box_Aabb()],
                              avoidSelfInteractionMask=AVOID),
        InteractionLoop([sphere, Ig2_Facet_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom(), Ig2_Box_Sphere_ScGeom()], ip2s,
                        law2s),
        NewtonIntegrator(damping=damping, gravity=GRAVITY, label='newton')]
