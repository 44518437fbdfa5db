"""ballast.experiments.clumpsample, the clump grains of a sample (issue 47, item 1): a small oedometer packing built
with grain 'clump' is all clumps, each of mass density x its stored union volume (docs/grains.md: within 1 %), of r_eq the
cloud's radius (1e-12), and the stored sample rebuilds the same clumps: members where the stored template,
orientation, centre and r put them, worked out here with the quaternion by hand (1e-12), and the rows the scene gives
back equal to the stored ones (1e-12)."""
import json
import math

import numpy as np
import pytest

pytest.importorskip('yade')
from yade import O  # noqa: E402

from ballast import grainkinds  # noqa: E402
from ballast.experiments import grains, sample  # noqa: E402
from ballast.experiments.clumpsample import ClumpSample  # noqa: E402
from ballast.experiments.oedometer import Oedometer  # noqa: E402
from ballast.experiments.scene import materials  # noqa: E402

# about a dozen grains: the cylinder 0.1 m across, 0.04 m high, 30 % of it solid
SMALL = dict(diameter=0.1, height=0.04, fill=0.3, dMin=0.02, dMax=0.026, progress=60, grain='clump',
             clumpTemplates=3)
TOL_MASS = 1e-2   # [-] docs/grains.md: YADE's grid integration and the Monte Carlo volume


def rotate(q, v):
    """v turned by the unit quaternion q = (w, x, y, z): v + 2 w (u x v) + 2 u x (u x v), u = (x, y, z)."""
    w, u = q[0], np.asarray(q[1:])
    t = 2 * np.cross(u, v)
    return v + w * t + np.cross(u, t)


@pytest.fixture(scope='module')
def built(tmp_path_factory):
    root = tmp_path_factory.mktemp('clumps')
    exp = Oedometer(results=str(root), packingDir=str(root / 'packings'), **SMALL)
    exp.prepare()
    with open(exp.packing.file) as fh:
        doc = json.load(fh)
    return exp, doc


def test_a_clump_sample_is_all_clumps_of_the_clouds_radii_and_their_volumes_mass(built):
    exp, doc = built
    p = exp.p
    k = grainkinds.current()
    ids = k.ids()
    assert k.name == 'clump' and len(ids) == len(doc['clumps']) > 5
    assert all(O.bodies[int(i)].isClump for i in ids)
    # the grains' r_eq are the cloud's radii (the same cloud again from the seed; no grain left the cylinder here)
    _, rCloud, _ = sample.grainCloud(p, sample.CylinderShape(p['diameter'] / 2),
                                     p['fill'] * math.pi * (p['diameter'] / 2) ** 2 * p['height'], p['seed'])
    rows = np.array(doc['clumps'], dtype=float)
    assert exp.packing.escaped == 0
    assert np.array_equal(rows[:, 8], rCloud)
    assert np.allclose(k.radii(ids), rCloud, rtol=1e-12, atol=0)
    # each grain's mass is density x its stored union volume, 4/3 pi r^3
    V = k.volumes(ids)
    assert np.allclose(V, 4 / 3 * math.pi * rCloud ** 3, rtol=1e-12, atol=0)
    assert np.all(np.abs(k.masses(ids) / (p['density'] * V) - 1) < TOL_MASS)
    # a template's copies are the same grain scaled: mass / r^3 equal whatever the orientation (YADE integrates
    # the mass in the template's frame, so its grid error, up to 0.3 % (docs/grains.md), is the same for all; measured
    # 5e-12 here: the grid's points fall on the members' surfaces a little differently at another scale)
    t = rows[:, 0].astype(int)
    perR3 = k.masses(ids) / rCloud ** 3
    for j in set(t.tolist()):
        assert np.ptp(perR3[t == j]) <= 1e-9 * perR3[t == j].max()


def test_the_stored_clumps_are_rebuilt_where_the_store_puts_them(built):
    exp, doc = built
    O.reset()
    grainkinds.use('clump')
    ballast, _ = materials(exp.p, exp.p['young'])
    ids = ClumpSample.fromDocument(doc).rebuild(doc, ballast)
    rows = np.array(doc['clumps'], dtype=float)
    tmpl = doc['clumpTemplates']
    assert len(ids) == len(rows) and len(tmpl) == 3
    for cid, row in zip(ids, rows):
        t = np.array(tmpl[int(row[0])]['centres'], dtype=float)
        rt = np.array(tmpl[int(row[0])]['radii'], dtype=float)
        q, c, r = row[1:5], row[5:8], row[8]
        members = sorted(O.bodies[cid].shape.members)
        x = np.array([tuple(O.bodies[m].state.pos) for m in members])
        want = np.array([c + rotate(q, r * ti) for ti in t])
        assert np.allclose(x, want, rtol=0, atol=1e-12 * r)
        assert np.allclose([O.bodies[m].shape.radius for m in members], r * rt, rtol=1e-12, atol=0)
    # and the scene gives the stored rows back: template, orientation, centre, r
    again = np.array(ClumpSample.current().rows())
    assert np.array_equal(again[:, 0], rows[:, 0]) and np.array_equal(again[:, 8], rows[:, 8])
    assert np.allclose(again[:, 1:8], rows[:, 1:8], rtol=0, atol=1e-12)
    assert np.allclose(grains.arrays()[1], rows[:, 8], rtol=1e-12, atol=0)


def test_a_sample_of_sharp_grains_is_built_of_their_roundness(tmp_path):
    """clumpRoundness 0.4 (docs/grains.md, "Roundness"): each stored template has its 12 spheres, the tips at 0.4 times
    the core's radius, the bridges its arms need (crossMembers: 4 at e 0.7, f 0.6), every other member at most 0.4 of
    the core, and the box's extents e and f exactly; the grains' r_eq are the cloud's radii (1e-12)."""
    from ballast.clumpcross import crossMembers
    p = dict(SMALL, clumpRoundness=0.4, clumpSpheres=12)
    exp = Oedometer(results=str(tmp_path), packingDir=str(tmp_path / 'packings'), **p)
    exp.prepare()
    with open(exp.packing.file) as fh:
        doc = json.load(fh)
    bridges = len(crossMembers(0.7, 0.6, 0.4)[1]) - 5
    assert bridges == 4
    assert len(doc['clumpTemplates']) == 3
    for t in doc['clumpTemplates']:
        c, r = np.array(t['centres'], dtype=float), np.array(t['radii'], dtype=float)
        assert len(r) == 12
        S = r[0]
        assert np.allclose(r[1:5], 0.4 * S, rtol=1e-12, atol=0)
        assert np.all(r[5:5 + bridges] > 0.4 * S) and np.all(r[5 + bridges:] <= 0.4 * S * (1 + 1e-12))
        ext = (c + r[:, None]).max(axis=0) - (c - r[:, None]).min(axis=0)
        assert ext[1] / ext[0] == pytest.approx(0.7, rel=1e-12) and ext[2] / ext[1] == pytest.approx(0.6, rel=1e-12)
    rows = np.array(doc['clumps'], dtype=float)
    k = grainkinds.current()
    assert len(rows) > 5 and np.allclose(k.radii(k.ids()), rows[:, 8], rtol=1e-12, atol=0)
