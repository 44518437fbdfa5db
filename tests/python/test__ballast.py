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
    0.8, a peak: D = (1 - 0.8) 0.8^2 = 0.128, and 0.6 < 1 - 0.128 leaves it; grain 1 fell 0.15 from 0.4 < endurance: a
    reversal without damage; grain 2 fell 0.05 < 0.1: still rising, no peak."""
    fresh = np.tile([0.0, 0.0, 1.0, 0.0], (3, 1))
    r = [0.02, 0.02, 0.02]
    st, crush = ballast.fatigueCheck([0.8, 0.4, 0.8], r, fresh, 2.0, 0.5, 0.1, 0.0)
    np.testing.assert_array_equal(st, [[0, 0.8, 1, 0], [0, 0.4, 1, 0], [0, 0.8, 1, 0]])
    assert crush.dtype == bool and not crush.any()
    st, crush = ballast.fatigueCheck([0.6, 0.25, 0.75], r, st, 2.0, 0.5, 0.1, 0.0)
    np.testing.assert_allclose(st, [[0.128, 0.6, 0, 1], [0, 0.25, 0, 0], [0, 0.8, 1, 0]], rtol=1e-15)
    assert list(crush) == [False, False, False]
    # a damaged grain at 0.9 of its strength: 0.9 > 1 - 0.128 crushes it
    st, crush = ballast.fatigueCheck([0.9, 0.3, 0.8], r, st, 2.0, 0.5, 0.1, 0.0)
    assert list(crush) == [True, False, False]
    assert fresh[0, 2] == 1.0 and fresh[0, 0] == 0.0  # the input state is not changed in place


def test_weibull_strengths_of_many_grains_follow_the_law_and_eq4():
    """5 000 grains of each of two sizes with modulus k = 3: the strengths f_t = w ft0 / r^m pass a
    Kolmogorov-Smirnov test against P_f = 1 - exp(-(f / sigma_0)^k) with sigma_0 = ft0 / r^m (eq. 4, the
    characteristic strength) at the 1 % level (D < 1.628 / sqrt(n) = 0.023), and the characteristic values of
    the two sizes are in the ratio (r2 / r1)^m = 2 (m = 1) to the resolution of n = 5 000 samples."""
    n, ft0, k = 5000, 2e5, 3.0
    for r, keys in ((0.01, np.arange(n)), (0.02, np.arange(n, 2 * n))):
        w = ballast.weibullFactors(9, keys, k)
        _, ft, _ = ballast.crushCheck(np.zeros((n, 3, 3)), np.full(n, r), ft0, 1.0, 0.0, factor=w)
        sigma0 = ft0 / r
        f = np.sort(ft)
        cdf = 1 - np.exp(-(f / sigma0) ** k)
        D = max(np.max(np.arange(1, n + 1) / n - cdf), np.max(cdf - np.arange(n) / n))
        assert D < 1.628 / math.sqrt(n), (r, D)
        assert np.quantile(ft, 1 - math.exp(-1)) == pytest.approx(sigma0, rel=0.03)
        # a size law off by 10 % fails the same test
        cdf = 1 - np.exp(-(f / (1.1 * sigma0)) ** k)
        assert max(np.max(np.arange(1, n + 1) / n - cdf), np.max(cdf - np.arange(n) / n)) > 1.628 / math.sqrt(n)


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


# ---------------------------------------------------------------- NumPy scalars and 0-d arrays (issue 15)
# Every scalar argument of every function, with Python-number keyword arguments that make a valid call:
# (function, argument, the other arguments, a float value, an int value or None when no int is valid).
S1 = np.array([squeezed(0.02, 2e3)])
FRESH = [[0.0, 0.0, 1.0, 0.0]]
SCALAR_ARGS = [
    ('fabricStress', 'radius', dict(branches=[[1, 0, 0], [0, 2, 0]], forces=[[3, 0, 1], [0, -1, 0]]), 1.5, 2),
    ('hertzPressure', 'Fn', dict(R1=0.02, R2=0.01, uN=1e-5), 1.5e3, 1500),
    ('hertzPressure', 'R1', dict(Fn=1e3, R2=0.01, uN=1e-5), 0.25, 0),
    ('hertzPressure', 'R2', dict(Fn=1e3, R1=0.01, uN=1e-5), 0.25, 2),
    ('hertzPressure', 'uN', dict(Fn=1e3, R1=0.01, R2=0.02), 0.5, 1),
    ('effectiveRadius', 'R1', dict(R2=0.02), 0.5, 1),
    ('effectiveRadius', 'R2', dict(R1=0.02), 0.5, 0),
    ('sizeStrength', 'ft0', dict(radius=0.02, m=1.0), 2.5e5, 250000),
    ('sizeStrength', 'radius', dict(ft0=2e5), 0.125, 3),
    ('sizeStrength', 'm', dict(ft0=2e5, radius=0.02), 1.5, 2),
    ('contactModulus', 'E1', dict(nu1=0.3, E2=2e11, nu2=0.25), 3.5e10, 35000000000),
    ('contactModulus', 'nu1', dict(E1=3e10, E2=2e11, nu2=0.25), 0.25, 0),
    ('contactModulus', 'E2', dict(E1=3e10, nu1=0.3, nu2=0.25), 2.5e11, 250000000000),
    ('contactModulus', 'nu2', dict(E1=3e10, nu1=0.3, E2=2e11), -0.5, -1),
    ('hertzPressureFromForce', 'Fn', dict(R=0.01, Estar=1.6e11), 1.5e4, 15000),
    ('hertzPressureFromForce', 'R', dict(Fn=1e4, Estar=1.6e11), 0.0625, 1),
    ('hertzPressureFromForce', 'Estar', dict(Fn=1e4, R=0.01), 1.5e11, 150000000000),
    ('crushCheck', 'ft0', dict(stresses=S1, radii=[0.02], m=1.0, rMin=0.0), 2.5e2, 250),
    ('crushCheck', 'm', dict(stresses=S1, radii=[0.02], ft0=2e5, rMin=0.0), 0.5, 2),
    ('crushCheck', 'rMin', dict(stresses=S1, radii=[0.02], ft0=2e5, m=1.0), 0.03125, 0),
    ('abrasionCheck', 'strength', dict(radii=[0.02], grain1=[0], grain2=[-1], Fn=[1e3], R1=[0.02], R2=[0.0], uN=[1e-5], rMin=0.0),
     1.5e8, 150000000),
    ('abrasionCheck', 'rMin', dict(radii=[0.02], grain1=[0], grain2=[-1], Fn=[1e3], R1=[0.02], R2=[0.0], uN=[1e-5], strength=1e8),
     0.03125, 0),
    ('fatigueCheck', 'exponent', dict(ratio=[0.5], radii=[0.02], state=FRESH, endurance=0.5, hysteresis=0.1, rMin=0.0), 2.5, 8),
    ('fatigueCheck', 'endurance', dict(ratio=[0.5], radii=[0.02], state=FRESH, exponent=2.0, hysteresis=0.1, rMin=0.0), 0.5, 0),
    ('fatigueCheck', 'hysteresis', dict(ratio=[0.5], radii=[0.02], state=FRESH, exponent=2.0, endurance=0.5, rMin=0.0), 0.25, None),
    ('fatigueCheck', 'rMin', dict(ratio=[0.5], radii=[0.02], state=FRESH, exponent=2.0, endurance=0.5, hysteresis=0.1), 0.03125, 0),
    ('abrasionBound', 'rPartner', dict(stresses=S1, radii=[0.02], EstarMax=1.6e11), 0.0078125, 0),
    ('abrasionBound', 'EstarMax', dict(stresses=S1, radii=[0.02], rPartner=0.005), 1.5e11, 150000000000),
    ('sphereContactBound', 'maxOverlapRatio', dict(EstarMax=1.6e11), 0.0009765625, 0),
    ('sphereContactBound', 'EstarMax', dict(maxOverlapRatio=1e-3), 1.5e11, 150000000000),
    ('placeFragments', 'radius', dict(pattern=6, centre=[0.1, 0.2, 0.3], seed=1, counter=2), 0.015625, 1),
]
# (dtype, 0-d): a NumPy scalar of that type, or a 0-d array of it
FLOAT_TYPES = [(t, d) for t in (np.float16, np.float32, np.float64, np.longdouble) for d in (False, True)]
INT_TYPES = [(t, d) for t in (np.int8, np.int16, np.int32, np.int64, np.uint8, np.uint16, np.uint32, np.uint64)
             for d in (False, True)]


def numpyNumber(type_, zeroD, value):
    return np.array(value, dtype=type_) if zeroD else type_(value)


def typeId(t):
    return t[0].__name__ + ('-0d' if t[1] else '')


def holds(type_, value):
    """Whether the NumPy type holds value exactly (np.float16 cannot hold 1.5e11, np.int8 not 250000)."""
    if np.issubdtype(type_, np.integer):
        return np.iinfo(type_).min <= value <= np.iinfo(type_).max
    with np.errstate(over='ignore'):
        return float(type_(value)) == value


def assert_same_result(a, b):
    """Results of two calls are equal, value and type (a float stays a float)."""
    assert type(a) is type(b)
    if isinstance(a, tuple):
        for x, y in zip(a, b):
            np.testing.assert_array_equal(x, y)
    else:
        np.testing.assert_array_equal(a, b)


@pytest.mark.parametrize('fn,arg,others,value,type_', [
    pytest.param(fn, arg, others, v, t, id='%s-%s-%s' % (fn, arg, typeId(t)))
    for fn, arg, others, x, i in SCALAR_ARGS
    for t, v in [(t, x) for t in FLOAT_TYPES] + [(t, i) for t in INT_TYPES]
    if v is not None and holds(t[0], v)])
def test_numpy_scalars_and_0d_arrays_are_numbers(fn, arg, others, value, type_):
    f = getattr(ballast, fn)
    assert_same_result(f(**others, **{arg: numpyNumber(*type_, value)}), f(**others, **{arg: value}))


@pytest.mark.parametrize('type_', INT_TYPES, ids=typeId)
@pytest.mark.parametrize('call', [
    lambda n: ballast.fragmentPattern(n(6)),
    lambda n: ballast.fragmentPattern(n(14)),
    lambda n: ballast.keptVolumeFraction(n(4)),
    lambda n: ballast.patternName(n(6)),
    lambda n: ballast.randomRotation(n(42), n(7)),
    lambda n: ballast.placeFragments(n(4), [0.1, 0.2, 0.3], 0.02, n(42), n(7)),
], ids=['fragmentPattern6', 'fragmentPattern14', 'keptVolumeFraction', 'patternName', 'randomRotation', 'placeFragments'])
def test_numpy_integers_are_integers(call, type_):
    assert_same_result(call(lambda v: numpyNumber(*type_, v)), call(int))


def test_seed_takes_the_whole_uint64_range():
    top = 2 ** 64 - 1
    np.testing.assert_array_equal(ballast.randomRotation(np.uint64(top), 0), ballast.randomRotation(top, 0))
    assert not np.allclose(ballast.randomRotation(top, 0), ballast.randomRotation(top - 1, 0))


def test_fabric_stress_of_huge_values_that_stay_finite():
    # no overflow below the double range: the effective radius of two huge radii, a grain of radius 1e100
    assert ballast.effectiveRadius(1e200, 1e200) == pytest.approx(5e199, rel=1e-15)
    assert ballast.effectiveRadius(1e-200, 1e-200) == pytest.approx(5e-201, rel=1e-15)
    r = 1e100
    assert squeezed(r, 1e150)[0, 0] == pytest.approx(-3 * 1e150 / (2 * math.pi * r ** 2), rel=1e-12)


BIG = np.diag([1e200, 0, 0])
UINT_TOP = np.array([2 ** 64 - 1], dtype=np.uint64)


@pytest.mark.parametrize('call,exc,words', [
    # integers the code takes: Python ints and NumPy integers only, in range
    (lambda: ballast.fragmentPattern(np.int64(5)), ValueError, ['pattern', 'got 5']),
    (lambda: ballast.fragmentPattern(np.float64(6)), TypeError, ['pattern', '6.0']),
    (lambda: ballast.fragmentPattern(np.True_), TypeError, ['pattern', 'True']),
    (lambda: ballast.fragmentPattern(np.array([6])), TypeError, ['pattern', 'array([6])']),
    (lambda: ballast.fragmentPattern(2 ** 70), ValueError, ['pattern', str(2 ** 70)]),
    (lambda: ballast.randomRotation(2 ** 64, 0), ValueError, ['seed', str(2 ** 64), '2^64']),
    (lambda: ballast.randomRotation(0, np.int64(-1)), ValueError, ['counter', '-1']),
    (lambda: ballast.randomRotation(np.float32(1), 0), TypeError, ['seed']),
    (lambda: ballast.randomRotation(0, True), TypeError, ['counter', 'True']),
    (lambda: ballast.placeFragments(6, [0, 0, 0], 1.0, 1, np.array(2.0)), TypeError, ['counter']),
    (lambda: ballast.grainStresses([1.0], UINT_TOP, [[1, 0, 0]], [[1, 0, 0]]), ValueError,
     ['grainIndex', '18446744073709551615', '2^63']),
    (lambda: ballast.abrasionCheck([0.01], UINT_TOP, [-1], [1.0], [0.01], [0.0], [1e-6], 1.0, 0.0), ValueError,
     ['grain1', '18446744073709551615']),
    (lambda: ballast.abrasionCheck([0.01], [0], [1], [1.0], [0.01], [0.0], [1e-6], 1.0, 0.0), ValueError,
     ['grain2[0]', '-1 or 0 <= index < 1', 'got 1']),
    # numbers: one each, finite, real
    (lambda: ballast.crushCheck(S1, [0.02], np.array([2e5, 1.0]), 1.0, 0.0), TypeError, ['ft0', 'shape (2,)']),
    (lambda: ballast.crushCheck(S1, [0.02], 2e5, np.float64('nan'), 0.0), ValueError, ['m', 'nan']),
    (lambda: ballast.crushCheck(S1, [0.02], 2e5, 1.0, np.float32('inf')), ValueError, ['rMin', 'inf']),
    (lambda: ballast.crushCheck(S1, [0.02], 'a', 1.0, 0.0), TypeError, ['ft0', 'dtype']),
    (lambda: ballast.crushCheck(S1, [0.02], np.complex128(1), 1.0, 0.0), TypeError, ['ft0', 'complex']),
    (lambda: ballast.fatigueCheck([0.5], [0.02], FRESH, np.True_, 0.5, 0.1, 0.0), TypeError, ['exponent', 'bool']),
    (lambda: ballast.abrasionBound(S1, [0.02], np.array([0.0]), 1e11), TypeError, ['rPartner', 'shape (1,)']),
    (lambda: ballast.sphereContactBound(np.float64('nan'), 1e11), ValueError, ['maxOverlapRatio', 'nan']),
    (lambda: ballast.sphereContactBound(1e-3, None), TypeError, ['EstarMax', 'object']),
    (lambda: ballast.matricesToArray(5), TypeError, ['matrices', 'sequence']),
    (lambda: ballast.matricesToArray([np.eye(3), np.full((3, 3), np.nan)]), ValueError, ['matrices[1]', 'nan']),
    # results that would not be finite
    (lambda: ballast.fabricStress(1e-200, [[1, 0, 0]], [[1, 0, 0]]), ValueError, ['radius', '1e-200', 'overflows']),
    (lambda: ballast.fabricStress(1e103, [[1, 0, 0]], [[1, 0, 0]]), ValueError, ['radius', '1e+103', 'overflows']),
    (lambda: ballast.fabricStress(1e-100, [[1, 0, 0]], [[1e100, 0, 0]]), ValueError,
     ['radius, branches, forces', 'fabric stress is finite', 'would be inf']),
    (lambda: ballast.grainStresses([1.0, 1e-200], [0], [[1, 0, 0]], [[1, 0, 0]]), ValueError, ['radii[1]', '1e-200']),
    (lambda: ballast.grainStresses([1.0, 1e-100], [1], [[1, 0, 0]], [[1e100, 0, 0]]), ValueError,
     ['radii, branches, forces', 'would be inf at index 1']),
    (lambda: ballast.vonMises(BIG), ValueError, ['sigma', 'von Mises stress is finite', 'would be inf']),
    (lambda: ballast.vonMises([np.eye(3), BIG]), ValueError, ['sigma', 'would be inf at index 1']),
    (lambda: ballast.principalStresses(np.full((3, 3), 1.7e308)), ValueError, ['sigma', 'principal stress', 'would be nan']),
    (lambda: ballast.hertzPressure(1e300, 1e-10, 0, 1e-300), ValueError, ['Fn, R1, R2, uN', 'would be inf']),
    (lambda: ballast.hertzPressure([1.0, 1e300], 1e-10, 0, 1e-290), ValueError, ['Fn, R1, R2, uN', 'inf at index 1']),
    (lambda: ballast.sizeStrength(1e300, 1e-100, 5), ValueError, ['ft0, radius, m', 'would be inf']),
    (lambda: ballast.contactModulus(1.0, -1.0, 1.0, -1.0), ValueError, ['E1, nu1, E2, nu2', 'would be inf']),
    (lambda: ballast.hertzPressureFromForce(1.0, 1e-200, 1e11), ValueError, ['Fn, R, Estar', 'would be inf']),
    (lambda: ballast.crushCheck(np.array([BIG]), [0.02], 2e5, 1.0, 0.0), ValueError, ['stresses', "criterion's stress", 'inf at index 0']),
    (lambda: ballast.crushCheck(S1, [1e-100], 1e300, 5.0, 0.0), ValueError, ['ft0, radii, m', 'inf at index 0']),
    (lambda: ballast.abrasionCheck([0.01], [0], [-1], [1e300], [0.01], [0.0], [1e-300], 1.0, 0.0), ValueError,
     ['Fn, R1, R2, uN', 'would be inf']),
    (lambda: ballast.fatigueCheck([0.0], [0.02], [[np.inf, 0, 1, 0]], 100, 0.5, 0.1, 0.0), ValueError,
     ['state', 'inf']),
    (lambda: ballast.abrasionBound(np.full((1, 3, 3), 1e308), [1.0], 0.0, 1e11), ValueError, ['stresses', 'trace', 'inf']),
    (lambda: ballast.abrasionBound(-np.eye(3)[None] * 1e300, [1.0], 0.0, 1e11), ValueError, ['radii', 'would be inf']),
    (lambda: ballast.abrasionBound(S1, [0.02], 0.0, 1e200), ValueError, ['EstarMax', 'would be inf']),
    (lambda: ballast.sphereContactBound(1e308, 1e308), ValueError, ['maxOverlapRatio, EstarMax', 'would be inf']),
    (lambda: ballast.placeFragments(6, [1.7e308, 0, 0], 1e308, 1, 1), ValueError, ['centre, radius', 'would be inf']),
])
def test_bad_numbers_and_non_finite_results_name_the_argument(call, exc, words):
    with pytest.raises(exc) as e:
        call()
    for w in words:
        assert w in str(e.value), (w, str(e.value))
