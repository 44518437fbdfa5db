"""The scene every experiment shares (section 4): the ballast and steel materials, and the engine chain
with the contact law (``law``: YADE's linear ``FrictPhys`` + ``CundallStrack``, or Hertz-Mindlin), with
rolling resistance as an option. The containers are :mod:`.containers`.

Group masks: grains GRAIN_MASK, steel (walls, facets, platens, a sleeper) STEEL_MASK, and the collider's
avoidSelfInteractionMask = AVOID: steel bodies share a mask within AVOID, so the collider pairs them
with grains only. Without it the 144 cylinder facets and the plate of the oedometer held about 1 700
potential interactions with each other, half of the scene's.
"""
from yade import O
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


def polyhedronModulus(p, young):
    """The volumetric modulus Y [N/m^3] of YADE's PolyhedraMat for a Young's modulus young [Pa]: Y = young / r_ref with
    r_ref = (dMin + dMax) / 4, the mean grain radius, so a grain of r_ref pressed face on over an area about r_ref^2
    (Y r^2 / 2, the two moduli in series) is about as stiff as a sphere of the linear law (E r / 2 ... E r): the
    choice of this comparison (docs/grains.md, "Polyhedra")."""
    return young / ((p['dMin'] + p['dMax']) / 4)


def polyhedronMaterials(p, young):
    """(ballast, steel) for a polyhedron scene: YADE's PolyhedraMat (the volumetric law pairs only PolyhedraMat),
    moduli polyhedronModulus of young and of steelYoungRatio young, the ballast split by YADE's PolyhedraSplitter
    (strength ft0 / 1000: engines.polyhedra.yadeStrength), the steel never; appended to O.materials."""
    from yade.wrapper import PolyhedraMat
    from ..engines.polyhedra import yadeStrength
    out = []
    for label, E, nu, phi, rho, split in (
            ('ballast', young, p['poisson'], p['friction'], p['density'], True),
            ('steel', p['steelYoungRatio'] * young, p['steelPoisson'], p['steelFriction'], p['steelDensity'], False)):
        m = PolyhedraMat()   # set one by one: the keyword constructor left young at 1e9 (measured)
        m.young, m.poisson, m.frictionAngle, m.density, m.label = polyhedronModulus(p, E), nu, phi, rho, label
        m.IsSplitable, m.strength = split, yadeStrength(p['ft0'])
        O.materials.append(m)
        out.append(m)
    return tuple(out)


def polyhedronEngines(damping, gravity=GRAVITY):
    """ForceResetter, collider, the volumetric law between polyhedra and with facets and walls, Newton. YADE's warning
    'Unhandled switch case:0' of Polyhedra_support.cpp (a pair that overlapped at the last step, every step of every
    contact) is silenced: printing it took most of a step's time (measured, 11 grains in the oedometer)."""
    from yade import log
    log.setLevel('Polyhedra_support.cpp', log.ERROR)
    from yade.wrapper import (Bo1_Polyhedra_Aabb, Ig2_Facet_Polyhedra_PolyhedraGeom, Ig2_Polyhedra_Polyhedra_PolyhedraGeom,
                              Ig2_Wall_Polyhedra_PolyhedraGeom, Ip2_PolyhedraMat_PolyhedraMat_PolyhedraPhys,
                              Law2_PolyhedraGeom_PolyhedraPhys_Volumetric)
    return [
        ForceResetter(),
        InsertionSortCollider([Bo1_Polyhedra_Aabb(), Bo1_Facet_Aabb(), Bo1_Wall_Aabb()], avoidSelfInteractionMask=AVOID),
        InteractionLoop([Ig2_Polyhedra_Polyhedra_PolyhedraGeom(), Ig2_Facet_Polyhedra_PolyhedraGeom(),
                         Ig2_Wall_Polyhedra_PolyhedraGeom()], [Ip2_PolyhedraMat_PolyhedraMat_PolyhedraPhys()],
                        [Law2_PolyhedraGeom_PolyhedraPhys_Volumetric()]),
        NewtonIntegrator(damping=damping, gravity=gravity, label='newton')]


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


def sceneMaterials(p, young):
    """(ballast, steel) of p's grain kind: polyhedronMaterials with grain 'polyhedron', else materials."""
    return polyhedronMaterials(p, young) if p.get('grain') == 'polyhedron' else materials(p, young)


def sceneEngines(p, damping):
    """The engine chain of p's grain kind: polyhedronEngines with grain 'polyhedron', else engines with p's law and
    rolling resistance."""
    return polyhedronEngines(damping) if p.get('grain') == 'polyhedron' else engines(damping, p['law'], rolling(p))
