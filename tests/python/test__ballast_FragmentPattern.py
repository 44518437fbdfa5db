"""Tests of pkg/python/bind_FragmentPattern.cpp: the fragment layouts of Fig. 1 (inside the parent, no overlap,
the kept volume in closed form), their reproducible random rotation by (seed, counter), the seed checked
against the engines' range [0, 2^63 - 1] and the counter against [0, 2^64)."""
import math

import numpy as np
import pytest

import ballast._ballast as B


@pytest.mark.parametrize('pattern,name,n,kept', [
    (4, 'tetra4', 4, 4 * (math.sqrt(2 / 3) / (1 + math.sqrt(2 / 3))) ** 3),  # edge 2 rho = (1 - rho) sqrt(8/3)
    ('planar4', 'planar4', 4, 4 / (1 + math.sqrt(2)) ** 3),                  # square: 2 rho = (1 - rho) sqrt(2)
    (6, 'octa6', 6, 6 / (1 + math.sqrt(2)) ** 3),
    ('14', 'fill14', 14, None)])
def test_fragments_fit_inside_without_overlap(pattern, name, n, kept):
    f = B.fragmentPattern(pattern)
    assert f.shape == (n, 4) and B.patternName(pattern) == name
    c, r = f[:, :3], f[:, 3]
    assert np.all(np.linalg.norm(c, axis=1) + r <= 1 + 1e-12)
    d = np.linalg.norm(c[:, None] - c[None], axis=2) - (r[:, None] + r[None])
    assert np.all(d[~np.eye(n, dtype=bool)] >= -1e-12)
    assert B.keptVolumeFraction(pattern) == pytest.approx(np.sum(r ** 3), rel=1e-12)
    if kept is not None:
        assert B.keptVolumeFraction(pattern) == pytest.approx(kept, rel=1e-12)
    else:
        assert B.keptVolumeFraction(pattern) > 0.52  # the paper: more than 28 % lost; here 47.6 %


def test_place_fragments_reproducible_rotated_inside_the_parent():
    centre, R = np.array([0.1, -0.2, 0.3]), 0.02
    a = B.placeFragments(6, centre, R, 42, 7)
    np.testing.assert_array_equal(a, B.placeFragments('octa6', centre, R, 42, 7))
    assert not np.allclose(a, B.placeFragments(6, centre, R, 42, 8))
    assert np.all(np.linalg.norm(a[:, :3] - centre, axis=1) + a[:, 3] <= R * (1 + 1e-12))
    np.testing.assert_allclose(a[:, :3].mean(axis=0), centre, atol=1e-15)  # symmetric layout
    Q = B.randomRotation(42, 7)
    np.testing.assert_allclose(a[:, :3], centre + R * B.fragmentPattern(6)[:, :3] @ Q.T, atol=1e-15)
    np.testing.assert_allclose(Q @ Q.T, np.eye(3), atol=1e-12)
    assert np.linalg.det(Q) == pytest.approx(1.0, abs=1e-12)


def test_seed_range_and_counter_range():
    top = 2 ** 63 - 1  # the largest seed ballast.params allows, and the binding
    np.testing.assert_array_equal(B.randomRotation(np.int64(top), 0), B.randomRotation(top, 0))
    assert not np.allclose(B.randomRotation(top, 0), B.randomRotation(top - 1, 0))
    last = 2 ** 64 - 1  # every 64-bit counter
    np.testing.assert_array_equal(B.randomRotation(0, np.uint64(last)), B.randomRotation(0, last))
    assert not np.allclose(B.randomRotation(0, last), B.randomRotation(0, last - 1))


@pytest.mark.parametrize('call,exc,message', [
    (lambda: B.fragmentPattern(5), ValueError, "pattern: expected 4, 6, 14 or one of 'tetra4', 'planar4', 'octa6', 'fill14', got 5"),
    (lambda: B.fragmentPattern('hex'), ValueError,
     "pattern: expected 4, 6, 14 or one of 'tetra4', 'planar4', 'octa6', 'fill14', got 'hex'"),
    (lambda: B.fragmentPattern(4.0), TypeError,
     "pattern: expected 4, 6, 14 or one of 'tetra4', 'planar4', 'octa6', 'fill14', got 4.0"),
    (lambda: B.fragmentPattern(np.array([6])), TypeError,
     "pattern: expected 4, 6, 14 or one of 'tetra4', 'planar4', 'octa6', 'fill14', got array([6])"),
    (lambda: B.fragmentPattern(2 ** 70), ValueError,
     "pattern: expected 4, 6, 14 or one of 'tetra4', 'planar4', 'octa6', 'fill14', got %d" % 2 ** 70),
    (lambda: B.randomRotation(-1, 0), ValueError, 'seed: expected an integer in [0, 2^63 - 1], got -1'),
    (lambda: B.randomRotation(2 ** 63, 0), ValueError, 'seed: expected an integer in [0, 2^63 - 1], got 9223372036854775808'),
    (lambda: B.randomRotation(2 ** 64, 0), ValueError, 'seed: expected an integer in [0, 2^63 - 1], got 18446744073709551616'),
    (lambda: B.randomRotation(0, 2 ** 64), ValueError, 'counter: expected an integer in [0, 2^64), got 18446744073709551616'),
    (lambda: B.placeFragments(6, [0, 0], 1.0, 1, 1), TypeError, 'centre: expected a 3-vector, got shape (2,)'),
    (lambda: B.placeFragments(6, [0, 0, 0], 0.0, 1, 1), ValueError, 'radius: expected a finite number > 0, got 0'),
    (lambda: B.placeFragments(6, [0, 0, 0], 1.0, 2 ** 64 - 1, 1), ValueError,
     'seed: expected an integer in [0, 2^63 - 1], got 18446744073709551615'),
    (lambda: B.placeFragments(6, [1.7e308, 0, 0], 1e308, 1, 1), ValueError,
     'centre, radius: expected values whose fragment position is finite, the result would be inf at index 3'),
])
def test_bad_input_names_the_argument_the_value_and_what_is_allowed(call, exc, message):
    with pytest.raises(exc) as e:
        call()
    assert str(e.value) == message
