"""ballast.grainkinds.clumpshapes: the descriptors held by the member cloud, the union volume against the
closed form of two overlapping spheres, r_eq of the union against an independent estimate, determinism,
and the input checks. No YADE."""
import math
import re

import numpy as np
import pytest

from ballast import templatefile
from ballast.grainkinds import clumpshapes
from ballast.grainkinds.clumpshapes import clumpMembers, principalExtents, unionVolume


def test_union_volume_of_two_spheres_against_the_lens_formula():
    # two spheres of radius r at distance d: V = 2 (4/3 pi r^3) - pi (4 r + d) (2 r - d)^2 / 12
    r, d = 1.0, 1.2
    exact = 2 * 4 / 3 * math.pi * r ** 3 - math.pi * (4 * r + d) * (2 * r - d) ** 2 / 12
    V, err = unionVolume([[0, 0, 0], [d, 0, 0]], [r, r], samples=400000, seed=3)
    assert err < 2e-3 * exact                    # the stated error: ~0.1 % at 400 000 samples
    assert abs(V - exact) < 4 * err              # within 4 standard errors


@pytest.mark.parametrize('e, f, n, rho', [(0.7, 0.6, 8, 1.0), (0.5, 0.8, 5, 1.0), (1.0, 1.0, 12, 1.0),
                                         (0.9, 0.45, 20, 1.0), (0.7, 0.6, 8, 0.5), (0.5, 0.5, 12, 1.0),
                                         (0.7, 0.6, 30, 0.2)])
def test_descriptors_held_by_the_member_cloud(e, f, n, rho):
    c, r, V, err = clumpMembers(0.02, elongation=e, flatness=f, n=n, seed=7, roundness=rho)
    assert c.shape == (n, 3) and r.shape == (n,)
    L, I, S = principalExtents(c, r)
    assert I / L == pytest.approx(e, rel=1e-12)  # exact by construction (the tips reach L and I, the core S)
    assert S / I == pytest.approx(f, rel=1e-12)
    assert templatefile.connected(c, r)        # every member touches the clump (bridges where the tips do not)
    # the roundness bounds every member but the core and the bridges: corners curved at <= rho S
    s = S / 2   # the core's radius
    bridges = len(clumpshapes.crossMembers(e, f, rho)[1]) - 5
    assert r[0] == pytest.approx(s, rel=1e-12)
    assert np.all(np.delete(r, [0] + list(range(5, 5 + bridges))) <= rho * s * (1 + 1e-12))


def test_the_skeleton_of_a_sharp_grain_by_hand():
    # e 0.7, f 0.6, roundness 0.5: S = 0.42, tips t = 0.21 at +-0.79 (x) and +-0.49 (y). A long arm: the tip does not
    # reach the core (0.79 >= 0.42 + 0.21); one bridge halfway, radius (0.42 + 0.21) / 2 = 0.315, overlaps both
    # (0.395 <= 0.9 (0.42 + 0.315) and 0.9 (0.315 + 0.21) = 0.4725). A short arm: 0.49 < 0.63, no bridge
    c, r = clumpshapes.crossMembers(0.7, 0.6, 0.5)
    np.testing.assert_allclose(r, [0.42, 0.21, 0.21, 0.21, 0.21, 0.315, 0.315], rtol=1e-12)
    np.testing.assert_allclose(c, [[0, 0, 0], [0.79, 0, 0], [-0.79, 0, 0], [0, 0.49, 0], [0, -0.49, 0],
                                   [0.395, 0, 0], [-0.395, 0, 0]], atol=1e-12)
    # at roundness 1 and e f > 1/3 the skeleton is the core and the tips of radius S, as before the roundness
    c, r = clumpshapes.crossMembers(0.7, 0.6, 1.0)
    np.testing.assert_allclose(r, [0.42] * 5, rtol=1e-12)
    # a long thin arm (e 0.5, f 0.5, roundness 0.2): the tip at 1 - 0.05 = 0.95 from the core (S 0.25, t 0.05); k
    # bridges at spacing 0.95 / (k + 1), the thinnest pair (the last bridge, 0.25 - 0.2 k / (k + 1), and the tip)
    # overlapping by a tenth: k = 7 gives 0.11875 > 0.9 x 0.125 = 0.1125, k = 8 gives 0.10556 <= 0.9 x 0.12222 = 0.11
    k = 8
    c, r = clumpshapes.crossMembers(0.5, 0.5, 0.2)
    long = np.flatnonzero((np.abs(c[:, 1]) < 1e-15) & (c[:, 0] >= 0))   # the core, the +x tip and its bridges
    assert len(long) == 2 + k
    d = np.sort(c[long, 0])
    assert np.allclose(np.diff(d), 0.95 / (k + 1), rtol=1e-12)


def test_equivalent_radius_of_the_union_within_its_stated_error():
    rEq = 0.025
    c, r, V, err = clumpMembers(rEq, seed=11)
    assert V == pytest.approx(4 / 3 * math.pi * rEq ** 3, rel=1e-12)
    # an independent estimate (another seed, more samples) agrees within 4 combined standard errors
    V2, err2 = unionVolume(c, r, samples=800000, seed=12345)
    assert abs(V2 - V) < 4 * math.hypot(err, err2)
    assert err / V < 2e-3
    assert (3 * V2 / (4 * math.pi)) ** (1 / 3) == pytest.approx(rEq, rel=2e-3)


def test_deterministic_for_a_seed_and_different_across_seeds():
    a, b, c = (clumpMembers(0.02, seed=s, samples=20000) for s in (1, 1, 2))
    np.testing.assert_array_equal(a[0], b[0])
    np.testing.assert_array_equal(a[1], b[1])
    assert not np.array_equal(a[0], c[0])


@pytest.mark.parametrize('kw, name', [({'rEq': -1.0}, 'rEq'), ({'elongation': 0.0}, 'elongation'),
                                      ({'flatness': 1.5}, 'flatness'), ({'n': 4}, 'n'), ({'n': 6.0}, 'n'),
                                      ({'roundness': 0.0}, 'roundness'), ({'roundness': 1.01}, 'roundness'),
                                      # 0.5 x 0.5 < 1/3: each long arm needs a bridge, 7 members
                                      ({'elongation': 0.5, 'flatness': 0.5, 'n': 6}, 'n')])
def test_bad_inputs_are_named(kw, name):
    args = dict(rEq=0.02)
    args.update(kw)
    with pytest.raises(ValueError) as e:
        clumpMembers(**args)
    assert str(e.value).startswith(name + ':')


def test_containers_by_hand():
    # 0 holds 1 (0.5 + 0.3 <= 1) and 3 (0 + 0.2); 2 overlaps 0 but sticks out; 4 and 5 are one sphere twice: the
    # first holds the second; 6 sits in 1 and so in 0, whose margin is the larger (1 - 0.55 - 0.1 against 0.3 - 0.05
    # - 0.1)
    c = [(0, 0, 0), (0.5, 0, 0), (1.5, 0, 0), (0, 0, 0), (5, 0, 0), (5, 0, 0), (0.55, 0, 0)]
    r = [1.0, 0.3, 0.8, 0.2, 0.5, 0.5, 0.1]
    assert clumpshapes.containers(c, r).tolist() == [-1, 0, -1, 0, -1, 4, 0]


def test_a_piece_of_no_volume_joins_the_piece_its_members_lie_deepest_in():
    # the crash of a clump box (issue 47): a member alone on its side of a plane, wholly inside members of another
    # piece, got no share of the volume and would have become a grain of no mass. Pieces 0, 1, 2 of which 1 is
    # empty: its member (index 2) lies deepest in member 0 (1 - 0.2 against 0.5 - 1.0 for member 1) -> piece 0;
    # pieces renumbered 0, 1 and the shares of the others kept
    c = [(0, 0, 0), (1.2, 0, 0), (0.2, 0, 0), (2.0, 0, 0)]
    r = [1.0, 0.5, 0.1, 0.4]
    piece, shares = clumpshapes.absorbEmpty(c, r, [0, 2, 1, 2], [0.7, 0.0, 0.3])
    assert piece.tolist() == [0, 1, 0, 1] and shares.tolist() == [0.7, 0.3]
    same = clumpshapes.absorbEmpty(c, r, [0, 1, 1, 1], [0.6, 0.4])
    assert same[0].tolist() == [0, 1, 1, 1] and same[1].tolist() == [0.6, 0.4]


def test_cross_pairs_are_the_overlapping_spheres_of_different_pieces():
    """Spheres of radius 1 on the x axis at 0, 1.5, 3 and 5 (neighbours 1.5 apart overlap, 2 apart touch only) in
    pieces 0, 0, 1, 1: (1, 2) overlaps across the pieces; (0, 1) and (2, 3) are in one piece; (2, 3) only touches."""
    from ballast.grainkinds.clumpshapes import crossPairs
    c = [(0, 0, 0), (1.5, 0, 0), (3, 0, 0), (5, 0, 0)]
    assert crossPairs(c, [1, 1, 1, 1], [0, 0, 1, 1]).tolist() == [[1, 2]]
    assert crossPairs(c, [1, 1, 1, 1], [0, 1, 0, 1]).tolist() == [[0, 1], [1, 2]]
    assert crossPairs(c, [1, 1, 1, 1], [0, 0, 0, 0]).shape == (0, 2)


# ---------------------------------------------------------------- templates from a file (clumpFile)
def writeCsv(path, rows, header='template,x,y,z,r'):
    path.write_text(header + '\n' + ''.join(','.join(str(v) for v in row) + '\n' for row in rows))
    return str(path)


def test_templates_read_from_a_file_in_their_order(tmp_path):
    f = writeCsv(tmp_path / 't.csv', [('b', 0, 0, 0, 1), ('a', 0, 0, 0, 2), ('b', 1.5, 0, 0, 1)])
    t = templatefile.readTemplates(f)
    assert [name for name, _, _ in t] == ['b', 'a']
    assert t[0][1].tolist() == [[0, 0, 0], [1.5, 0, 0]] and t[0][2].tolist() == [1, 1]
    assert t[1][1].tolist() == [[0, 0, 0]] and t[1][2].tolist() == [2]


@pytest.mark.parametrize('rows,header,words', [
    ([], 'template,x,y,z,r', 'no rows'),
    ([(1, 0, 0, 0, 1)], 'template,x,y,r', 'no column z'),
    ([(1, 0, 0, 0, 1), (1, 0, 'a', 0, 1)], 'template,x,y,z,r', 'line 3: x, y, z and r must be finite numbers'),
    ([(1, 0, 0, 0, 1), (1, 0, 0, 0, 0)], 'template,x,y,z,r', 'line 3: r = 0 must be > 0'),
    ([(1, 0, 0, 0, 1), ('', 1, 0, 0, 1)], 'template,x,y,z,r', 'line 3: no template'),
    ([(7, 0, 0, 0, 1), (7, 2.5, 0, 0, 1)], 'template,x,y,z,r',
     'template 7 (lines 2-3): its spheres do not all overlap'),
])
def test_a_bad_template_file_is_refused_with_its_line(tmp_path, rows, header, words):
    f = writeCsv(tmp_path / 'bad.csv', rows, header)
    with pytest.raises(ValueError, match=re.escape(words)):
        templatefile.readTemplates(f)


def test_a_template_in_its_principal_frame_at_unit_radius():
    """Two spheres of radius 1, 1.2 apart along (1, 1, 1) and shifted: turned so the axis lies along x, centred on the
    bounding box (members at -+0.6 s), scaled by s so the union (the lens formula) has r_eq 1; a third small sphere
    on the side makes y the intermediate axis. The volume is 4/3 pi by construction, the scale within four of the
    Monte Carlo's standard errors of the lens formula's."""
    u = np.array([1.0, 1.0, 1.0]) / math.sqrt(3)
    shift = np.array([0.3, -2.0, 5.0])
    c, r, V, err = clumpshapes.principalTemplate([shift, shift + 1.2 * u], [1.0, 1.0], samples=400000, seed=5)
    exact = 2 * 4 / 3 * math.pi - math.pi * (4 + 1.2) * (2 - 1.2) ** 2 / 12
    s = (4 / 3 * math.pi / exact) ** (1 / 3)
    assert V == pytest.approx(4 / 3 * math.pi, rel=1e-12)
    assert r[0] == pytest.approx(s, rel=4 * (err / V) / 3 + 1e-12)   # r_eq ~ V^(1/3): a third of V's relative error
    assert np.abs(c[:, 1:]).max() < 1e-12 and sorted(c[:, 0] / r[0]) == pytest.approx([-0.6, 0.6], rel=1e-12)
    w = np.array([0.0, 0.6, 0.0])   # a small third sphere off the axis, in the plane of y
    c3, r3, _, _ = clumpshapes.principalTemplate([[-0.6, 0, 0], [0.6, 0, 0], w], [1.0, 1.0, 0.5], samples=20000)
    L, I, S = principalExtents(c3, r3)
    assert L > I > S and np.abs(c3[:, 2]).max() < 1e-12
