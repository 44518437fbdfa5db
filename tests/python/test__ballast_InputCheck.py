"""Tests of pkg/python/bind_InputCheck.cpp: the ranges of the engines' parameters, declared once in C++
(pkg/InputCheck.hpp) and exported as parameterRanges(); ballast.params builds its checks and words from them,
so that the Python check and the binding refuse the same values, in the same words."""
import math

import numpy as np
import pytest

import ballast._ballast as B
from ballast import params
from ballast.engineparams import ABRASION, CRUSH
from ballast.experiments.parameters import CYCLE_JUMP
from ballast.params import ParamError, validate

INF = math.inf
# (lower, upper, lowerClosed, upperClosed, integer, zeroAllowed, words), as the engines' documentation gives them
EXPECTED = {
    'ft0': (0.0, INF, False, False, False, False, 'a finite number > 0'),
    'm': (0.0, 3.0, True, True, False, False, 'a number in [0, 3]'),
    'rMin': (0.0, INF, True, False, False, False, 'a finite number >= 0'),
    'seed': (0.0, 2.0 ** 63, True, False, True, False, 'an integer in [0, 2^63 - 1]'),
    'weibullModulus': (1.0, 50.0, True, True, False, True, '0 or a number in [1, 50]'),
    'fatigueExponent': (1.0, 100.0, True, True, False, False, 'a number in [1, 100]'),
    'fatigueEndurance': (0.0, 1.0, True, False, False, False, 'a number in [0, 1)'),
    'fatigueHysteresis': (0.001, 0.5, True, True, False, False, 'a number in [0.001, 0.5]'),
    'strength': (0.0, INF, False, False, False, False, 'a finite number > 0'),
    'jumpWindow': (2.0, 10000.0, True, True, True, False, 'an integer in [2, 10000]'),
    'jumpSteady': (0.0, 1.0, False, True, False, False, 'a number in (0, 1]'),
    'jumpMaxDamage': (0.0, 1.0, False, False, False, False, 'a number in (0, 1)'),
    'jumpMargin': (0.0, 10000.0, True, True, True, False, 'an integer in [0, 10000]'),
    'jumpGrowth': (0.0, 1000.0, False, True, False, False, 'a number in (0, 1000]'),
    'jumpDriftNoise': (0.0, 100.0, True, True, False, False, 'a number in [0, 100]'),
    'jumpDriftDamage': (0.0, 1.0, True, False, False, False, 'a number in [0, 1)'),
}
TABLE = dict(CRUSH, **ABRASION, **CYCLE_JUMP)


def test_the_ranges_are_exported_as_declared():
    assert B.parameterRanges() == EXPECTED


@pytest.mark.parametrize('name', sorted(EXPECTED))
def test_the_python_declaration_says_the_cores_words(name):
    assert TABLE[name].allowed == EXPECTED[name][-1]


# The binding's entry of each parameter: a call with the value v and valid other arguments.
S1, FRESH, KEYS = np.zeros((1, 3, 3)), [[0.0, 0.0, 1.0, 0.0]], [1, 2]
ENTRIES = {
    'ft0': [lambda v: B.crushCheck(S1, [0.02], v, 1.0, 0.0), lambda v: B.sizeStrength(v, 0.02, 1.0)],
    'm': [lambda v: B.crushCheck(S1, [0.02], 2e5, v, 0.0), lambda v: B.sizeStrength(2e5, 0.02, v)],
    'rMin': [lambda v: B.crushCheck(S1, [0.02], 2e5, 1.0, v),
             lambda v: B.fatigueCheck([0.5], [0.02], FRESH, 2.0, 0.5, 0.1, v),
             lambda v: B.abrasionCheck([0.02], [0], [-1], [1.0], [0.02], [0.0], [1e-6], 1e8, v)],
    'seed': [lambda v: B.weibullFactors(v, KEYS, 3.0), lambda v: B.randomRotation(v, 0),
             lambda v: B.placeFragments(6, [0, 0, 0], 0.02, v, 0)],
    'weibullModulus': [lambda v: B.weibullFactors(1, KEYS, v)],
    'fatigueExponent': [lambda v: B.fatigueCheck([0.5], [0.02], FRESH, v, 0.5, 0.1, 0.0),
                        lambda v: B.cycleJumpPlan(np.zeros((3, 1)), np.zeros((2, 1)), 7, 5, 2, 0.2, 0.05, 1, 1.0, 0.5, 2.0,
                                                  v, 1e-3)],
    'fatigueEndurance': [lambda v: B.fatigueCheck([0.5], [0.02], FRESH, 2.0, v, 0.1, 0.0),
                         lambda v: B.cycleJumpPlan(np.zeros((3, 1)), np.zeros((2, 1)), 7, 5, 2, 0.2, 0.05, 1, 1.0, v, 2.0, 10.0, 1e-3)],
    'fatigueHysteresis': [lambda v: B.fatigueCheck([0.5], [0.02], FRESH, 2.0, 0.5, v, 0.0)],
    'strength': [lambda v: B.abrasionCheck([0.02], [0], [-1], [1.0], [0.02], [0.0], [1e-6], v, 0.0)],
    # a window of v cycles needs v + 1 rows of damage and v of peaks (3 and 2 where v is refused anyway)
    'jumpWindow': [lambda v: B.cycleJumpPlan(np.zeros((v + 1 if 2 <= v <= 10000 else 3, 1)),
                                             np.zeros((v if 2 <= v <= 10000 else 2, 1)), 7, 5, v, 0.2, 0.05, 1, 1.0, 0.5, 2.0,
                                             10.0, 1e-3)],
    'jumpSteady': [lambda v: B.cycleJumpPlan(np.zeros((3, 1)), np.zeros((2, 1)), 7, 5, 2, v, 0.05, 1, 1.0, 0.5, 2.0, 10.0, 1e-3)],
    'jumpMaxDamage': [lambda v: B.cycleJumpPlan(np.zeros((3, 1)), np.zeros((2, 1)), 7, 5, 2, 0.2, v, 1, 1.0, 0.5, 2.0, 10.0, 1e-3)],
    'jumpMargin': [lambda v: B.cycleJumpPlan(np.zeros((3, 1)), np.zeros((2, 1)), 7, 5, 2, 0.2, 0.05, v, 1.0, 0.5, 2.0, 10.0, 1e-3)],
    'jumpGrowth': [lambda v: B.cycleJumpPlan(np.zeros((3, 1)), np.zeros((2, 1)), 7, 5, 2, 0.2, 0.05, 1, v, 0.5, 2.0, 10.0, 1e-3)],
    'jumpDriftNoise': [lambda v: B.cycleJumpPlan(np.zeros((3, 1)), np.zeros((2, 1)), 7, 5, 2, 0.2, 0.05, 1, 1.0, 0.5, v, 10.0, 1e-3)],
    'jumpDriftDamage': [lambda v: B.cycleJumpPlan(np.zeros((3, 1)), np.zeros((2, 1)), 7, 5, 2, 0.2, 0.05, 1, 1.0, 0.5, 2.0, 10.0,
                                                  v)],
}


def probes(name):
    """Values at and next to the ends of the range, 0, -1, 0.5, a large value and NaN."""
    lower, upper, *_, integer, _, _ = EXPECTED[name]
    if integer:
        return [-1, 0, 1, 2 ** 62, 2 ** 63 - 1, 2 ** 63, 2 ** 64 - 1]
    ends = [x for x in (lower, upper) if math.isfinite(x)]
    near = [np.nextafter(x, d) for x in ends for d in (-INF, INF)]
    return sorted(set(ends + near + [0.0, -1.0, 0.5, 2.0, 1e300])) + [math.nan]


def accepts(call, v):
    try:
        call(v)
        return True
    except ValueError:
        return False


@pytest.mark.parametrize('name', sorted(EXPECTED))
def test_python_and_the_binding_refuse_the_same_values(name):
    for v in probes(name):
        python = True
        try:
            validate('E', TABLE, name, v)
        except ParamError:
            python = False
        for call in ENTRIES[name]:
            assert accepts(call, v) == python, (name, v, python)


@pytest.mark.parametrize('name,argument,value', [
    ('ft0', 'ft0', 0.0), ('m', 'm', 3.5), ('rMin', 'rMin', -1.0), ('seed', 'seed', 2 ** 63),
    ('weibullModulus', 'modulus', 0.5), ('fatigueExponent', 'exponent', 0.5), ('fatigueEndurance', 'endurance', 1.0),
    ('fatigueHysteresis', 'hysteresis', 0.7), ('strength', 'strength', -1.0), ('jumpWindow', 'window', 1),
    ('jumpSteady', 'steady', 0.0), ('jumpMaxDamage', 'maxDamage', 1.0), ('jumpMargin', 'margin', -1),
    ('jumpGrowth', 'growth', 0.0), ('jumpDriftNoise', 'driftNoise', -1.0), ('jumpDriftDamage', 'driftDamage', 1.0)])
def test_both_say_the_same_words(name, argument, value):
    words = EXPECTED[name][-1]
    with pytest.raises(ParamError) as e:
        validate('E', TABLE, name, value)
    assert 'expected %s [' % words in str(e.value)
    for call in ENTRIES[name]:
        with pytest.raises(ValueError) as e:
            call(value)
        assert str(e.value).startswith('%s: expected %s, got ' % (argument, words)), str(e.value)


def test_a_range_check_refuses_what_is_not_a_number_and_keeps_the_type():
    check, words = params.coreRange('seed')
    assert check(7.0) == 7 and type(check(7.0)) is int
    for bad in (True, 'x', 7.5, None):
        with pytest.raises((TypeError, ValueError)):
            check(bad)
    check, _ = params.coreRange('weibullModulus')
    assert check(0) == 0.0 and type(check(0)) is float
