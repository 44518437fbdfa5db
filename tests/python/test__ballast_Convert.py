"""Tests of the shared conversions pkg/python/Convert.cpp, through the functions that use them: any Python or
NumPy number where a number is due, any integer type where an integer is, arrays of any real dtype and order,
and each bad type, dtype, shape or value named in a TypeError or ValueError."""
import numpy as np
import pytest

import ballast._ballast as B

S1 = np.array([np.diag([-1e6, 0.0, 0.0])])  # one grain in uniaxial compression
FRESH = [[0.0, 0.0, 1.0, 0.0]]

# Every scalar argument of every function, with Python-number keyword arguments that make a valid call:
# (function, argument, the other arguments, a float value, an int value or None when no int is valid).
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
    ('weibullFactors', 'modulus', dict(seed=1, keys=[3, 4]), 2.5, 3),
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
    f = getattr(B, fn)
    assert_same_result(f(**others, **{arg: numpyNumber(*type_, value)}), f(**others, **{arg: value}))


@pytest.mark.parametrize('type_', INT_TYPES, ids=typeId)
@pytest.mark.parametrize('call', [
    lambda n: B.fragmentPattern(n(6)),
    lambda n: B.fragmentPattern(n(14)),
    lambda n: B.keptVolumeFraction(n(4)),
    lambda n: B.patternName(n(6)),
    lambda n: B.randomRotation(n(42), n(7)),
    lambda n: B.placeFragments(n(4), [0.1, 0.2, 0.3], 0.02, n(42), n(7)),
    lambda n: B.weibullFactors(n(42), [1, 2], 3.0),
], ids=['fragmentPattern6', 'fragmentPattern14', 'keptVolumeFraction', 'patternName', 'randomRotation', 'placeFragments',
        'weibullFactors'])
def test_numpy_integers_are_integers(call, type_):
    assert_same_result(call(lambda v: numpyNumber(*type_, v)), call(int))


def test_arrays_of_any_real_dtype_order_and_nesting_are_read_alike():
    # grainStresses of eq. 3 with the branches and forces as float64 C arrays, Fortran-ordered, strided views,
    # nested lists, int and float32 arrays holding the same values: the same tensors, bit for bit
    radii, idx = np.array([1.0, 2.0]), np.array([0, 1, 1])
    l = np.array([[1.0, 0, 0], [0, 2, 0], [0, 0, -2]])
    f = np.array([[-4.0, 0, 0], [0, 8, 0], [0, 0, 2]])
    want = B.grainStresses(radii, idx, l, f)
    wide = np.zeros((3, 6))
    wide[:, ::2] = l
    for form in (np.asfortranarray(l), wide[:, ::2], l.tolist(), l.astype(np.int32), l.astype(np.float32)):
        np.testing.assert_array_equal(B.grainStresses(radii, idx, form, f), want)
    np.testing.assert_array_equal(B.grainStresses(radii, idx.astype(np.uint8), l, f), want)
    # (1/V) sum l F: grain 0 has l_x F_x = -4 over V = 4/3 pi
    assert want[0, 0, 0] == pytest.approx(-4 / (4 / 3 * np.pi), rel=1e-15)


def test_inputs_are_not_changed():
    state = np.array([[0.0, 0.8, 1.0, 0.0]])
    B.fatigueCheck([0.6], [0.02], state, 2.0, 0.5, 0.1, 0.0)
    np.testing.assert_array_equal(state, [[0.0, 0.8, 1.0, 0.0]])


UINT_TOP = np.array([2 ** 64 - 1], dtype=np.uint64)


@pytest.mark.parametrize('call,exc,message', [
    # numbers: one each, finite, real
    (lambda: B.crushCheck(S1, [0.02], np.array([2e5, 1.0]), 1.0, 0.0), TypeError,
     'ft0: expected a number, got an array of shape (2,)'),
    (lambda: B.crushCheck(S1, [0.02], 2e5, np.float64('nan'), 0.0), ValueError, 'm: expected a finite number, got nan'),
    (lambda: B.crushCheck(S1, [0.02], 2e5, 1.0, np.float32('inf')), ValueError, 'rMin: expected a finite number, got inf'),
    (lambda: B.crushCheck(S1, [0.02], 'a', 1.0, 0.0), TypeError, 'ft0: expected real numbers, got dtype <U1'),
    (lambda: B.crushCheck(S1, [0.02], np.complex128(1), 1.0, 0.0), TypeError, 'ft0: expected real numbers, got dtype complex128'),
    (lambda: B.fatigueCheck([0.5], [0.02], FRESH, np.True_, 0.5, 0.1, 0.0), TypeError,
     'exponent: expected real numbers, got dtype bool'),
    (lambda: B.abrasionBound(S1, [0.02], np.array([0.0]), 1e11), TypeError,
     'rPartner: expected a number, got an array of shape (1,)'),
    (lambda: B.sphereContactBound(1e-3, None), TypeError, 'EstarMax: expected real numbers, got dtype object'),
    # arrays: real, finite, the right shape
    (lambda: B.vonMises(np.zeros((3, 3), dtype=complex)), TypeError, 'sigma: expected real numbers, got dtype complex128'),
    (lambda: B.vonMises([[1, 2], [3]]), TypeError, 'sigma: expected an array of numbers, got list'),
    (lambda: B.fabricStress(1.0, [[np.inf, 0, 0]], [[1, 0, 0]]), ValueError,
     'branches: expected finite numbers, got inf at flat index 0'),
    (lambda: B.fabricStress(1.0, [[1, 0, 0]], [[0, 0, np.nan]]), ValueError,
     'forces: expected finite numbers, got nan at flat index 2'),
    (lambda: B.fabricStress(1.0, [[1, 0]], [[1, 0, 0]]), TypeError, 'branches: expected an (n,3) array, got shape (1,2)'),
    # integers: Python ints and NumPy integers only, in range
    (lambda: B.grainStresses([1.0], [0.5], [[1, 0, 0]], [[1, 0, 0]]), TypeError, 'grainIndex: expected integers, got dtype float64'),
    (lambda: B.grainStresses([1.0], UINT_TOP, [[1, 0, 0]], [[1, 0, 0]]), ValueError,
     'grainIndex: expected integers below 2^63, got 18446744073709551615 at flat index 0'),
    (lambda: B.fragmentPattern(np.float64(6)), TypeError,
     "pattern: expected 4, 6, 14 or one of 'tetra4', 'planar4', 'octa6', 'fill14', got 6.0"),
    (lambda: B.fragmentPattern(np.True_), TypeError,
     "pattern: expected 4, 6, 14 or one of 'tetra4', 'planar4', 'octa6', 'fill14', got True"),
    (lambda: B.randomRotation(0, np.int64(-1)), ValueError, 'counter: expected an integer in [0, 2^64), got -1'),
    (lambda: B.randomRotation(0, True), TypeError, 'counter: expected an integer in [0, 2^64), got True'),
    (lambda: B.placeFragments(6, [0, 0, 0], 1.0, 1, np.array(2.0)), TypeError,
     'counter: expected an integer in [0, 2^64), got array(2.)'),
    (lambda: B.randomRotation(np.float32(1), 0), TypeError, 'seed: expected an integer in [0, 2^63 - 1], got 1.0'),
    # a result that would not be finite (finiteResult): one value, or the first index
    (lambda: B.vonMises(np.diag([1e200, 0, 0])), ValueError,
     'sigma: expected values whose von Mises stress is finite, the result would be inf'),
    (lambda: B.hertzPressure([1.0, 1e300], 1e-10, 0, 1e-290), ValueError,
     'Fn, R1, R2, uN: expected values whose Hertz pressure is finite, the result would be inf at index 1'),
    (lambda: B.hertzPressure([1, 2], [1, 1, 1], 0, 1e-3), TypeError,
     'Fn, R1, R2, uN: expected scalars or arrays of equal length, got shapes (2,), (3,), (), ()'),
])
def test_bad_types_dtypes_shapes_and_values_are_named(call, exc, message):
    with pytest.raises(exc) as e:
        call()
    assert str(e.value) == message


def test_a_scalar_result_is_a_float_and_arrays_broadcast():
    assert type(B.effectiveRadius(0.02, 0.02)) is float
    assert B.effectiveRadius(0.02, 0.02) == 0.01
    r = B.effectiveRadius([0.02, 0.03], 0.0)  # a wall: R = R1
    assert isinstance(r, np.ndarray) and r.tolist() == [0.02, 0.03]
    assert B.effectiveRadius(np.array(0.02), 0.06) == pytest.approx(0.015, rel=1e-15)  # 0-d in, float out
