"""Crushing a clump (issue 47, item 2; ballast.grainkinds.clump ClumpKind.crush/split and the crushing engine),
against values worked out by hand. The hand clump has four members of radius R at (+-A, +-B, 0): neighbours 2A and
2B apart overlap, the diagonals do not, so no point lies in three members and its union volume is exactly
4 V_s - 2 (lens(2A) + lens(2B)), lens(d) = pi (4R + d)(2R - d)^2 / 12 the volume two spheres of radius R at
distance d share. Debian's /usr/bin/python3, YADE as a module."""
import math

import numpy as np
import pytest
from yade import O, Vector3, utils

from ballast import grainkinds
from ballast.engines import BallastCrushEngine
from ballast.grainkinds import clump
from ballast.scenes import hertzEngines
from test_grainkinds_clump import _scene as clumpScene

R, OV = 0.01, 1e-4
A, B = 0.005, 0.0095      # B > A tan 60: under tension turned 30 degrees the pieces change (see below)
VS = 4 / 3 * math.pi * R ** 3


def lens(d):
    return math.pi * (4 * R + d) * (2 * R - d) ** 2 / 12


V0 = 4 * VS - 2 * (lens(2 * A) + lens(2 * B))


def _scene():
    steel, mat = clumpScene()   # steel walls E = 1e10 Pa, ballast E = 1e9 Pa, kind 'clump'
    members = [utils.sphere((x, y, 0), R, material=mat) for x, y in ((A, B), (A, -B), (-A, B), (-A, -B))]
    cid = clump.appendClump(members, V0)
    return steel, cid, sorted(O.bodies[cid].shape.members.keys())


def _overlaps(ids):
    """Pairs of the spheres ids that overlap, by position."""
    out = set()
    for i in ids:
        for j in ids:
            if i < j and (O.bodies[i].state.pos - O.bodies[j].state.pos).norm() < (O.bodies[i].shape.radius
                                                                                   + O.bodies[j].shape.radius):
                out.add((i, j))
    return out


def _pressed(axis):
    """The hand clump between two walls normal to axis, with a crushing engine that crushes it at once (ft0 tiny)
    but not the one-member pieces (rMin between R and its r_eq)."""
    steel, cid, members = _scene()
    for sense, pos in ((1, -(R - OV)), (-1, R - OV)):
        O.bodies.append(utils.wall(pos if axis == 2 else (A + R - OV) * -sense, axis=axis, sense=sense, material=steel))
    crush = BallastCrushEngine(ft0=1e-6, rMin=1.2 * R, iterPeriod=1, label='crush')
    O.engines = hertzEngines() + [crush]
    O.dt = 0.2 * utils.PWaveTimeStep()
    return cid, members, crush


def test_pressed_between_walls_along_z_four_sphere_grains_mass_kept_and_the_ledger_by_hand():
    """Compression along z: s1 = s2 > 0 on x and y (one eigenspace), the first plane across the longest spread
    (y, B > A), the second across x: four pieces of one member, each now a sphere grain."""
    cid, members, crush = _pressed(2)
    M = O.bodies[cid].state.mass
    before = _overlaps(members)
    assert before == {(members[0], members[1]), (members[0], members[2]), (members[1], members[3]),
                      (members[2], members[3])}
    O.run(3, True)
    assert crush.nCrushed == 1 and O.bodies[cid] is None
    e = crush.events[0]
    k = grainkinds.current()
    assert sorted(e['newIds']) == members and sorted(k.ids().tolist()) == members   # no member lost or duplicated
    assert all(not O.bodies[i].isClumpMember and k.isGrain(O.bodies[i]) for i in members)
    assert e['split']['pieces'] == 4 and not e['split']['median']
    np.testing.assert_allclose(e['split']['normals'], [[0, 1, 0], [1, 0, 0]], atol=1e-9)
    # the volume partitioned: a lens shared by two pieces is halved by the radical plane (deepest member), so by
    # symmetry each piece holds V0 / 4 (Monte Carlo shares: within 3 %); volume and mass sum to the clump's exactly
    q = np.array(e['split']['shares'])
    assert q.sum() == pytest.approx(1, abs=1e-14)
    np.testing.assert_allclose(q, 0.25, rtol=0.03)
    vols, masses = k.volumes(members), k.masses(members)
    assert vols.sum() == pytest.approx(V0, rel=1e-12) and crush.volumeLost == pytest.approx(0, abs=1e-12 * V0)
    assert abs(masses.sum() / M - 1) < 1e-12 and crush.massLost == pytest.approx(0, abs=1e-12 * M)
    np.testing.assert_allclose(masses / M, vols / V0, rtol=1e-12)   # the density kept
    # each a sphere grain shrunk to its volume: r' = (3 V0 q / (4 pi))^(1/3), by hand (3 V0 / (16 pi))^(1/3)
    np.testing.assert_allclose(k.radii(members), (3 * V0 * q / (4 * math.pi)) ** (1 / 3), rtol=1e-12)
    r1 = (3 * V0 / (16 * math.pi)) ** (1 / 3)
    np.testing.assert_allclose(k.radii(members), r1, rtol=0.01)
    # no new overlap: shrunk to r1 (2 r1 = 0.01889 m) the pairs 2B = 0.019 m apart part, those 2A apart still
    # overlap, each with a contact without force
    assert 2 * r1 < 2 * B and 2 * r1 > 2 * A
    kept = {(members[0], members[2]), (members[1], members[3])}
    assert _overlaps(members) == kept and {tuple(p) for p in e['split']['silenced']} == kept
    O.run(20, True)
    for i, j in kept:
        c = O.interactions[i, j]
        assert c.isReal and c.phys.normalForce.norm() == 0 and c.phys.shearForce.norm() == 0


def test_pressed_along_x_two_clump_pieces_with_their_share_of_the_volume():
    """Compression along x: y and z tensile relative to the mean, one eigenspace; the members spread along y only,
    so the first plane is y = 0 and the second (z = 0) leaves all members on one side: two pieces of two members,
    (+-A, B) and (+-A, -B), clumped again."""
    cid, members, crush = _pressed(0)
    M = O.bodies[cid].state.mass
    O.run(3, True)
    assert crush.nCrushed == 1
    e = crush.events[0]
    k = grainkinds.current()
    ids = e['newIds']
    assert len(ids) == 2 and all(O.bodies[i].isClump for i in ids) and sorted(k.ids().tolist()) == sorted(ids)
    assert [sorted(O.bodies[i].shape.members.keys()) for i in ids] == [[members[0], members[2]],
                                                                      [members[1], members[3]]]
    assert abs(k.masses(ids).sum() / M - 1) < 1e-12
    # each piece: two members 2A apart and half of each lens 2B apart cut by y = 0, V0 / 2 by symmetry (Monte
    # Carlo shares, 100 000 points: within 2 %); the two sum to V0 exactly, nothing lost
    np.testing.assert_allclose(k.volumes(ids), V0 / 2, rtol=2e-2)
    assert k.volumes(ids).sum() == pytest.approx(V0, rel=1e-12) and crush.volumeLost == pytest.approx(0, abs=1e-12 * V0)
    assert O.bodies[ids[0]].material.young == 1e9   # the clump body's material: the grain table and moduli() read it


def test_split_follows_the_planes_turned_30_degrees_and_keeps_momentum():
    """Uniaxial tension along n = (cos 30, sin 30, 0) on a moving, spinning clump: the plane normal to n puts
    (A, B) and (-A, B) on its positive side (A cos30 - B sin30 < 0 since B > A tan 60); under tension along x the
    pieces would be the members at x = +A and x = -A."""
    steel, cid, members = _scene()
    O.engines = hertzEngines()
    c = O.bodies[cid].state
    c.vel, c.angVel = Vector3(0.3, -0.1, 0.2), Vector3(5.0, -2.0, 7.0)
    M, P = c.mass, c.mass * Vector3(c.vel)
    t = math.radians(30)
    n = np.array([math.cos(t), math.sin(t), 0])
    k = grainkinds.current()
    rep = k.crush(cid, 1e6 * np.outer(n, n), lambda: pytest.fail('a clump uses no sphere fragments'), False)
    assert rep.split['pieces'] == 2 and rep.volumeRatio == 1
    np.testing.assert_allclose(rep.split['normals'], [n], atol=1e-12)
    assert [sorted(O.bodies[i].shape.members.keys()) for i in rep.ids] == [[members[0], members[2]],
                                                                          [members[1], members[3]]]
    x = np.diag([1e6, 0, 0])
    assert clump._ballast.clumpSplit(x, (0, 0, 0), [(A, B, 0), (A, -B, 0), (-A, B, 0), (-A, -B, 0)],
                                     [R] * 4)['piece'].tolist() == [0, 0, 1, 1]
    pieces = [O.bodies[i].state for i in rep.ids]
    assert abs(sum(s.mass for s in pieces) / M - 1) < 1e-12 and rep.massAfter == pytest.approx(M, rel=1e-12)
    Pn = sum((s.mass * s.vel for s in pieces), Vector3(0, 0, 0))
    assert (Pn - P).norm() < 1e-12 * P.norm()
    assert all(s.angVel == Vector3(5.0, -2.0, 7.0) for s in pieces)


def test_a_sphere_piece_follows_the_sphere_model():
    """A free sphere of a clump scene is a grain: its stress is YADE's own tensor, its crush the paper's fragments."""
    cid, members, crush = _pressed(2)
    O.run(3, True)
    k = grainkinds.current()
    S = k.stressTensors()
    own = clump._ballast.matricesToArray(utils.bodyStressTensors())
    np.testing.assert_array_equal(S[members], own[members])
    rep = k.crush(members[0], S[members[0]], lambda: np.array([[0.0, B, 0, 0.4 * R], [A, B, 0, 0.4 * R]]), False)
    assert rep.split is None and len(rep.ids) == 2 and rep.radii.tolist() == [0.4 * R, 0.4 * R]
    other = clump.addClump((1, 1, 1), 0.02, O.bodies[members[1]].material)
    with pytest.raises(ValueError, match='is a clump; a crushed clump splits'):
        k.replace(other, None, True)


def test_a_member_held_whole_by_another_goes_with_it_across_the_plane():
    """A member inside another (a small sphere of the builder placed within the core) adds nothing to the union: the
    clump is cut without it and it goes with the member that holds it, wherever the plane passes. Here the core
    (R at the origin) and a tip (R/2 at 1.2 R) under tension along x: the plane normal to x through the centre of
    mass (between them, 0 < X < 0.5 R) would put the small member (0.2 R at 0.5 R, inside the core) with the tip
    and give it a piece of no volume of its own there; it goes with the core, the mass is kept."""
    steel, mat = clumpScene()
    spheres = [utils.sphere(x, r, material=mat) for x, r in (((0, 0, 0), R), ((1.2 * R, 0, 0), R / 2),
                                                             ((0.5 * R, 0, 0), 0.2 * R))]
    d, r2 = 1.2 * R, R / 2   # the union: core + tip - their lens (the small member adds nothing)
    lens = math.pi * (R + r2 - d) ** 2 * (d * d + 2 * d * (R + r2) - 3 * (R - r2) ** 2) / (12 * d)
    V = VS + 4 / 3 * math.pi * r2 ** 3 - lens
    cid = clump.appendClump(spheres, V)
    members = sorted(O.bodies[cid].shape.members.keys())
    X = O.bodies[cid].state.pos[0]
    assert 0 < X < 0.5 * R
    O.engines = hertzEngines()
    M = O.bodies[cid].state.mass
    k = grainkinds.current()
    rep = k.crush(cid, np.diag([1e6, 0, 0]), lambda: pytest.fail('a clump uses no sphere fragments'), False)
    assert rep.split['pieces'] == 2
    groups = sorted(sorted(O.bodies[i].shape.members.keys()) if O.bodies[i].isClump else [i] for i in rep.ids)
    assert groups == [[members[0], members[2]], [members[1]]]
    assert abs(sum(O.bodies[i].state.mass for i in rep.ids) / M - 1) < 1e-12
