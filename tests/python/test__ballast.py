"""Tests of the module file pkg/python/_ballast.cpp: it registers the functions of every binding file
(pkg/python/bind_<Header>.cpp, each tested in tests/python/test__ballast_<Header>.py), and bad input comes out
as Python's TypeError or ValueError (the translators of Convert.cpp), never as a RuntimeError."""
import os

import numpy as np
import pytest

import ballast._ballast as B

HERE = os.path.dirname(os.path.abspath(__file__))
BINDING = os.path.join(HERE, '..', '..', 'pkg', 'python')

# The functions each binding file registers.
BY_FILE = {
    'FabricStress': {'fabricStress', 'grainStresses'},
    'VonMises': {'vonMises', 'principalStresses'},
    'HertzPressure': {'hertzPressure', 'effectiveRadius', 'contactModulus', 'hertzPressureFromForce'},
    'Strength': {'sizeStrength'},
    'CrushCriterion': {'criterionNames'},
    'BallastCrushEngine': {'crushCheck'},
    'Weibull': {'weibullFactors'},
    'Fatigue': {'fatigueCheck'},
    'CycleJump': {'cycleJumpPlan'},
    'BallastAbrasionEngine': {'abrasionCheck', 'abrasionBound', 'sphereContactBound'},
    'FragmentPattern': {'fragmentPattern', 'keptVolumeFraction', 'patternName', 'randomRotation', 'placeFragments'},
    'InputCheck': {'parameterRanges'},
    'Types': {'matricesToArray', '_fastMatrixPath'},
    'DensityScaling': {'pWaveStep', 'densityScaling'},
    'InertialNumber': {'inertialNumber'},
    'Membrane': {'membraneLoad'},
    'ClumpStress': {'clumpStresses'},
    'ClumpSplit': {'clumpSplit'},
}


def test_the_module_holds_the_functions_of_every_binding_file():
    public = {k for k in dir(B) if not k.startswith('__')}
    assert public == set().union(*BY_FILE.values())


def test_every_binding_file_binds_a_core_header_and_has_its_test_file():
    files = sorted(f for f in os.listdir(BINDING) if f.startswith('bind_'))
    assert files == sorted('bind_%s.cpp' % h for h in BY_FILE)
    for header in BY_FILE:
        assert os.path.exists(os.path.join(BINDING, '..', header + '.hpp')), header
        assert os.path.exists(os.path.join(HERE, 'test__ballast_%s.py' % header)), header


def test_every_function_is_documented_with_its_arguments():
    assert 'Dubina & Elias' in B.__doc__
    for name in set().union(*BY_FILE.values()):
        assert getattr(B, name).__doc__.lstrip().startswith(name + '('), name


@pytest.mark.parametrize('call,exc', [
    (lambda: B.vonMises('a'), TypeError),                           # Convert.cpp's TypeError
    (lambda: B.vonMises(np.zeros(4)), TypeError),
    (lambda: B.vonMises(np.full((3, 3), np.nan)), ValueError),      # asDoubles: ArgumentError
    (lambda: B.effectiveRadius(0.0, 0.0), ValueError),              # the core's ArgumentError
    (lambda: B.crushCheck(np.zeros((1, 3, 3)), [0.02], 2e5, 1.0, 0.0, 'tresca'), ValueError),
])
def test_errors_are_type_and_value_errors(call, exc):
    with pytest.raises(exc) as e:
        call()
    assert type(e.value) is exc
