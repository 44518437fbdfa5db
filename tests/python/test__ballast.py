"""Tests of the binding pkg/python/_ballast.cpp: closed forms through Python, arrays in and out,
and bad input named in the error."""
import math

import numpy as np
import pytest

import ballast

RTOL = 1e-12


def squeezed(r, F):
    """A grain of radius r squeezed along x by two opposite forces F (acting on the grain)."""
    return ballast.fabricStress(r, [[r, 0, 0], [-r, 0, 0]], [[-F, 0, 0], [F, 0, 0]])


def test_two_opposite_forces_give_3F_over_2pi_r2():
    r, F = 0.016, 2.5e4
    s = squeezed(r, F)
    assert s.shape == (3, 3)
    expected = 3 * F / (2 * math.pi * r ** 2)
    assert s[0, 0] == pytest.approx(-expected, rel=RTOL)  # compression negative
    assert ballast.vonMises(s) == pytest.approx(expected, rel=RTOL)


def test_von_mises_closed_forms():
    sig, tau = 7.0e6, 3.0e6
    assert ballast.vonMises(np.diag([sig, 0, 0])) == pytest.approx(sig, rel=RTOL)
    assert ballast.vonMises(np.diag([0, 0, -sig])) == pytest.approx(sig, rel=RTOL)
    assert ballast.vonMises(np.eye(3) * -sig) == pytest.approx(0, abs=1e-9)
    shear = np.array([[0, tau, 0], [tau, 0, 0], [0, 0, 0]])
    assert ballast.vonMises(shear) == pytest.approx(math.sqrt(3) * tau, rel=RTOL)


def test_von_mises_vectorised_matches_eq2_from_principal_stresses():
    rng = np.random.default_rng(1)
    S = rng.normal(size=(50, 3, 3)) * 1e6
    ve = ballast.vonMises(S)
    p = ballast.principalStresses(S)
    assert ve.shape == (50,) and p.shape == (50, 3)
    assert np.all(p[:, 0] >= p[:, 1]) and np.all(p[:, 1] >= p[:, 2])
    eq2 = np.sqrt(((p[:, 0] - p[:, 1]) ** 2 + (p[:, 1] - p[:, 2]) ** 2 + (p[:, 0] - p[:, 2]) ** 2) / 2)
    np.testing.assert_allclose(ve, eq2, rtol=1e-10)


def test_grain_stresses_match_single_grain_form():
    radii = np.array([0.01, 0.02])
    idx = np.array([0, 0, 1, 1, 1])
    rng = np.random.default_rng(2)
    l, f = rng.normal(size=(5, 3)) * 0.01, rng.normal(size=(5, 3)) * 1e3
    S = ballast.grainStresses(radii, idx, l, f)
    assert S.shape == (2, 3, 3)
    for g in range(2):
        m = idx == g
        # eq. 3 by hand: (1/V) sum_c l_i F_j
        expected = np.einsum('ci,cj->ij', l[m], f[m]) / (4 / 3 * math.pi * radii[g] ** 3)
        np.testing.assert_allclose(S[g], expected, rtol=1e-12)
        np.testing.assert_allclose(S[g], ballast.fabricStress(radii[g], l[m], f[m]), rtol=1e-12)


def test_hertz_pressure_wall_and_two_spheres():
    F, uN = 1.2e4, 2e-5
    R1, R2 = 0.02, 0.015
    assert ballast.hertzPressure(F, R1, 0, uN) == pytest.approx(3 * F / (2 * math.pi * R1 * uN), rel=RTOL)
    R = R1 * R2 / (R1 + R2)
    assert ballast.hertzPressure(F, R1, R2, uN) == pytest.approx(3 * F / (2 * math.pi * R * uN), rel=RTOL)
    # arrays, with a broadcast scalar wall radius
    p = ballast.hertzPressure([F, 2 * F], [R1, R1], 0, [uN, uN])
    np.testing.assert_allclose(p, [3 * F / (2 * math.pi * R1 * uN), 6 * F / (2 * math.pi * R1 * uN)], rtol=RTOL)
    assert ballast.hertzPressure(-F, R1, R2, uN) == 0.0


def test_size_strength_eq4():
    assert ballast.sizeStrength(2.0e5, 0.02) == pytest.approx(1.0e7, rel=RTOL)
    np.testing.assert_allclose(ballast.sizeStrength(100.0, [0.1, 0.2], 2.0), [1e4, 2500.0], rtol=RTOL)


def test_crush_check_threshold_and_rmin():
    r, ft0 = 0.02, 2.0e5
    ft = ft0 / r
    # forces giving sigma_e = 1.01 f_t and 0.99 f_t (sigma_e = 3F / (2 pi r^2))
    F_hi, F_lo = [k * ft * 2 * math.pi * r ** 2 / 3 for k in (1.01, 0.99)]
    S = np.array([squeezed(r, F_hi), squeezed(r, F_lo), squeezed(r / 4, 1e9)])
    radii = np.array([r, r, r / 4])
    se, st, crush = ballast.crushCheck(S, radii, ft0, 1.0, r / 2)
    np.testing.assert_allclose(se[:2], [1.01 * ft, 0.99 * ft], rtol=1e-12)
    np.testing.assert_allclose(st, ft0 / radii, rtol=RTOL)
    assert crush.dtype == bool and list(crush) == [True, False, False]  # third is below rMin


def test_fatigue_check_counts_a_peak_and_crushes_with_damage():
    """Three grains, fresh state (0, 0, 1, 0), exponent 2, endurance 0.5, hysteresis 0.1.
    Ratios 0.8, 0.4, 0.8 rise to their first sample; then 0.6, 0.25, 0.75: grain 0 fell 0.2 > 0.1 from
    0.8, a peak: D = 0.8^2 = 0.64, and 0.6 > 1 - 0.64 crushes it; grain 1 fell 0.15 from 0.4 < endurance: a
    reversal without damage; grain 2 fell 0.05 < 0.1: still rising, no peak."""
    fresh = np.tile([0.0, 0.0, 1.0, 0.0], (3, 1))
    r = [0.02, 0.02, 0.02]
    st, crush = ballast.fatigueCheck([0.8, 0.4, 0.8], r, fresh, 2.0, 0.5, 0.1, 0.0)
    np.testing.assert_array_equal(st, [[0, 0.8, 1, 0], [0, 0.4, 1, 0], [0, 0.8, 1, 0]])
    assert crush.dtype == bool and not crush.any()
    st, crush = ballast.fatigueCheck([0.6, 0.25, 0.75], r, st, 2.0, 0.5, 0.1, 0.0)
    np.testing.assert_allclose(st, [[0.64, 0.6, 0, 1], [0, 0.25, 0, 0], [0, 0.8, 1, 0]], rtol=1e-15)
    assert list(crush) == [True, False, False]
    assert fresh[0, 2] == 1.0 and fresh[0, 0] == 0.0  # the input state is not changed in place


def test_abrasion_check_max_over_contacts_both_sides():
    radii = np.array([0.02, 0.01])
    F, uN = np.array([1e3, 5e3, 2e3]), np.array([1e-5, 1e-5, 2e-5])
    g1, g2 = np.array([0, 0, -1]), np.array([-1, 1, 1])
    R1, R2 = np.array([0.02, 0.02, 0.0]), np.array([0.0, 0.01, 0.01])
    p = 3 * F / (2 * math.pi * np.array([0.02, 0.02 * 0.01 / 0.03, 0.01]) * uN)
    strength = 0.5 * (p[0] + p[1])
    p0, ab = ballast.abrasionCheck(radii, g1, g2, F, R1, R2, uN, strength, 0.0)
    np.testing.assert_allclose(p0, [max(p[0], p[1]), max(p[1], p[2])], rtol=1e-12)
    assert list(ab) == [p0[0] > strength, p0[1] > strength]


def test_hertz_pressure_from_force_and_contact_modulus():
    # ballast-steel contact modulus by hand; eq. 7 from (F, uN) on a Hertz contact = the force-only form
    E, nu = 3e11, 0.3
    Es = ballast.contactModulus(E, nu, 10 * E, 0.25)
    assert Es == pytest.approx(1 / ((1 - nu**2) / E + (1 - 0.25**2) / (10 * E)), rel=1e-14)
    F, R = np.array([10.0, 1e4, 1e6]), 0.012
    uN = (3 * F / (4 * Es * math.sqrt(R))) ** (2 / 3)
    np.testing.assert_allclose(ballast.hertzPressureFromForce(F, R, Es), ballast.hertzPressure(F, R, 0.0, uN), rtol=1e-12)


def test_abrasion_bound_of_grains_with_hertz_contacts():
    # grain 0 (r 0.02): one contact with the smallest sphere (0.005); grain 1 (r 0.01): a wall and a
    # sphere of 0.03; grain 2 unloaded. Stress traces built by hand from eq. 3 with l = r - uN/2.
    Es, rs = 1.6e11, 0.005
    radii = np.array([0.02, 0.01, 0.015])

    def contact(F, r, other):
        R = r if other == 0 else r * other / (r + other)
        u = (3 * F / (4 * Es * math.sqrt(R))) ** (2 / 3)
        return F * (r - u / 2), ballast.hertzPressure(F, r, other, u)

    c0 = [contact(5e4, 0.02, rs)]
    c1 = [contact(2e4, 0.01, 0.0), contact(8e4, 0.01, 0.03)]
    sig = np.zeros((3, 3, 3))
    for g, cs in ((0, c0), (1, c1)):
        sig[g] = -np.eye(3) * sum(fl for fl, _ in cs) / (3 * 4 / 3 * math.pi * radii[g]**3)  # trace = -sum F l / V
    b = ballast.abrasionBound(sig, radii, rs, Es)
    assert b[0] >= c0[0][1] and b[1] >= max(p for _, p in c1)
    assert b[0] / c0[0][1] == pytest.approx((2 * c0[0][0] / 5e4 / 0.02) ** (1 / 3), rel=1e-12)  # (2 l / r)^(1/3)
    assert b[2] == 0.0
    with pytest.raises(TypeError, match='stresses'):
        ballast.abrasionBound(np.zeros((2, 3, 3)), radii, rs, Es)
    with pytest.raises(ValueError, match='rPartner'):
        ballast.abrasionBound(sig, radii, -1.0, Es)
    # sphere-sphere contacts: the bound from the largest u_N / (2 R) is eq. 7 at that contact
    R = 0.02 * 0.005 / 0.025
    u = (3 * 5e4 / (4 * Es * math.sqrt(R))) ** (2 / 3)
    assert ballast.sphereContactBound(u / (2 * R), Es) == pytest.approx(ballast.hertzPressure(5e4, 0.02, 0.005, u), rel=1e-12)


@pytest.mark.parametrize('pattern,n,kept', [
    (4, 4, 4 * (math.sqrt(2 / 3) / (1 + math.sqrt(2 / 3))) ** 3),
    ('planar4', 4, 4 / (1 + math.sqrt(2)) ** 3),
    (6, 6, 6 / (1 + math.sqrt(2)) ** 3),
    (14, 14, None)])
def test_fragment_patterns_fit_inside_without_overlap(pattern, n, kept):
    f = ballast.fragmentPattern(pattern)
    assert f.shape == (n, 4)
    c, r = f[:, :3], f[:, 3]
    assert np.all(np.linalg.norm(c, axis=1) + r <= 1 + 1e-12)
    d = np.linalg.norm(c[:, None] - c[None], axis=2) - (r[:, None] + r[None])
    assert np.all(d[~np.eye(n, dtype=bool)] >= -1e-12)
    assert ballast.keptVolumeFraction(pattern) == pytest.approx(np.sum(r ** 3), rel=1e-12)
    if kept is not None:
        assert ballast.keptVolumeFraction(pattern) == pytest.approx(kept, rel=1e-12)
    else:
        assert ballast.keptVolumeFraction(pattern) > 0.52


def test_place_fragments_reproducible_rotated_inside_parent():
    centre, R = np.array([0.1, -0.2, 0.3]), 0.02
    a = ballast.placeFragments(6, centre, R, 42, 7)
    b = ballast.placeFragments(6, centre, R, 42, 7)
    c = ballast.placeFragments(6, centre, R, 42, 8)
    np.testing.assert_array_equal(a, b)
    assert not np.allclose(a, c)
    assert np.all(np.linalg.norm(a[:, :3] - centre, axis=1) + a[:, 3] <= R * (1 + 1e-12))
    np.testing.assert_allclose(a[:, :3].mean(axis=0), centre, atol=1e-15)  # symmetric layout
    Q = ballast.randomRotation(42, 7)
    np.testing.assert_allclose(Q @ Q.T, np.eye(3), atol=1e-12)
    assert np.linalg.det(Q) == pytest.approx(1.0, abs=1e-12)


@pytest.mark.parametrize('call,exc,words', [
    (lambda: ballast.fabricStress(-1.0, [[1, 0, 0]], [[1, 0, 0]]), ValueError, ['radius', '-1']),
    (lambda: ballast.fabricStress(0.0, [[1, 0, 0]], [[1, 0, 0]]), ValueError, ['radius', '0']),
    (lambda: ballast.fabricStress(1.0, [[1, 0]], [[1, 0, 0]]), TypeError, ['branches', '(n,3)']),
    (lambda: ballast.fabricStress(1.0, [[1, 0, 0]], [[1, 0, 0], [1, 0, 0]]), TypeError, ['forces']),
    (lambda: ballast.fabricStress(1.0, [[np.nan, 0, 0]], [[1, 0, 0]]), ValueError, ['branches', 'nan']),
    (lambda: ballast.fabricStress(1.0, [[np.inf, 0, 0]], [[1, 0, 0]]), ValueError, ['branches', 'inf']),
    (lambda: ballast.fabricStress('a', [[1, 0, 0]], [[1, 0, 0]]), TypeError, ['radius', 'dtype']),
    (lambda: ballast.vonMises(np.zeros((2, 2))), TypeError, ['sigma', '(2,2)']),
    (lambda: ballast.vonMises(np.zeros((3, 3), dtype=complex)), TypeError, ['sigma', 'complex']),
    (lambda: ballast.hertzPressure([1, 2], [1, 1, 1], 0, 1e-3), TypeError, ['Fn', 'R1', 'equal length']),
    (lambda: ballast.hertzPressure(1.0, -1.0, 0, 1e-3), ValueError, ['R1', '-1']),
    (lambda: ballast.hertzPressure(1.0, 0, 0, 1e-3), ValueError, ['R1', 'R2']),
    (lambda: ballast.grainStresses([1.0], [0.5], [[1, 0, 0]], [[1, 0, 0]]), TypeError, ['grainIndex', 'integers']),
    (lambda: ballast.grainStresses([1.0], [3], [[1, 0, 0]], [[1, 0, 0]]), ValueError, ['grainIndex', '3']),
    (lambda: ballast.crushCheck(np.zeros((2, 3, 3)), [1.0], 1.0, 1.0, 0.0), TypeError, ['stresses', '(1,3,3)']),
    (lambda: ballast.crushCheck(np.zeros((1, 3, 3)), [1.0], -2.0, 1.0, 0.0), ValueError, ['ft0', '-2']),
    (lambda: ballast.fatigueCheck([0.5], [0.02], np.zeros((2, 4)), 2, 0.5, 0.1, 0), TypeError, ['state', '(1,4)']),
    (lambda: ballast.fatigueCheck([0.5], [0.02], [[0, 0, 1, 0]], 2, 1.5, 0.1, 0), ValueError, ['endurance', '1.5']),
    (lambda: ballast.fatigueCheck([-0.5], [0.02], [[0, 0, 1, 0]], 2, 0.5, 0.1, 0), ValueError, ['ratio', '-0.5']),
    (lambda: ballast.fatigueCheck([0.5], [0.02], [[0, 0, 2, 0]], 2, 0.5, 0.1, 0), ValueError, ['state[0]']),
    (lambda: ballast.fragmentPattern(5), ValueError, ['pattern', '5']),
    (lambda: ballast.fragmentPattern('hex'), ValueError, ['pattern', 'hex']),
    (lambda: ballast.fragmentPattern(4.0), TypeError, ['pattern']),
    (lambda: ballast.placeFragments(6, [0, 0], 1.0, 1, 1), TypeError, ['centre']),
    (lambda: ballast.randomRotation(-1, 0), ValueError, ['seed', '-1']),
])
def test_bad_input_names_the_argument(call, exc, words):
    with pytest.raises(exc) as e:
        call()
    for w in words:
        assert w in str(e.value), (w, str(e.value))
