"""Seeded fuzz test of the binding pkg/python/ (issue 15): every function that takes arguments is called with random
valid and invalid arguments (shapes, dtypes, NaN/inf, huge and tiny values, negative radii, NumPy scalars,
objects of the wrong type). Each call must either return finite results of the documented shape, or raise
TypeError/ValueError whose message starts with the name of one of the call's arguments ("radii[3]: ...",
"Fn, R1, R2, uN: ..."). Valid calls whose inputs are moderate (0 or 1e-30 <= |x| <= 1e30, so that no
intermediate value of a formula leaves the double range) are checked against NumPy formulas written
here independently of the C++ code."""
import math
import re
import warnings

import numpy as np
import pytest

import ballast._ballast as B

SEED = 20240615
CALLS = 200  # per function; the whole test runs in about a second
KEPT = {'tetra4': 4, 'planar4': 4, 'octa6': 6, 'fill14': 14}
PATTERNS = [4, 6, 14, 'tetra4', 'planar4', 'octa6', 'fill14', '4', '6', '14']
INT_TYPES = (int, np.int8, np.int16, np.int32, np.int64, np.uint8, np.uint16, np.uint32, np.uint64)
FLOAT_TYPES = (float, np.float16, np.float32, np.float64, np.longdouble)
EXTREMES = (0.0, -0.0, 5e-324, 1e-310, 1e-200, 1e-100, 1e100, 1e200, 1.7e308, -1.0, -1e300,
            math.nan, math.inf, -math.inf)
GARBAGE = (None, 'a', '1.5', b'x', 1 + 2j, True, np.bool_(False), object(), {}, [[1, 2], [3]], [None])


class Gen:
    """Random arguments: valid, each mutated with probability p (about half of the calls are valid)."""

    def __init__(self, rng, p=0.1):
        self.rng = rng
        self.p = p

    def chance(self, p):
        return self.rng.random() < p

    def pick(self, seq):
        return seq[self.rng.integers(len(seq))]

    def magnitude(self, size=None):
        """Moderate (1e-5 ... 1e5), or in one draw of ten anything from subnormal to 1e308."""
        wild = self.rng.random(size) < 0.5 if self.chance(0.1) else False
        return np.where(wild, 10.0 ** self.rng.uniform(-320, 308, size), 10.0 ** self.rng.uniform(-5, 5, size))

    def signed(self, size=None):
        return self.magnitude(size) * self.rng.choice([-1.0, 1.0], size)

    # --- scalars
    def number(self, x):
        """x as a Python number, or a NumPy scalar or 0-d array of a random type (np.float16(1e5) is inf); or mutated."""
        if self.chance(self.p):
            return self.badNumber()
        types = FLOAT_TYPES
        if float(x).is_integer() and abs(x) < 100 and self.chance(0.3):
            types, x = [t for t in INT_TYPES if t is int or np.iinfo(t).min <= x <= np.iinfo(t).max], int(x)
        t = self.pick(types)
        return np.array(x, dtype=t) if t not in (int, float) and self.chance(0.2) else t(x)

    def badNumber(self):
        k = self.rng.integers(5)
        if k == 0:
            return self.pick(EXTREMES)
        if k == 1:
            return self.pick(GARBAGE)
        if k == 2:
            return np.array([float(self.signed())])  # an array, not a number
        if k == 3:
            return float(-self.magnitude())
        return 10 ** int(self.rng.integers(18, 400))  # a Python int beyond int64, maybe beyond double

    def integer(self, x):
        """An integer argument: x as a Python int or a NumPy integer (scalar or 0-d); or mutated."""
        if self.chance(self.p):
            return self.pick([-1, 2 ** 64, 2 ** 70, -2 ** 63, 6.0, np.float64(4), True, np.True_, 'x', None,
                              np.array([4]), np.int8(-3), 5, 2 ** 64 - 1, np.uint64(2 ** 64 - 1)])
        t = self.pick([t for t in INT_TYPES if t is int or np.iinfo(t).min <= x <= np.iinfo(t).max])
        return np.array(x, dtype=t) if t is not int and self.chance(0.3) else t(x)

    # --- arrays
    def array(self, values, integers=False):
        """values (float64 or int64) as a random dtype, sometimes a nested list; or mutated (shape, dtype, NaN...)."""
        a = np.asarray(values)
        if self.chance(self.p):
            return self.badArray(a)
        if integers:
            types = [t for t in (np.int64, np.int32, np.int8, np.uint64, np.uint8)
                     if not a.size or np.iinfo(t).min <= a.min() and a.max() <= np.iinfo(t).max]
        else:  # float32 turns huge values into inf and tiny ones into 0
            types = [np.float64, np.float64, np.float32, np.longdouble] + ([np.int64] if np.all(np.abs(a) < 1e15) else [])
        a = a.astype(self.pick(types))
        return a.tolist() if a.dtype != np.longdouble and self.chance(0.15) else a

    def badArray(self, a):
        k = self.rng.integers(6)
        b = np.array(a, dtype=float)
        if k == 0 and b.size:  # a NaN, inf, huge, tiny or negative entry
            b.flat[self.rng.integers(b.size)] = self.pick(EXTREMES)
            return b
        if k == 1:  # one dimension more or less, or another length
            shapes = [b.shape[1:], b.shape + (1,), (b.shape[0] + 1,) + b.shape[1:] if b.ndim else (2,), ()]
            return self.signed(self.pick(shapes))
        if k == 2:
            return b.astype(self.pick([bool, complex, object, 'U3']))
        if k == 3:
            return self.pick(GARBAGE)
        if k == 4:
            return np.uint64(2 ** 64 - 1) * np.ones(b.shape, dtype=np.uint64)  # wraps to -1 as int64
        return -np.abs(b) - 1e-3  # all negative


def asFloat(x):
    """What the binding computes with: x as float64."""
    return np.asarray(x, dtype=np.float64)


def moderate(*xs):
    """All values are 0 or in [1e-30, 1e30] in magnitude: no formula here over- or underflows."""
    for x in xs:
        a = np.abs(asFloat(x))
        if not np.all((a == 0) | ((a >= 1e-30) & (a <= 1e30))):
            return False
    return True


def close(got, want, atol=0.0, rtol=1e-11):
    """|got - want| <= atol + rtol |want| elementwise; atol may be an array (a scale per element)."""
    got, want = np.asarray(got, dtype=float), np.asarray(want, dtype=float)
    assert got.shape == want.shape, (got.shape, want.shape)
    bad = ~(np.abs(got - want) <= atol + rtol * np.abs(want))
    assert not bad.any(), (got[bad], want[bad])


def symmetricPart(S):
    return 0.5 * (S + np.swapaxes(S, -1, -2))


def principalRef(S):
    return np.linalg.eigvalsh(symmetricPart(S))[..., ::-1]


def vonMisesRef(S):
    """Eq. 2 from the principal stresses."""
    p = principalRef(S)
    return np.sqrt(((p[..., 0] - p[..., 1]) ** 2 + (p[..., 1] - p[..., 2]) ** 2 + (p[..., 0] - p[..., 2]) ** 2) / 2)


def tensorScale(S):
    """Largest entry of each tensor: the rounding errors of eq. 2 and of eigenvalues scale with it."""
    return np.max(np.abs(S), axis=(-2, -1), initial=0)


def effectiveRadiusRef(R1, R2):
    with np.errstate(divide='ignore', invalid='ignore'):
        return np.where(R1 == 0, R2, np.where(R2 == 0, R1, R1 * R2 / (R1 + R2)))


def hertzRef(Fn, R1, R2, uN):
    """Eq. 7: 3 F / (2 pi a^2), a^2 = R uN; no compression gives 0."""
    a2 = effectiveRadiusRef(R1, R2) * uN
    with np.errstate(divide='ignore', invalid='ignore'):
        return np.where((Fn > 0) & (uN > 0), 3 * Fn / (2 * np.pi * a2), 0.0)


def hertzFromForceRef(Fn, R, Es):
    with np.errstate(invalid='ignore'):
        return np.where(Fn > 0, np.cbrt(6 * Fn * Es ** 2 / (np.pi ** 3 * R ** 2)), 0.0)


def volume(r):
    return 4 / 3 * np.pi * r ** 3


def fatigueRef(ratio, radii, rMin, state, b, endurance, h):
    """docs/fatigue.md, one sample per grain with r >= rMin: a peak >= endurance ends when s falls h below it,
    D += (1 - peak) peak^b."""
    out = np.array(state, dtype=float)
    for g, s in enumerate(ratio):
        if radii[g] < rMin:
            continue
        D, ext, rising, peaks = out[g]
        if rising:
            if s > ext:
                ext = s
            elif s < ext - h:
                if ext >= endurance:
                    D, peaks = D + max(0.0, 1 - ext) * ext ** b, peaks + 1
                rising, ext = 0.0, s
        elif s < ext:
            ext = s
        elif s > ext + h:
            rising, ext = 1.0, s
        out[g] = D, ext, rising, peaks
    return out


# ---------------------------------------------------------------- one random call per function
# Each returns (the keyword arguments, a check of the result of a successful call). A check asserts the
# documented shape and, for moderate inputs, the value; it returns True when it compared values.

def fabricStress(g):
    n = int(g.rng.integers(0, 5))
    kw = dict(radius=g.number(g.magnitude()), branches=g.array(g.signed((n, 3))), forces=g.array(g.signed((n, 3))))

    def check(out):
        assert out.shape == (3, 3)
        r, l, f = asFloat(kw['radius']), asFloat(kw['branches']), asFloat(kw['forces'])
        if not moderate(r, l, f):
            return False
        scale = np.einsum('ci,cj->ij', np.abs(l), np.abs(f)) / volume(r)  # bounds the rounding error of a cancelling sum
        close(out, np.einsum('ci,cj->ij', l, f) / volume(r), atol=1e-13 * scale)
        return True
    return kw, check


def grainStresses(g):
    n, m = int(g.rng.integers(0, 4)), int(g.rng.integers(0, 7))
    idx = g.rng.integers(0, n, m) if n else np.zeros(m, dtype=int)
    kw = dict(radii=g.array(g.magnitude(n)), grainIndex=g.array(idx, integers=True), branches=g.array(g.signed((m, 3))),
              forces=g.array(g.signed((m, 3))))

    def check(out):
        r, gi = asFloat(kw['radii']), np.asarray(kw['grainIndex'], dtype=np.int64)
        assert out.shape == (len(r), 3, 3)
        l, f = asFloat(kw['branches']), asFloat(kw['forces'])
        if not moderate(r, l, f):
            return False
        want, scale = np.zeros((len(r), 3, 3)), np.zeros((len(r), 3, 3))
        np.add.at(want, gi, np.einsum('ci,cj->cij', l, f))
        np.add.at(scale, gi, np.einsum('ci,cj->cij', np.abs(l), np.abs(f)))
        V = volume(r)[:, None, None]
        close(out, want / V, atol=1e-13 * scale / V)
        return True
    return kw, check


def sigmaArgument(g):
    shape = (3, 3) if g.chance(0.4) else (int(g.rng.integers(0, 4)), 3, 3)
    return g.signed(shape) * (g.magnitude() if g.chance(0.3) else 1.0)


def vonMises(g):
    kw = dict(sigma=g.array(sigmaArgument(g)))

    def check(out):
        S = asFloat(kw['sigma'])
        assert (isinstance(out, float) if S.ndim == 2 else out.shape == S.shape[:1])
        if not moderate(S):
            return False
        close(out, vonMisesRef(S), atol=1e-9 * tensorScale(S))
        return True
    return kw, check


def principalStresses(g):
    kw = dict(sigma=g.array(sigmaArgument(g)))

    def check(out):
        S = asFloat(kw['sigma'])
        assert out.shape == S.shape[:-1]
        if not moderate(S):
            return False
        close(out, principalRef(S), atol=1e-12 * tensorScale(S)[..., None])
        return True
    return kw, check


def broadcastArguments(g, names, draw):
    """Scalars or arrays of one common length (sometimes not: a broadcast error)."""
    n = int(g.rng.integers(1, 5))
    kw = {}
    for name in names:
        v = draw(name, n if g.chance(0.5) else None)
        kw[name] = g.number(float(v)) if np.ndim(v) == 0 else g.array(v)
    return kw


def elementwiseCheck(kw, ref, rtol=1e-11):
    def check(out):
        args = [asFloat(kw[k]) for k in kw]
        shape = np.broadcast(*args).shape
        assert isinstance(out, float) if shape == () else out.shape == shape
        if not moderate(*args):
            return False
        close(out, ref(*np.broadcast_arrays(*args)), rtol=rtol)
        return True
    return check


def radiusOrWall(g, size):
    return np.where(g.rng.random(size) < 0.2, 0.0, g.magnitude(size))


def hertzPressure(g):
    kw = broadcastArguments(g, ['Fn', 'R1', 'R2', 'uN'], lambda k, n: g.signed(n) if k in ('Fn', 'uN') else radiusOrWall(g, n))
    return kw, elementwiseCheck(kw, hertzRef)


def effectiveRadius(g):
    kw = broadcastArguments(g, ['R1', 'R2'], lambda k, n: radiusOrWall(g, n))
    return kw, elementwiseCheck(kw, effectiveRadiusRef)


def sizeStrength(g):
    kw = broadcastArguments(g, ['ft0', 'radius', 'm'], lambda k, n: g.rng.uniform(0, 3, n) if k == 'm' else g.magnitude(n))
    return kw, elementwiseCheck(kw, lambda ft0, r, m: ft0 / r ** m, rtol=1e-10)  # pow: a few ulps of r^m


def contactModulus(g):
    kw = broadcastArguments(g, ['E1', 'nu1', 'E2', 'nu2'],
                            lambda k, n: g.rng.uniform(-1, 0.5, n) if k.startswith('nu') else g.magnitude(n))
    return kw, elementwiseCheck(kw, lambda E1, nu1, E2, nu2: 1 / ((1 - nu1 ** 2) / E1 + (1 - nu2 ** 2) / E2), rtol=1e-9)


def hertzPressureFromForce(g):
    kw = broadcastArguments(g, ['Fn', 'R', 'Estar'], lambda k, n: g.signed(n) if k == 'Fn' else g.magnitude(n))
    return kw, elementwiseCheck(kw, hertzFromForceRef)


def pWaveStep(g):
    kw = broadcastArguments(g, ['r', 'density', 'young'], lambda k, n: g.magnitude(n))
    return kw, elementwiseCheck(kw, lambda r, rho, E: r * np.sqrt(rho / E))


def densityScaling(g):
    kw = broadcastArguments(g, ['ownStep', 'targetStep'],
                            lambda k, n: np.where(g.rng.random(n) < 0.2, 0.0, g.magnitude(n)) if k == 'targetStep'
                            else g.magnitude(n))
    return kw, elementwiseCheck(kw, lambda own, t: np.where((t == 0) | (own >= t), 1.0, (own / np.where(t == 0, 1, t)) ** 2))


def inertialNumber(g):
    kw = broadcastArguments(g, ['rate', 'd', 'density', 'pressure'], lambda k, n: g.signed(n) if k == 'rate' else g.magnitude(n))
    return kw, elementwiseCheck(kw, lambda rate, d, rho, p: np.abs(rate) * d * np.sqrt(rho / p))


def membraneLoad(g):
    # grains near a cylinder of radius R around the axis, the membrane between z0 = 0 and z1 = 0.6
    n = int(g.rng.integers(0, 6))
    R, theta = g.rng.uniform(0.05, 0.3), g.rng.uniform(0, 2 * np.pi, n)
    c = np.column_stack([R * np.cos(theta), R * np.sin(theta), g.rng.uniform(0, 0.6, n)])
    kw = dict(centres=g.array(c), radii=g.array(g.rng.uniform(0.01, 0.05, n)), pressure=g.number(float(g.magnitude())),
              axisX=g.number(0.0), axisY=g.number(0.0), z0=g.number(0.0), z1=g.number(0.6),
              nTheta=g.integer(int(g.rng.integers(3, 40))), nZ=g.integer(int(g.rng.integers(1, 30))),
              depth=g.number(float(g.rng.uniform(0, 0.02))))

    def check(out):
        # the area is the sum over the cells carried of rho dtheta dz; no axial force; owners are grains or -1
        x = {k: asFloat(v) for k, v in kw.items()}
        if x['centres'].shape != (n, 3) or not moderate(x['centres'], x['radii'], x['pressure']):
            return False
        rho, owner = out['radius'], out['owner']
        nZ, nT = rho.shape
        assert owner.shape == rho.shape and owner.min(initial=-1) >= -1 and owner.max(initial=-1) < n
        dth, dz = 2 * np.pi / nT, (float(x['z1']) - float(x['z0'])) / nZ
        close(out['area'], np.sum(rho[owner >= 0]) * dth * dz, atol=1e-300, rtol=1e-9)
        assert np.all(out['force'][:, 2] == 0) and np.all(rho[owner < 0] == 0)
        assert np.sum(np.hypot(out['force'][:, 0], out['force'][:, 1])) <= float(x['pressure']) * out['area'] * (1 + 1e-9)
        return True
    return kw, check


def clumpStresses(g):
    # m members of k clumps: sigma_k V_k = sum over its members of sigma_m V_m + F_m (x) (x_m - X_k)
    k, m = int(g.rng.integers(1, 4)), int(g.rng.integers(0, 7))
    idx = g.rng.integers(0, k, m)
    kw = dict(memberStresses=g.array(g.signed((m, 3, 3))), memberVolumes=g.array(g.magnitude(m)),
              memberForces=g.array(g.signed((m, 3))), memberPositions=g.array(g.signed((m, 3))),
              clumpIndex=g.array(idx, integers=True), clumpCentres=g.array(g.signed((k, 3))),
              clumpVolumes=g.array(g.magnitude(k)))

    def check(out):
        x = {n: asFloat(v) for n, v in kw.items() if n != 'clumpIndex'}
        ci = np.asarray(kw['clumpIndex'])
        shapes = {'memberStresses': (m, 3, 3), 'memberVolumes': (m,), 'memberForces': (m, 3),
                  'memberPositions': (m, 3), 'clumpCentres': (k, 3), 'clumpVolumes': (k,)}
        if any(x[n].shape != sh for n, sh in shapes.items()) or ci.shape != (m,) or not moderate(*x.values()):
            return False
        terms = x['memberStresses'] * x['memberVolumes'][:, None, None] + np.einsum(
            'mi,mj->mij', x['memberForces'], x['memberPositions'] - x['clumpCentres'][idx])
        want, scale = np.zeros((k, 3, 3)), np.zeros(k)
        for j in range(m):
            want[idx[j]] += terms[j]
            scale[idx[j]] += np.max(np.abs(terms[j]))
        want /= x['clumpVolumes'][:, None, None]
        close(out, want, atol=1e-12 * (scale / x['clumpVolumes'])[:, None, None], rtol=1e-11)
        return True
    return kw, check


def majorPrincipalRef(S):
    """The largest principal compressive stress of eq. 3 (compression negative): -lambda_min, 0 if none."""
    return np.maximum(0.0, -np.linalg.eigvalsh(symmetricPart(S))[..., 0])


def crushCheck(g):
    n = int(g.rng.integers(0, 5))
    r = g.magnitude(n)
    criterion = g.pick(['vonMises', 'vonMises', 'maxContactForce', 'majorPrincipal', 'tresca'])
    kw = dict(stresses=g.array(g.signed((n, 3, 3))), radii=g.array(r), ft0=g.number(g.magnitude()),
              m=g.number(g.pick([1.0, 0.0, 2.0, g.rng.uniform(0, 3)])),
              rMin=g.number(float(np.median(r)) if n and g.chance(0.5) else 0.0), criterion=criterion)
    if criterion == 'maxContactForce' or g.chance(0.2):
        kw['fMax'] = g.array(g.magnitude(n))
    if g.chance(0.5):
        kw['factor'] = g.array(g.magnitude(n))

    def check(out):
        S, r = asFloat(kw['stresses']), asFloat(kw['radii'])
        ft0, m, rMin = (float(asFloat(kw[k])) for k in ('ft0', 'm', 'rMin'))
        w = asFloat(kw['factor']) if 'factor' in kw else np.ones(len(r))
        stress, ft, crush = out
        assert stress.shape == ft.shape == crush.shape == r.shape and crush.dtype == bool
        fm = asFloat(kw['fMax']) if 'fMax' in kw else np.zeros(len(r))
        if not moderate(S, r, ft0, m, rMin, w, fm):
            return False
        want = {'vonMises': lambda: vonMisesRef(S), 'majorPrincipal': lambda: majorPrincipalRef(S),
                'maxContactForce': lambda: fm / (4 * r ** 2)}[criterion]()
        close(stress, want, atol=1e-9 * (tensorScale(S) if criterion != 'maxContactForce' else np.max(want, initial=0)))
        close(ft, w * ft0 / r ** m, rtol=1e-10)
        clear = np.abs(stress - ft) > 1e-8 * np.maximum(stress, ft)  # eq. 1 away from a tie
        np.testing.assert_array_equal(crush[clear], ((r >= rMin) & (stress > ft))[clear])
        return True
    return kw, check


def weibullFactors(g):
    n = int(g.rng.integers(0, 6))
    kw = dict(seed=g.integer(int(g.rng.integers(0, 2 ** 63))), keys=g.array(g.rng.integers(0, 10 ** 6, n), integers=True),
              modulus=g.number(g.pick([0.0, 3.0, 10.0, float(g.rng.uniform(1, 50))])))

    def check(w):
        k = asFloat(kw['modulus'])
        assert w.shape == (n,) and np.all(w > 0)
        if k == 0:
            np.testing.assert_array_equal(w, 1.0)
        # the same key, drawn alone, gives the same factor (independent of the order and of the others)
        keys = np.asarray(kw['keys'], dtype=np.int64)
        if n:
            assert B.weibullFactors(kw['seed'], keys[-1:], float(k))[0] == w[-1]
        return True
    return kw, check


def abrasionCheck(g):
    n, m = int(g.rng.integers(0, 4)), int(g.rng.integers(0, 6))

    def side():  # a grain index or -1
        return g.rng.integers(-1, n, m)
    kw = dict(radii=g.array(g.magnitude(n)), grain1=g.array(side(), integers=True), grain2=g.array(side(), integers=True),
              Fn=g.array(g.signed(m)), R1=g.array(radiusOrWall(g, m)), R2=g.array(radiusOrWall(g, m)), uN=g.array(g.signed(m)),
              strength=g.number(g.magnitude()), rMin=g.number(g.pick([0.0, 1e-3])))

    def check(out):
        p0, abrade = out
        r = asFloat(kw['radii'])
        assert p0.shape == abrade.shape == r.shape and abrade.dtype == bool
        F, R1, R2, uN = (asFloat(kw[k]) for k in ('Fn', 'R1', 'R2', 'uN'))
        strength, rMin = float(asFloat(kw['strength'])), float(asFloat(kw['rMin']))
        if not moderate(r, F, R1, R2, uN, strength, rMin):
            return False
        p = hertzRef(F, R1, R2, uN)
        want = np.zeros(len(r))
        for k in ('grain1', 'grain2'):
            gi = np.asarray(kw[k], dtype=np.int64)
            np.maximum.at(want, gi[gi >= 0], p[gi >= 0])
        close(p0, want)
        clear = np.abs(p0 - strength) > 1e-9 * strength
        np.testing.assert_array_equal(abrade[clear], ((r >= rMin) & (p0 > strength))[clear])
        return True
    return kw, check


def fatigueCheck(g):
    n = int(g.rng.integers(0, 5))
    state = np.column_stack([g.rng.uniform(0, 1, n) * (g.rng.random(n) < 0.5), g.rng.uniform(0, 1.5, n),
                             g.rng.integers(0, 2, n), g.rng.integers(0, 5, n)]).astype(float).reshape(n, 4)
    kw = dict(ratio=g.array(g.rng.uniform(0, 1.5, n)), radii=g.array(g.magnitude(n)), state=g.array(state),
              exponent=g.number(g.pick([1.0, 2.0, 8.0, 100.0])), endurance=g.number(g.rng.uniform(0, 1)),
              hysteresis=g.number(g.rng.uniform(0.001, 0.5)), rMin=g.number(g.pick([0.0, 1e-3])))

    def check(out):
        st, crush = out
        s, r = asFloat(kw['ratio']), asFloat(kw['radii'])
        assert st.shape == (len(s), 4) and crush.shape == s.shape and crush.dtype == bool
        b, e, h, rMin = (float(asFloat(kw[k])) for k in ('exponent', 'endurance', 'hysteresis', 'rMin'))
        state = asFloat(kw['state'])
        if not moderate(s, r, state, b, e, h, rMin):
            return False
        want = fatigueRef(s, r, rMin, state, b, e, h)
        close(st, want, atol=1e-300)
        clear = np.abs(s - (1 - want[:, 0])) > 1e-12
        np.testing.assert_array_equal(crush[clear], ((r >= rMin) & (s > 1 - want[:, 0]))[clear])
        return True
    return kw, check


def abrasionBound(g):
    n = int(g.rng.integers(0, 4))
    kw = dict(stresses=g.array(g.signed((n, 3, 3))), radii=g.array(g.magnitude(n)),
              rPartner=g.number(g.pick([0.0, float(g.magnitude())])), EstarMax=g.number(g.magnitude() * 1e6))

    def check(out):
        S, r = asFloat(kw['stresses']), asFloat(kw['radii'])
        rP, Es = float(asFloat(kw['rPartner'])), float(asFloat(kw['EstarMax']))
        assert out.shape == r.shape
        if not moderate(S, r, rP, Es):
            return False
        Fmax = 2 * np.abs(np.trace(S, axis1=1, axis2=2)) * volume(r) / r  # docs: the largest normal force
        R = r if rP == 0 else r * rP / (r + rP)
        close(out, hertzFromForceRef(Fmax, R, Es), rtol=1e-10)
        return True
    return kw, check


def sphereContactBound(g):
    kw = dict(maxOverlapRatio=g.number(g.pick([-1.0, 0.0, float(g.magnitude())])), EstarMax=g.number(g.magnitude() * 1e6))

    def check(out):
        rho, Es = float(asFloat(kw['maxOverlapRatio'])), float(asFloat(kw['EstarMax']))
        assert isinstance(out, float)
        if not moderate(rho, Es):
            return False
        close(out, 2 * Es / np.pi * np.sqrt(2 * rho) if rho > 0 else 0.0)
        return True
    return kw, check


def patternArgument(g):
    p = g.pick(PATTERNS)
    if isinstance(p, str):
        return p if not g.chance(g.p) else g.pick(['hex', '5', '', 'Tetra4'])
    return g.integer(p)


def fragmentPattern(g):
    kw = dict(pattern=patternArgument(g))

    def check(f):
        assert f.shape == (KEPT[B.patternName(kw['pattern'])], 4)
        assert np.all(np.linalg.norm(f[:, :3], axis=1) + f[:, 3] <= 1 + 1e-12)  # inside the unit parent
        return True
    return kw, check


def keptVolumeFraction(g):
    kw = dict(pattern=patternArgument(g))

    def check(kept):
        assert isinstance(kept, float) and 0 < kept < 1
        close(kept, np.sum(B.fragmentPattern(kw['pattern'])[:, 3] ** 3))
        return True
    return kw, check


def patternName(g):
    kw = dict(pattern=patternArgument(g))

    def check(name):
        assert len(B.fragmentPattern(kw['pattern'])) == KEPT[name]
        return True
    return kw, check


def seedArguments(g):
    return dict(seed=g.integer(int(g.rng.integers(0, 2 ** 63))), counter=g.integer(int(g.rng.integers(0, 1000))))


def randomRotation(g):
    kw = seedArguments(g)

    def check(Q):
        assert Q.shape == (3, 3)
        close(Q @ Q.T, np.eye(3), atol=1e-12)
        close(np.linalg.det(Q), 1.0)
        return True
    return kw, check


def placeFragments(g):
    kw = dict(pattern=patternArgument(g), centre=g.array(g.signed(3)), radius=g.number(g.magnitude()), **seedArguments(g))

    def check(out):
        f = B.fragmentPattern(kw['pattern'])
        assert out.shape == f.shape
        c, r = asFloat(kw['centre']), float(asFloat(kw['radius']))
        if not moderate(c, r):
            return False
        Q = B.randomRotation(kw['seed'], kw['counter'])
        close(out[:, :3], c + r * f[:, :3] @ Q.T, atol=1e-14 * (np.max(np.abs(c)) + r))
        close(out[:, 3], r * f[:, 3])
        return True
    return kw, check


def matricesToArray(g):
    n = int(g.rng.integers(0, 4))
    items = [g.array(g.signed((3, 3))) for _ in range(n)]
    form = g.rng.integers(3)
    kw = dict(matrices=items if form == 0 else tuple(items) if form == 1 else g.array(g.signed((n, 3, 3))))

    def check(out):
        want = asFloat(list(kw['matrices']))
        assert out.shape == (len(want), 3, 3)
        close(out, want.reshape(-1, 3, 3), rtol=0)
        return True
    return kw, check


def driftDamageRef(b, e, s0, d, N):
    """The bound on sum (1 - s) s^b over the drifting peaks s0 + k d >= e, k <= N: the integral of the law, held at
    its top b / (b + 1) beyond it, from max(e, s0 + d) to s0 + (N + 1) d, over d."""
    if s0 + N * d < e:
        return 0.0
    top = b / (b + 1)

    def primitive(s):
        u = min(s, top)
        extra = (1 - top) * top ** b * (s - top) if s > top else 0.0
        return u ** (b + 1) / (b + 1) - u ** (b + 2) / (b + 2) + extra
    return (primitive(s0 + (N + 1) * d) - primitive(max(e, s0 + d))) / d


def cycleJumpRef(D, S, cycle, remaining, W, steady, maxDamage, margin, growth, endurance, driftNoise, exponent,
                 driftDamage):
    """CycleJump.hpp's bounds, written again: (cycles, limit, grain, maxRate, rate, the bounding grain's largest
    peak and drift)."""
    h, best, limit, grain, which = W // 2, float(remaining), 'remaining', -1, (0.0, 0.0)
    if math.floor(growth * cycle) < best:
        best, limit = max(math.floor(growth * cycle), 0.0), 'growth'
    rate = (D[W] - D[0]) / W
    for k, r in enumerate(rate):
        sMax, first, second = 0.0, 0.0, 0.0
        for c in range(W):
            sMax = max(sMax, S[c, k])
            if c < h:
                first += S[c, k]
            else:
                second += S[c, k]
        first, second = first / h, second / (W - h)
        squares = 0.0
        for c in range(W):
            squares += (S[c, k] - (first if c < h else second)) ** 2
        spread = math.sqrt(squares / (W - 2) * (1.0 / h + 1.0 / (W - h))) if W > 2 else 0.0
        drift = (second - first - driftNoise * spread) / (0.5 * W)
        bounds = []
        if sMax < endurance and drift > 0:
            lo, hi = math.floor((endurance - sMax) / drift), best
            if lo < hi and driftDamageRef(exponent, endurance, sMax, drift, hi) > driftDamage:
                if driftDamageRef(exponent, endurance, sMax, drift, lo) > driftDamage:
                    lo -= 1
                while hi - lo > 1:   # the largest count whose bound is within driftDamage
                    mid = math.floor((lo + hi) / 2)
                    if driftDamageRef(exponent, endurance, sMax, drift, mid) <= driftDamage:
                        lo = mid
                    else:
                        hi = mid
                bounds.append((lo, 'endurance'))
            bounds.append((math.floor((1.0 - D[W, k] - sMax) / drift) - margin, 'failure'))
        if r > 0:
            a, b = (D[h, k] - D[0, k]) / h, (D[W, k] - D[h, k]) / (W - h)
            bounds.append((math.floor(maxDamage / r), 'maxDamage'))
            if a != b:
                bounds.append((math.floor(steady * maxDamage / abs(b - a)), 'steady'))
            bounds.append((math.floor((1.0 - sMax - D[W, k]) / r) - margin, 'failure'))
        for c, name in bounds:   # in the order the C++ tests them: endurance, maxDamage, steady, failure
            if c < best:
                best, limit, grain, which = max(c, 0.0), name, k, (sMax, drift)
    return (int(best), limit, grain, max([0.0] + list(rate)), rate) + which


def cycleJumpPlan(g):
    W, n = int(g.rng.integers(2, 6)), int(g.rng.integers(0, 5))
    inc = g.rng.uniform(0, 0.02, (W, n)) * (g.rng.random((W, n)) < 0.7)
    D = np.vstack([g.rng.uniform(0, 0.5, (1, n)) * (g.rng.random(n) < 0.5), inc]).cumsum(axis=0)
    S = g.rng.uniform(0.05, 1.0, (W, n)) * (g.rng.random((W, n)) < 0.9)
    S[:, D[-1] > D[0]] += 0.01                               # a grain whose damage grew has peaks
    kw = dict(damage=g.array(D), peaks=g.array(S), cycle=g.number(float(g.rng.integers(1, 10 ** 4))),
              remaining=g.number(float(g.rng.integers(0, 10 ** 6))), window=g.number(float(W)),
              steady=g.number(g.rng.uniform(0.01, 1)), maxDamage=g.number(g.rng.uniform(0.001, 0.99)),
              margin=g.number(float(g.rng.integers(0, 4))), growth=g.number(g.pick([0.5, 1.0, 10.0, 1000.0])),
              endurance=g.number(g.rng.uniform(0, 0.9)), driftNoise=g.number(g.pick([0.0, 0.5, 2.0, 100.0])),
              exponent=g.number(g.pick([1.0, 3.0, 30.0])), driftDamage=g.number(g.pick([0.0, 1e-6, 1e-3, 0.5])))

    def check(out):
        cycles, limit, grain, maxRate, rate, peak, drift = out
        x = {k: asFloat(v) for k, v in kw.items()}
        if x['damage'].shape != (W + 1, n) or not moderate(x['damage'], x['peaks']):
            return False
        want = cycleJumpRef(x['damage'], x['peaks'], float(x['cycle']), float(x['remaining']), W, float(x['steady']),
                            float(x['maxDamage']), float(x['margin']), float(x['growth']), float(x['endurance']),
                            float(x['driftNoise']), float(x['exponent']), float(x['driftDamage']))
        assert (cycles, limit, grain) == want[:3] and rate.shape == (n,)
        close(rate, want[4], atol=1e-300)
        assert maxRate == pytest.approx(want[3], rel=1e-12, abs=1e-300)
        assert (peak, drift) == pytest.approx(want[5:], rel=1e-12, abs=1e-300)
        return True
    return kw, check


def fastMatrixPath(g):
    kw = dict(item=g.pick([g.array(g.signed((3, 3))), g.pick(GARBAGE), g.number(1.0)]))

    def check(out):
        assert out is False  # no minieigen matrix outside YADE
        return False
    return kw, check


def clumpSplit(g):
    # m members about a centre: every member in one piece 0..k-1, each piece held, k >= 2 when m >= 2, unit normals;
    # pairs: members of different pieces whose spheres overlap (|x_i - x_j| < r_i + r_j)
    m = int(g.rng.integers(1, 12))
    kw = dict(stress=g.array(g.signed((3, 3))), centre=g.array(g.signed(3)), memberPositions=g.array(g.signed((m, 3))),
              memberRadii=g.array(g.magnitude(m)))

    def check(out):
        x = {n: asFloat(v) for n, v in kw.items()}
        shapes = {'stress': (3, 3), 'centre': (3,), 'memberPositions': (m, 3), 'memberRadii': (m,)}
        if any(x[n].shape != sh for n, sh in shapes.items()) or not moderate(*x.values()):
            return False
        piece, k = out['piece'], out['nPieces']
        assert piece.shape == (m,) and sorted(set(piece.tolist())) == list(range(k)) and (k >= 2) == (m >= 2)
        close(np.linalg.norm(out['normals'], axis=1), np.ones(len(out['normals'])), rtol=1e-12)
        c, r = x['memberPositions'], x['memberRadii']
        want = [[i, j] for i in range(m) for j in range(i + 1, m)
                if piece[i] != piece[j] and np.linalg.norm(c[i] - c[j]) < r[i] + r[j]]
        assert out['pairs'].tolist() == want
        return True
    return kw, check


FUNCTIONS = {'fabricStress': fabricStress, 'grainStresses': grainStresses, 'vonMises': vonMises,
             'principalStresses': principalStresses, 'hertzPressure': hertzPressure, 'effectiveRadius': effectiveRadius,
             'sizeStrength': sizeStrength, 'contactModulus': contactModulus, 'hertzPressureFromForce': hertzPressureFromForce,
             'crushCheck': crushCheck, 'abrasionCheck': abrasionCheck, 'fatigueCheck': fatigueCheck,
             'weibullFactors': weibullFactors,
             'abrasionBound': abrasionBound, 'sphereContactBound': sphereContactBound, 'fragmentPattern': fragmentPattern,
             'keptVolumeFraction': keptVolumeFraction, 'patternName': patternName, 'randomRotation': randomRotation,
             'placeFragments': placeFragments, 'matricesToArray': matricesToArray, '_fastMatrixPath': fastMatrixPath,
             'pWaveStep': pWaveStep, 'densityScaling': densityScaling, 'inertialNumber': inertialNumber,
             'membraneLoad': membraneLoad, 'clumpStresses': clumpStresses, 'clumpSplit': clumpSplit,
             'cycleJumpPlan': cycleJumpPlan}


# functions without arguments: nothing to fuzz (tests/python/test__ballast_InputCheck.py, _CrushCriterion.py)
NO_ARGUMENTS = {'parameterRanges', 'criterionNames'}


def test_every_function_of_the_binding_is_fuzzed():
    public = {k for k in dir(B) if not k.startswith('__')}
    assert public == set(FUNCTIONS) | NO_ARGUMENTS


def finite(out):
    """Every float in the result (a float, an array or a tuple of them) is finite."""
    if isinstance(out, tuple):
        return all(finite(o) for o in out)
    if isinstance(out, dict):
        return all(finite(o) for o in out.values())
    if isinstance(out, (bool, str)):
        return True
    a = np.asarray(out)
    return a.dtype == bool or bool(np.all(np.isfinite(a)))


def namedArguments(message):
    """The argument names a message starts with: 'Fn, R1[3]: expected ...' -> {'Fn', 'R1'}."""
    head = message.split(': ', 1)[0]
    return {re.sub(r'\[\d+\]$', '', name) for name in head.split(', ')}


def generate(name, g):
    with warnings.catch_warnings(), np.errstate(all='ignore'):
        warnings.simplefilter('ignore')  # casts of huge values to float16 or float32
        return FUNCTIONS[name](g)


@pytest.mark.parametrize('name', sorted(FUNCTIONS))
def test_fuzz(name):
    nArgs = len(generate(name, Gen(np.random.default_rng(0)))[0])
    g = Gen(np.random.default_rng([SEED, sorted(FUNCTIONS).index(name)]), p=1 - 0.5 ** (1 / nArgs))
    fn = getattr(B, name)
    compared = refused = 0
    for call in range(CALLS):
        kw, check = generate(name, g)
        try:
            out = fn(**kw)
        except (TypeError, ValueError) as e:
            assert namedArguments(str(e)) & set(kw), (call, kw, str(e))
            refused += 1
            continue
        # anything else (another exception, a crash) fails the test by itself
        assert finite(out), (call, kw, out)
        with np.errstate(all='ignore'):
            compared += bool(check(out))
    if name != '_fastMatrixPath':  # takes anything
        assert refused > CALLS // 20, refused  # the bad inputs were exercised,
        assert compared > CALLS // 5, compared  # and so were valid calls, checked against the formulas
