"""Corner wear of a clump (issue 47, item 3; ballast.grainkinds.clump ClumpKind.abrade and the abrasion engine),
against values worked out by hand. The hand clump has two members along z, a large one (radius R1) below and a small
one (R2) above, their centres D apart; a wall presses each from outside. With Hertz contacts eq. 7 is
p0 = 3 F / (2 pi R uN) = (2 E*/pi) sqrt(uN / R) at a wall (R the member's radius), so at equal overlaps the small
member has the larger pressure; a strength between the two wears it alone. The union of two spheres is
4/3 pi (r1^3 + r2^3) - lens(d; r1, r2), with the lens two spheres of radii r1, r2 at distance d share
(|r1 - r2| < d < r1 + r2):

    lens(d; r1, r2) = pi (r1 + r2 - d)^2 (d^2 + 2 d (r1 + r2) - 3 (r1 - r2)^2) / (12 d).

Debian's /usr/bin/python3, YADE as a module."""
import math

import numpy as np
import pytest
from yade import O, utils

from ballast import grainkinds, harvest
from ballast.engines import BallastAbrasionEngine
from ballast.grainkinds import clump
from ballast.grainkinds.clumpshapes import SHELL_SAMPLES, shellOutside
from ballast.scenes import hertzEngines
from test_grainkinds_clump import _scene as clumpScene

R1, R2, D, OV = 0.012, 0.008, 0.012, 1e-4
GAMMA = 0.9


def sphere(r):
    return 4 / 3 * math.pi * r ** 3


def lens(d, r1, r2):
    return math.pi * (r1 + r2 - d) ** 2 * (d * d + 2 * d * (r1 + r2) - 3 * (r1 - r2) ** 2) / (12 * d)


def union(r1, r2):
    return sphere(r1) + sphere(r2) - lens(D, r1, r2)


V0 = union(R1, R2)


def test_lens_formula_by_hand():
    """The general lens against its equal-radius form pi (4R + d)(2R - d)^2 / 12 and its limits."""
    assert lens(0.015, 0.01, 0.01) == pytest.approx(math.pi * (0.04 + 0.015) * (0.02 - 0.015) ** 2 / 12, rel=1e-14)
    assert lens(R1 + R2, R1, R2) == 0
    assert lens(R1 - R2, R1, R2) == pytest.approx(sphere(R2), rel=1e-12)   # the small sphere just inside


def _pressed(strength, rMin=0.0):
    """The hand clump between two walls normal to z, each overlapping its member by OV, free along z only, one step
    run; then an abrasion engine. Returns (clump id, lower member, upper member, engine)."""
    steel, mat = clumpScene()
    z1, z2 = -D / 2, D / 2
    low, up = utils.sphere((0, 0, z1), R1, material=mat), utils.sphere((0, 0, z2), R2, material=mat)
    cid = clump.appendClump([low, up], V0)
    O.bodies[cid].state.blockedDOFs = 'xyXYZ'
    O.bodies.append(utils.wall(z1 - R1 + OV, axis=2, sense=1, material=steel))
    O.bodies.append(utils.wall(z2 + R2 - OV, axis=2, sense=-1, material=steel))
    O.engines = hertzEngines()
    O.dt = 0.2 * utils.PWaveTimeStep()
    O.run(1, True)
    ab = BallastAbrasionEngine(strength=strength, gamma=GAMMA, rMin=rMin, iterPeriod=1, label='abrasion')
    O.engines = O.engines + [ab]
    return cid, low.id, up.id, ab


def _p0(mid, r):
    """Eq. 7 at the member's wall contact, by hand from the contact YADE computed: 3 F / (2 pi r uN)."""
    (i,) = [i for i in O.bodies[mid].intrs() if i.isReal]
    F = i.phys.normalForce.dot(i.geom.normal)
    return 3 * abs(F) / (2 * math.pi * r * i.geom.penetrationDepth), i


def _strengthBetween():
    """A strength between the two members' pressures, from a probe run (equal overlaps: p0 = (2 E*/pi) sqrt(uN / R)
    of eq. 7 with the Hertz law, in the ratio sqrt(R1/R2))."""
    _, low, up, _ = _pressed(1e30)
    O.run(1, True)
    p1, p2 = _p0(low, R1)[0], _p0(up, R2)[0]
    assert p2 / p1 == pytest.approx(math.sqrt(R1 / R2), rel=0.01)
    return math.sqrt(p1 * p2)


def test_the_pressed_member_alone_shrinks_by_gamma_volume_mass_ledger_by_hand():
    strength = _strengthBetween()
    cid, low, up, ab = _pressed(strength)
    k = grainkinds.current()
    M0, J0 = O.bodies[cid].state.mass, np.array(O.bodies[cid].state.inertia)   # a copy: YADE gives a view
    O.run(1, True)
    p1, _ = _p0(low, R1)
    p2, i2 = _p0(up, R2)     # the contact as the engine read it (forces and overlap are not changed by the wear)
    assert p1 < strength < p2
    assert ab.nAbraded == 1
    e = ab.events[0]
    assert e['id'] == cid and e['member'] == up and e['value'] == pytest.approx(p2, rel=1e-12)
    assert e['radius'] == pytest.approx((3 * V0 / (4 * math.pi)) ** (1 / 3), rel=1e-12)   # r_eq before
    assert O.bodies[up].shape.radius == pytest.approx(GAMMA * R2, rel=1e-15)
    assert O.bodies[low].shape.radius == R1                                        # the other member untouched
    assert O.bodies[up].isClumpMember and O.bodies[up].clumpId == cid and k.ids().tolist() == [cid]
    # the member's contact as YADE would create it at the new radius
    assert (i2.geom.refR1 if i2.id1 == up else i2.geom.refR2) == pytest.approx(GAMMA * R2, rel=1e-15)
    # the union now: the hand formula, within the Monte Carlo error of the loss (shell sampled alone)
    V1 = k.volumes([cid])[0]
    hand = union(R1, GAMMA * R2)
    dV = V0 - hand
    shell = sphere(R2) - sphere(GAMMA * R2)
    se = shell * math.sqrt((dV / shell) * (1 - dV / shell) / SHELL_SAMPLES)
    print('V0 %.6e, V1 %.6e, hand %.6e, loss %.4e (%.3f %% of V0), error %.2e (%.2f s.e.)'
          % (V0, V1, hand, dV, 100 * dV / V0, V1 - hand, (V1 - hand) / se))
    assert abs(V1 - hand) < 4 * se and 4 * se < 0.03 * dV   # 0.5 % of the loss, 2.4e-4 of V1
    # mass by the volume (density kept), the ledger by the grain's own change, r_eq from the new volume
    M1 = O.bodies[cid].state.mass
    assert M1 == pytest.approx(M0 * V1 / V0, rel=1e-12)
    assert ab.volumeLost == pytest.approx(V0 - V1, rel=1e-12) and ab.massLost == pytest.approx(M0 - M1, rel=1e-12)
    rEq = (3 * V1 / (4 * math.pi)) ** (1 / 3)
    assert k.radii([cid])[0] == pytest.approx(rEq, rel=1e-12)
    tab = harvest.grains()
    assert tab.radii[tab.ids == cid][0] == pytest.approx(rEq, rel=1e-12)
    assert tab.radiusById[up] == pytest.approx(GAMMA * R2, rel=1e-15) and tab.radiusById[cid] == 0
    # inertia per mass: that of a clump built afresh from the worn members on the same grid (YADE's), and smaller
    J1 = np.sort(np.array(O.bodies[cid].state.inertia))
    ref = clump.appendClump([utils.sphere((1, 1, 1 - D / 2), R1, material=O.bodies[low].material),
                             utils.sphere((1, 1, 1 + D / 2), GAMMA * R2, material=O.bodies[low].material)], hand)
    O.bodies.addToClump([], ref, k.wearDiscretization)
    Jref = np.sort(np.array(O.bodies[ref].state.inertia)) / O.bodies[ref].state.mass
    np.testing.assert_allclose(J1 / M1, Jref, rtol=1e-6)   # the same grid, translated: 3e-9 (rounding of the box)
    assert np.all(J1 < np.sort(J0))


def test_rmin_is_the_members_radius_and_a_strength_above_both_wears_nothing():
    """rMin between R2 and R1 (and below the clump's r_eq): the small member is below it, so nothing wears."""
    strength = _strengthBetween()
    cid, low, up, ab = _pressed(strength, rMin=0.5 * (R1 + R2))
    assert grainkinds.current().radii([cid])[0] > 0.5 * (R1 + R2)
    O.run(2, True)
    assert ab.nAbraded == 0 and O.bodies[up].shape.radius == R2 and ab.maxPressureRatio > 1
    cid, low, up, ab = _pressed(1e30)
    O.run(2, True)
    assert ab.nAbraded == 0 and ab.volumeLost == 0 and 0 < ab.maxPressureRatio < 1e-20


def test_both_members_over_the_strength_wear_in_one_check():
    cid, low, up, ab = _pressed(1.0)
    M0 = O.bodies[cid].state.mass
    O.run(1, True)
    assert ab.nAbraded == 2 and sorted(e['member'] for e in ab.events) == [low, up]
    assert O.bodies[low].shape.radius == pytest.approx(GAMMA * R1, rel=1e-15)
    V1 = grainkinds.current().volumes([cid])[0]
    # the second wear starts from the first's volume and mass: the ledger sums to the whole change
    assert ab.volumeLost == pytest.approx(V0 - V1, rel=1e-12)
    assert ab.massLost == pytest.approx(M0 - O.bodies[cid].state.mass, rel=1e-12)
    hand = sphere(GAMMA * R1) + sphere(GAMMA * R2) - lens(D, GAMMA * R1, GAMMA * R2)
    assert V1 == pytest.approx(hand, rel=2e-3)


def test_a_free_sphere_abrades_as_the_sphere_kind_and_bad_input_is_named():
    steel, mat = clumpScene()
    s = O.bodies.append(utils.sphere((0, 0, 0), 0.01, material=mat))
    cid = clump.appendClump([utils.sphere((1, 0, 0), R1, material=mat), utils.sphere((1, 0, D), R2, material=mat)], V0)
    w = O.bodies.append(utils.wall(-1, axis=2, material=steel))
    k = grainkinds.current()
    m0 = O.bodies[s].state.mass
    rs = k.abrade(s, 0.9)
    assert O.bodies[s].shape.radius == pytest.approx(0.009, rel=1e-15) and rs.volumeAfter is None
    assert rs.massAfter == pytest.approx(0.729 * m0, rel=1e-12)
    units, radii, grain = k.abrasionUnits(np.array([s, cid]), k.radii([s, cid]), harvest.grains().radiusById)
    members = sorted(O.bodies[cid].shape.members.keys())
    assert units.tolist() == [s] + members and grain.tolist() == [s, cid, cid]
    assert radii.tolist() == pytest.approx([0.009, R1, R2], rel=1e-15)
    with pytest.raises(ValueError, match='unitId: expected a clump member or a free sphere.*Wall'):
        k.abrade(w, 0.9)
    with pytest.raises(ValueError, match='unitId: .*Clump'):
        k.abrade(cid, 0.9)
    with pytest.raises(ValueError, match=r'factor: expected a radius factor in \(0, 1\]'):
        k.abrade(members[0], 1.5)
    with pytest.raises(NotImplementedError, match='abrasion wears its members'):
        k.resize(cid, 0.9)


def test_shell_outside_by_hand_and_bad_input():
    # no other sphere: the whole shell (every point outside), error 0
    assert shellOutside((0, 0, 0), 1.0, 0.5, np.zeros((0, 3)), []) == (pytest.approx(sphere(1) - sphere(0.5)), 0.0)
    # inside a larger sphere: nothing lost
    assert shellOutside((0, 0, 0), 1.0, 0.5, [(0.1, 0, 0)], [2.0]) == (0.0, 0.0)
    # half space x > 0 covered by a huge sphere: half the shell, within 4 s.e.
    V, se = shellOutside((0, 0, 0), 1.0, 0.9, [(1e3, 0, 0)], [1e3])
    half = (sphere(1) - sphere(0.9)) / 2
    assert abs(V - half) < 4 * se and se == pytest.approx(half * 2 * 0.5 / math.sqrt(SHELL_SAMPLES), rel=1e-5)
    with pytest.raises(ValueError, match=r'rNew: expected a radius in \(0, r = 1.0\]'):
        shellOutside((0, 0, 0), 1.0, 1.1, [], [])
    with pytest.raises(ValueError, match='radii: expected as many positive finite radii as centres'):
        shellOutside((0, 0, 0), 1.0, 0.9, [(1, 0, 0)], [])
    with pytest.raises(ValueError, match='centre: expected a finite point'):
        shellOutside((0, 0), 1.0, 0.9, [], [])
    with pytest.raises(ValueError, match='samples: expected an integer >= 1000'):
        shellOutside((0, 0, 0), 1.0, 0.9, [], [], samples=10)
