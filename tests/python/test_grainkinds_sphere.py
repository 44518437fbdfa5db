"""ballast.grainkinds.sphere, the sphere kind, against values worked out by hand: volume 4/3 pi r^3, mass
rho V, inertia 2/5 m r^2, equivalent radius r, sieve diameter 2 r; a resize keeps mass = rho V and
inertia 2/5 m r^2; a replacement erases the grain and appends its fragments with the parent's material,
mask and rigid-body velocity. Runs in Debian's /usr/bin/python3 with YADE imported as a module."""
import math

import numpy as np
import pytest
from yade import O, utils

from ballast import grainkinds
from ballast.geometry import equivalentRadius
from ballast.scenes import grainBetweenWalls
from engine_scenes import OVERLAP, R

RHO = 2600.0   # ballastMaterial's density [kg/m^3]
E = 3e11       # grainBetweenWalls's grain modulus [Pa]


@pytest.fixture
def grain():
    g, w0, w1 = grainBetweenWalls(r=R, overlap=OVERLAP)
    return g


def test_volume_mass_inertia_radius_by_hand(grain):
    k = grainkinds.kind('sphere')
    V = 4.0 / 3.0 * math.pi * R ** 3
    m = RHO * V
    assert k.volumes([grain])[0] == pytest.approx(V, rel=1e-15) and k.volume(grain) == pytest.approx(V, rel=1e-15)
    assert k.masses([grain])[0] == pytest.approx(m, rel=1e-14)
    np.testing.assert_allclose(k.inertias([grain]), [[0.4 * m * R ** 2] * 3], rtol=1e-14)
    assert k.radii([grain]).tolist() == [R] == k.vtkRadii([grain]).tolist()
    assert equivalentRadius(k.volume(grain)) == pytest.approx(R, rel=1e-15)
    assert k.sieveDiameters([grain]).tolist() == [2 * R]
    assert k.moduli([grain]).tolist() == [E]
    assert k.centres([grain]).tolist() == [[0.0, 0.0, 0.0]]
    assert k.ids().tolist() == [grain]


def test_scalar_and_array_volumes_keep_the_bits_of_their_callers(grain):
    """The ledgers took a float's power, the density scaling an array's: each keeps its bits (they may differ
    in the last one), both 4/3 pi r^3."""
    k = grainkinds.kind('sphere')
    for r in (0.0123487124, 0.3, 0.0112414163, 0.017, R):
        O.bodies[grain].shape.radius = r
        assert k.volume(grain) == 4.0 / 3.0 * math.pi * float(r) ** 3
        assert k.volumes([grain])[0] == (4.0 / 3.0 * math.pi * np.array([r]) ** 3)[0]
        assert k.volume(grain) == pytest.approx(k.volumes([grain])[0], rel=1e-15)


def test_stress_signature_and_contact_owner(grain):
    k = grainkinds.kind('sphere')
    O.run(1, True)
    s = k.stressTensors()
    assert s.shape == (len(O.bodies), 3, 3)
    np.testing.assert_array_equal(s[grain], np.array(utils.bodyStressTensors()[grain]))
    assert s[grain][2, 2] < 0
    assert k.signature() == utils.getSpheresVolume() == pytest.approx(4.0 / 3.0 * math.pi * R ** 3, rel=1e-14)
    ids = np.array([2, 0, 1], dtype=np.int64)
    assert k.grainOf(ids).tolist() == [2, 0, 1]


def test_resize_keeps_mass_equal_density_times_volume(grain):
    k = grainkinds.kind('sphere')
    O.run(1, True)
    m0 = O.bodies[grain].state.mass
    rs = k.resize(grain, 0.9)
    r1 = 0.9 * R
    m1 = RHO * 4.0 / 3.0 * math.pi * r1 ** 3
    assert rs.radiusBefore == R and rs.radiusAfter == r1 and rs.massBefore == m0
    assert rs.volumeBefore == pytest.approx(4.0 / 3.0 * math.pi * R ** 3, rel=1e-15)
    assert rs.massAfter == pytest.approx(m1, rel=1e-13) == O.bodies[grain].state.mass
    assert k.radii([grain]).tolist() == [r1]
    np.testing.assert_allclose(k.inertias([grain]), [[0.4 * m1 * r1 ** 2] * 3], rtol=1e-13)
    # its contacts as YADE makes them at the new radius (ballast.contacts): its own side's refR
    i = O.interactions[grain, 2]
    assert (i.geom.refR1 if i.id1 == grain else i.geom.refR2) == pytest.approx(r1, rel=1e-15)


def _fragments():
    d = 0.5 * R
    return np.array([[d, 0.0, 0.0, 0.4 * R], [-d, 0.0, 0.0, 0.3 * R]])


def test_replace_erases_the_grain_and_appends_fragments_that_move_with_it(grain):
    k = grainkinds.kind('sphere')
    b = O.bodies[grain]
    b.groupMask = 5
    b.state.vel, b.state.angVel = (1.0, 0.0, 0.0), (0.0, 0.0, 2.0)
    m0, mat, n0 = b.state.mass, b.material, len(O.bodies)
    frags = _fragments()
    rep = k.replace(grain, frags, False)
    assert O.bodies[grain] is None and rep.ids == [n0, n0 + 1]
    V = [4.0 / 3.0 * math.pi * rf ** 3 for rf in frags[:, 3]]
    assert rep.volumeBefore == pytest.approx(4.0 / 3.0 * math.pi * R ** 3, rel=1e-15)
    assert rep.volumeAfter == pytest.approx(sum(V), rel=1e-15)
    assert rep.volumeRatio == pytest.approx(1 / (0.4 ** 3 + 0.3 ** 3), rel=1e-14)
    assert rep.massBefore == m0 and rep.massAfter == pytest.approx(RHO * sum(V), rel=1e-13)
    assert rep.mask == 5 and rep.radii.tolist() == frags[:, 3].tolist()
    for i, (x, rf) in zip(rep.ids, ((0.5 * R, 0.4 * R), (-0.5 * R, 0.3 * R))):
        f = O.bodies[i]
        assert f.groupMask == 5 and f.material.id == mat.id and f.shape.radius == rf
        # rigid-body velocity of the parent at the fragment's centre: v + w x (x, 0, 0) = (1, 2 x, 0)
        assert tuple(f.state.vel) == pytest.approx((1.0, 2.0 * x, 0.0), rel=1e-15)
        assert tuple(f.state.angVel) == (0.0, 0.0, 2.0)
    assert k.ids().tolist() == rep.ids


def test_replace_keeping_mass_scales_fragments_to_the_parent(grain):
    k = grainkinds.kind('sphere')
    m0 = O.bodies[grain].state.mass
    rep = k.replace(grain, _fragments(), True)
    assert rep.massAfter == pytest.approx(m0, rel=1e-14)
    for i, s in zip(rep.ids, (0.4, 0.3)):
        f = O.bodies[i]
        mf = m0 * s ** 3 / (0.4 ** 3 + 0.3 ** 3)
        assert f.state.mass == pytest.approx(mf, rel=1e-13)
        np.testing.assert_allclose(list(f.state.inertia), [0.4 * mf * (s * R) ** 2] * 3, rtol=1e-13)


def test_a_clump_and_its_members_are_not_sphere_grains(grain):
    """A clump's spheres are members of another kind of grain: neither they nor the clump are spheres' grains."""
    mat = O.bodies[grain].material
    clumpId, memberIds = O.bodies.appendClumped([utils.sphere((0.1, 0, 0), 0.01, material=mat),
                                                 utils.sphere((0.115, 0, 0), 0.01, material=mat)])
    k = grainkinds.kind('sphere')
    assert k.ids().tolist() == [grain]
    assert not any(k.isGrain(O.bodies[i]) for i in [clumpId] + list(memberIds))
