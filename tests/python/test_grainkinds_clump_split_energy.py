"""A split clump's pieces inject no energy (issue 47: a clump box exploded when its clumps crushed). Every pair of
members of two pieces that still overlap must carry no force until they part: held members (inside another) and
members moved by absorbEmpty included, and through a later resize or a later crush of a piece. Debian's
/usr/bin/python3, YADE as a module.

The grain is the builder's default shape with seed 1 (r_eq = 20 mm): its member 6 lies wholly inside member 3
(clumpshapes.containers), so the planes cut the clump without it and it goes with member 3. By hand, for a clump in
free flight (no gravity, no damping, no other body) moving at v without spin: every piece moves at v after the split
(v_p = v + w x (x_p - X'), w = 0), no force acts on a piece, so the kinetic energy stays 1/2 M v^2 and the elastic
energy 0, step after step."""
import math

import numpy as np
import pytest
from yade import O, Vector3, utils
from yade.wrapper import (Bo1_Sphere_Aabb, Bo1_Wall_Aabb, CohFrictMat, ForceResetter, Ig2_Sphere_Sphere_ScGeom,
                          Ig2_Sphere_Sphere_ScGeom6D, Ig2_Wall_Sphere_ScGeom, InsertionSortCollider, InteractionLoop,
                          Ip2_CohFrictMat_CohFrictMat_CohFrictPhys, Ip2_FrictMat_FrictMat_FrictPhys,
                          Law2_ScGeom6D_CohFrictPhys_CohesionMoment, Law2_ScGeom_FrictPhys_CundallStrack,
                          NewtonIntegrator)

from ballast import contacts, energy, grainkinds
from ballast.engines import BallastCrushEngine
from ballast.grainkinds import clump
from ballast.grainkinds.clumpshapes import containers
from ballast.scenes import hertzEngines
from test_grainkinds_clump import _scene as clumpScene

REQ, SEED, DT_SAFETY = 0.02, 1, 0.8   # [m], the shape's seed, O.dt / PWaveTimeStep() (the experiments' default)
V = Vector3(0.1, -0.05, 0.02)         # [m/s]
STEPS = 100                           # the pieces keep their overlaps: they move together at V


def linearEngines(rolling=False):
    """YADE's default linear law (FrictPhys, CundallStrack), or with rolling resistance between grains the box's
    default (CohFrictPhys and its moment law, experiments/scene.py), without gravity or damping."""
    sphere, ip2s, law2s = Ig2_Sphere_Sphere_ScGeom(), [Ip2_FrictMat_FrictMat_FrictPhys()], [
        Law2_ScGeom_FrictPhys_CundallStrack()]
    if rolling:
        sphere = Ig2_Sphere_Sphere_ScGeom6D()
        ip2s.append(Ip2_CohFrictMat_CohFrictMat_CohFrictPhys())
        law2s.append(Law2_ScGeom6D_CohFrictPhys_CohesionMoment(useIncrementalForm=True, always_use_moment_law=True))
    return [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()]),
            InteractionLoop([sphere, Ig2_Wall_Sphere_ScGeom()], ip2s, law2s),
            NewtonIntegrator(gravity=(0, 0, 0), damping=0.0)]


LAWS = {'linear': linearEngines, 'rolling': lambda: linearEngines(True), 'hertz': hertzEngines}


def _scene(law):
    """(steel, ballast) and the law's engines; with rolling resistance the ballast is the box's CohFrictMat."""
    steel, mat = clumpScene()
    if law == 'rolling':
        mat = CohFrictMat(young=mat.young, poisson=mat.poisson, density=mat.density, frictionAngle=mat.frictionAngle,
                          isCohesive=False, momentRotationLaw=True, alphaKr=2.0, etaRoll=0.3, alphaKtw=0.0,
                          etaTwist=0.0)
        O.materials.append(mat)
    O.engines = LAWS[law]()
    return steel, mat


def _members(i):
    b = O.bodies[i]
    return sorted(b.shape.members.keys()) if b.isClump else [i]


def _heldClump(law):
    steel, mat = _scene(law)
    cid = clump.addClump((0, 0, 0), REQ, mat, seed=SEED)
    members = _members(cid)
    holder = containers([tuple(O.bodies[m].state.pos) for m in members], [O.bodies[m].shape.radius for m in members])
    assert holder.tolist() == [-1, -1, -1, -1, -1, -1, 3, -1]   # member 6 inside member 3: the case under test
    O.dt = DT_SAFETY * utils.PWaveTimeStep()
    return steel, mat, cid, members


def _crossOverlaps(pieces):
    """Pairs of members of different pieces that overlap, by position."""
    own = {m: p for p in pieces for m in _members(p)}
    ids = sorted(own)
    out = []
    for a in ids:
        for b in ids:
            A, B = O.bodies[a], O.bodies[b]
            if a < b and own[a] != own[b] and (A.state.pos - B.state.pos).norm() < A.shape.radius + B.shape.radius:
                out.append((a, b))
    return out


@pytest.mark.parametrize('law', sorted(LAWS))
@pytest.mark.parametrize('axis', [0, 1, 2])
def test_a_split_in_free_flight_keeps_the_energy(law, axis):
    """Uniaxial compression along x, y or z. After the split the kinetic energy is 1/2 M v^2 (to 1e-12), after STEPS
    steps the kinetic + elastic energy still is (to 1e-9), and every overlap between pieces, still there, has a
    silenced contact. Before the fix the held member's overlaps with other pieces were left to the collider, which
    made full-stiffness contacts pressed by up to 1.46 member radii: the energy rose from 5.6e-4 J to 65-1156 J in
    100 steps."""
    steel, mat, cid, members = _heldClump(law)
    O.bodies[cid].state.vel = V
    M = O.bodies[cid].state.mass
    E0 = 0.5 * M * V.squaredNorm()
    n = np.eye(3)[axis]
    rep = grainkinds.current().crush(cid, -1e6 * np.outer(n, n), lambda: pytest.fail('a clump has no fragments'),
                                     False)
    cross = _crossOverlaps(rep.ids)
    assert cross, 'the cut must leave overlaps between pieces'
    assert utils.kineticEnergy() == pytest.approx(E0, rel=1e-12)
    O.run(STEPS, True)
    ids = [b.id for b in O.bodies]
    assert utils.kineticEnergy() + energy.elastic(ids) == pytest.approx(E0, rel=1e-9)
    assert _crossOverlaps(rep.ids) == cross   # still overlapping: the silenced contacts were in use all along
    for a, b in cross:
        assert O.interactions.has(a, b) and contacts.silenced(O.interactions[a, b].phys), (a, b)
    assert sorted(map(tuple, rep.split['silenced'])) == cross


def test_the_member_held_inside_another_has_its_overlaps_silenced_in_some_cut():
    """Of the three cuts above, at least one puts member 6 (held by member 3) in a piece next to a member of another
    piece it overlaps: the pairs of the C++ cut (free members only) never held it."""
    found = []
    for axis in range(3):
        steel, mat, cid, members = _heldClump('linear')
        n = np.eye(3)[axis]
        rep = grainkinds.current().crush(cid, -1e6 * np.outer(n, n), None, False)
        found += [p for p in map(tuple, rep.split['silenced']) if members[6] in p]
    assert found


def test_every_piece_steps_stably_after_a_crush_by_the_engine():
    """The clump pressed between two walls along z and crushed by the engine (adjustDt: O.dt scaled with the drop of
    PWaveTimeStep()). A piece's mass is its share of the volume, below density x its members' union, while its
    contacts are its members' (kn = E r against an equal sphere at the linear law, at most E r_max): its step
    sqrt(m / (E r_max)) must not fall below the step O.dt was made from, O.dt / dtSafety. A free sphere of radius r
    has sqrt(rho 4/3 pi r^3 / (E r)) = 2.05 r sqrt(rho / E), 2.05 times its P-wave step."""
    steel, mat, cid, members = _heldClump('linear')
    low = min(O.bodies[m].state.pos[2] - O.bodies[m].shape.radius for m in members)
    high = max(O.bodies[m].state.pos[2] + O.bodies[m].shape.radius for m in members)
    O.bodies.append(utils.wall(low + 1e-4, axis=2, sense=1, material=steel))
    O.bodies.append(utils.wall(high - 1e-4, axis=2, sense=-1, material=steel))
    crush = BallastCrushEngine(ft0=1e-6, rMin=1e-3, iterPeriod=1, label='crush')
    O.engines = O.engines + [crush]
    O.run(2, True)
    assert crush.nCrushed >= 1
    pieces = [i for e in crush.events for i in e['newIds'] if O.bodies[i] is not None]
    assert O.dt <= DT_SAFETY * utils.PWaveTimeStep() * (1 + 1e-12)
    for i in pieces:
        rmax = max(O.bodies[m].shape.radius for m in _members(i))
        assert math.sqrt(O.bodies[i].state.mass / (mat.young * rmax)) >= O.dt / DT_SAFETY, i


@pytest.mark.parametrize('law', sorted(LAWS))
def test_a_silenced_contact_stays_silent_when_a_piece_is_resized(law):
    """Two pieces' members overlapping by half a radius, silenced; the sphere shrinks by 0.9 (abrasion, or a later
    split shrinking a one-member piece). The contact keeps no stiffness: at the new radius it would press them apart
    by an overlap of 0.4 R (before the fix: kn = 0.9 E R at the linear law; with rolling resistance the contact's
    physics was dropped and YADE made it afresh, at full stiffness)."""
    steel, mat = _scene(law)
    R = 0.01
    a = O.bodies.append(utils.sphere((0, 0, 0), R, material=mat))
    b = O.bodies.append(utils.sphere((1.5 * R, 0, 0), R, material=mat))
    contacts.silence(utils.createInteraction(a, b))
    O.dt = DT_SAFETY * utils.PWaveTimeStep()
    grainkinds.current().abrade(a, 0.9)
    i = O.interactions[a, b]
    assert i.isReal and contacts.silenced(i.phys)
    O.run(10, True)
    assert utils.kineticEnergy() == 0 and O.bodies[a].state.pos == Vector3(0, 0, 0)


def test_the_fragments_of_a_silenced_piece_inherit_the_silence():
    """A one-member piece (a free sphere) overlapping a member of another piece by half a radius through a silenced
    contact crushes into the paper's fragments. A fragment placed in that overlap gets a silenced contact too (the
    collider would give it full stiffness at a depth of 0.4 R); the scene, at rest, stays at rest."""
    steel, mat = _scene('rolling')
    R = 0.01
    a = O.bodies.append(utils.sphere((0, 0, 0), R, material=mat))
    b = O.bodies.append(utils.sphere((1.5 * R, 0, 0), R, material=mat))
    contacts.silence(utils.createInteraction(a, b))
    O.dt = DT_SAFETY * utils.PWaveTimeStep()
    frags = np.array([[0.5 * R, 0, 0, 0.4 * R], [-0.5 * R, 0, 0, 0.4 * R]])   # the first 0.4 R into b
    rep = grainkinds.current().crush(a, np.zeros((3, 3)), lambda: frags, False)
    f0, f1 = rep.ids
    assert contacts.silenced(O.interactions[f0, b].phys)
    assert not O.interactions.has(f1, b)   # 2 R from b's centre, 1.4 R of radii: apart
    O.run(10, True)
    assert utils.kineticEnergy() == 0


def test_a_clump_inside_one_member_crushes_as_that_sphere():
    """A core of radius R holding a member of 0.3 R at 0.4 R (inside it: 0.4 + 0.3 < 1) is one sphere: its union is
    the core's, V = 4/3 pi R^3. No plane cuts it; before the fix the split gave one piece, clumped again under a new id
    and crushed again at every check. It crushes as the sphere: the clump and both members go, the fragments given
    take their place, and the ledger sees the sphere of V and the clump's mass M."""
    steel, mat = _scene('linear')
    R = 0.01
    VS = 4 / 3 * math.pi * R ** 3
    cid = clump.appendClump([utils.sphere((0, 0, 0), R, material=mat), utils.sphere((0.4 * R, 0, 0), 0.3 * R,
                                                                                       material=mat)], VS)
    members = _members(cid)
    M = O.bodies[cid].state.mass
    O.bodies[cid].state.vel = V
    frags = np.array([[0.5 * R, 0, 0, 0.4 * R], [-0.5 * R, 0, 0, 0.4 * R]])
    rep = grainkinds.current().crush(cid, -1e6 * np.diag([1.0, 0, 0]), lambda: frags, False)
    assert rep.split is None and len(rep.ids) == 2
    assert O.bodies[cid] is None and all(O.bodies[m] is None for m in members)
    assert [O.bodies[i].shape.radius for i in rep.ids] == [0.4 * R, 0.4 * R]
    assert rep.volumeBefore == pytest.approx(VS, rel=1e-12) and rep.massBefore == pytest.approx(M, rel=1e-12)
    assert all(O.bodies[i].state.vel == V for i in rep.ids)   # no spin: the clump's velocity
