"""ballast.energy: kinetic and elastic energy of a few bodies against values worked out by hand."""
import math

import pytest
from yade import O, Quaternion, utils
from yade.wrapper import (Bo1_Sphere_Aabb, Bo1_Wall_Aabb, ForceResetter, Ig2_Sphere_Sphere_ScGeom,
                          Ig2_Wall_Sphere_ScGeom, InsertionSortCollider, InteractionLoop, Ip2_FrictMat_FrictMat_FrictPhys,
                          Law2_ScGeom_FrictPhys_CundallStrack, NewtonIntegrator)

from ballast import energy
from ballast.scenes import ballastMaterial, grainBetweenWalls, steelMaterial

R, OVERLAP = 0.02, 1e-4


def test_kinetic_by_hand():
    """A grain of mass m moving at v = (0.3, 0, 0.4) (|v| = 0.5) and spinning at w = 2 rad/s:
    1/2 m 0.25 + 1/2 (2/5 m R^2) 4."""
    g, w0, w1 = grainBetweenWalls(r=R, overlap=OVERLAP, block=False)
    b = O.bodies[g]
    b.state.vel, b.state.angVel = (0.3, 0.0, 0.4), (0.0, 2.0, 0.0)
    m = b.state.mass
    assert energy.kinetic([g]) == pytest.approx(0.5 * m * 0.25 + 0.5 * 0.4 * m * R ** 2 * 4, rel=1e-12)
    assert energy.kinetic([g, w0, w1]) == pytest.approx(energy.kinetic([g]), rel=1e-12)  # walls at rest


def test_kinetic_of_a_body_of_unequal_inertia_by_hand():
    """Principal moments (1, 2, 3) kg m^2 in the body's frame, turned 90 degrees about z, spinning at 1 rad/s
    about the global x axis, i.e. about its own -y: 1/2 2 1^2 = 1 J (not 1/2 I_x w^2 = 0.5 J)."""
    g, w0, w1 = grainBetweenWalls(r=R, overlap=OVERLAP, block=False)
    s = O.bodies[g].state
    s.vel, s.inertia, s.angVel = (0, 0, 0), (1.0, 2.0, 3.0), (1.0, 0.0, 0.0)
    s.ori = Quaternion((0, 0, 1), math.pi / 2)
    assert energy.rotational(s) == pytest.approx(1.0, rel=1e-14)
    assert energy.kinetic([g]) == pytest.approx(1.0, rel=1e-14)


def test_elastic_by_hand_hertz():
    """Two Hertz-Mindlin wall contacts of overlap u carrying Fn each: 2/5 Fn u per contact, no shear;
    each contact once even when both of its bodies are given."""
    g, w0, w1 = grainBetweenWalls(r=R, overlap=OVERLAP)
    O.run(1, True)
    e = 0.0
    for w in (w0, w1):
        i = O.interactions[g, w]
        e += 0.4 * i.phys.normalForce.norm() * i.geom.penetrationDepth
    assert e > 0
    assert energy.elastic([g]) == pytest.approx(e, rel=1e-12)
    assert energy.elastic([g, w0, w1]) == pytest.approx(e, rel=1e-12)
    assert energy.partners([g]) == sorted([w0, w1])
    k, el = energy.snapshot([g])
    assert el == pytest.approx(e, rel=1e-12) and k == pytest.approx(energy.kinetic([g]), rel=1e-12)
    # the closed form: Fn = kno u^1.5, so 2/5 Fn u = 2/5 kno u^2.5
    i = O.interactions[g, w1]
    assert 0.4 * i.phys.normalForce.norm() * i.geom.penetrationDepth == pytest.approx(
        0.4 * i.phys.kno * i.geom.penetrationDepth ** 2.5, rel=1e-9)
    assert math.isfinite(e)


def _clumpBetweenWalls():
    """Two members of radius R, 1.2 R apart along x, clumped, pressed along z by two fixed walls at +-(R - OVERLAP)
    (YADE's linear law): each member touches each wall. Returns (clump id, member ids, wall ids)."""
    O.reset()
    steel, ballast = steelMaterial(E=3e12), ballastMaterial(E=3e11)
    O.materials.append(steel)
    O.materials.append(ballast)
    cid, members = O.bodies.appendClumped([utils.sphere((x, 0, 0), R, material=ballast) for x in (-0.6 * R, 0.6 * R)])
    walls = [O.bodies.append(utils.wall(s * (R - OVERLAP), axis=2, sense=-s, material=steel)) for s in (-1, 1)]
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                                 [Law2_ScGeom_FrictPhys_CundallStrack()]), NewtonIntegrator(gravity=(0, 0, 0), damping=0.0)]
    O.dt = 0.5 * utils.PWaveTimeStep()
    return cid, sorted(members), walls


def test_a_clump_stores_in_its_members_contacts_and_moves_once():
    """A clump has no contacts of its own: its members do. Four member-wall contacts, each Fn^2 / (2 kn) (no shear:
    the walls press along the contact normals); the partners are the two walls; the kinetic energy is the clump's
    1/2 M v^2 (YADE integrates the clump; the members' own masses are not a second body), whether the clump, a
    member or both are given. Before 2026-12-06 a clump's snapshot read none of its members' contacts (0 J)."""
    cid, members, walls = _clumpBetweenWalls()
    O.run(1, True)
    e, n = 0.0, 0
    for m in members:
        for w in walls:
            i = O.interactions[m, w]
            assert i.isReal
            e += 0.5 * i.phys.normalForce.norm() ** 2 / i.phys.kn
            n += 1
    assert n == 4 and e > 0
    for ids in ([cid], members[:1], [cid] + members):
        assert energy.elastic(ids) == pytest.approx(e, rel=1e-12)
        assert energy.partners(ids) == sorted(walls)
    c = O.bodies[cid].state
    c.vel, c.angVel = (0.3, 0.0, 0.4), (0.0, 0.0, 0.0)
    want = 0.5 * c.mass * 0.25
    for ids in ([cid], members, [cid] + members + walls):
        assert energy.kinetic(ids) == pytest.approx(want, rel=1e-12)
    k, el = energy.snapshot([cid])
    assert k == pytest.approx(want, rel=1e-12) and el == pytest.approx(e, rel=1e-12)
    assert energy.partners(walls[:1]) == [cid]   # a wall's partner is the grain, not the member it touches
