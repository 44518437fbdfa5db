"""ballast.oedometer.parameters: the experiment's declarations (readable without YADE), the checks
between parameters, and the packing key."""
import subprocess

import pytest

from ballast.oedometer import parameters
from ballast.oedometer.parameters import PACKING_KEYS, PARAMS, check, packingKey
from ballast.engineparams import CRUSH
from ballast.params import ParamError


def test_defaults_are_the_declared_ones():
    p = check({})
    assert p == {k: d.default for k, d in PARAMS.items()}
    assert p['diameter'] == 0.3 and p['height'] == 0.15 and p['Fmax'] == 1.5e6  # section 4


def test_every_parameter_has_unit_doc_and_range():
    for name, d in PARAMS.items():
        assert d.unit and d.doc and d.allowed, name


def test_engine_parameters_are_the_engines_declarations():
    for name in ('m', 'pattern'):
        assert PARAMS[name] is CRUSH[name]
    assert PARAMS['ft0'].check is CRUSH['ft0'].check and PARAMS['ft0'].unit == CRUSH['ft0'].unit


@pytest.mark.parametrize('values,name', [
    ({'dMin': 0.05}, 'dMin'),                 # dMin >= dMax
    ({'dMax': 0.2}, 'dMax'),                  # dMax >= diameter / 2
    ({'height': 0.04}, 'dMax'),               # dMax >= height
    ({'rMin': 0.05}, 'rMin'),                 # rMin > dMax / 2
    ({'prepYoung': 1e12}, 'prepYoung'),       # prepYoung > young
    ({'f': -1}, 'f'), ({'gamma': 1.2}, 'gamma'), ({'pattern': 5}, 'pattern'), ({'F': 2}, 'F'), ({'f': '2'}, 'f'),
    ({'law': 'hooke'}, 'law'), ({'loadMode': 'press'}, 'loadMode'),
    # issue 15's audit: values that passed the checks and failed minutes later, or never ended
    ({'seed': 1e30}, 'seed'), ({'seed': 2 ** 31}, 'seed'),  # YADE's makeCloud takes a C int
    ({'f': 1e-300}, 'f'), ({'f': 0.01, 'cycles': 100}, 'f'),  # more than 1e9 time steps
    ({'f': 1e5}, 'f'),                                        # fewer than 100 time steps a cycle
    ({'Fmax': 1e300}, 'Fmax'), ({'Fmax': 2e7}, 'Fmax'),       # a single-contact overlap above 25 % of r
    ({'gamma': 1e-300}, 'gamma'), ({'m': 1e5}, 'm'), ({'fatigueExponent': 0.5}, 'fatigueExponent'),
])
def test_bad_values_name_the_parameter(values, name):
    with pytest.raises(ParamError) as e:
        check(values)
    assert e.value.name == name
    assert str(e.value).startswith('Oedometer: ') and name in str(e.value)


def test_text_values_as_from_a_command_line():
    p = check({'f': '2', 'pattern': 'planar4', 'crush': '0', 'seed': '3', 'results': '007'}, text=True)
    assert p['f'] == 2.0 and p['pattern'] == 'planar4' and p['crush'] is False and p['seed'] == 3
    assert p['results'] == '007'


def test_packing_key_depends_on_packing_parameters_only():
    a, b = check({}), check({'f': 2, 'ft0': 1e6})
    assert packingKey(a) == packingKey(b)
    c = check({'seed': 2})
    assert packingKey(c)[1] != packingKey(a)[1] and packingKey(c)[1].startswith('packing-seed2-')
    assert set(packingKey(a)[0]) == set(PACKING_KEYS) | {'version'}
    assert packingKey(a)[0]['version'] == parameters.PACKING_VERSION


def test_readable_without_yade():
    code = ('import sys, ballast, ballast.oedometer.parameters as p; p.check({}); '
            'print(any(m == "yade" or m.startswith("yade.") for m in sys.modules))')
    out = subprocess.run(['/usr/bin/python3', '-c', code], capture_output=True, text=True, cwd='/')
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == 'False'


def test_run_bounds_by_hand():
    """The bounds' numbers at the paper's values: dt = 0.8 x 0.01025 m x sqrt(2600 / 3e11) = 7.634e-7 s, so
    one cycle at 8 Hz is 1.637e5 steps; Fmax = 1.5 MN through one steel contact of the smallest grain:
    linear kn = 2 E r Es r / (E r + Es r) = 5.591e9 N/m, u = 2.683e-4 m = 2.6 % of r; Hertz E* =
    1 / (0.91 / 3e11 + 0.9375 / 3e12) = 2.989e11 Pa, kno = 4/3 E* sqrt(r/2) = 2.853e10, u = (F / kno)^(2/3)
    = 1.404e-3 m = 13.7 % of r: both below the 25 % allowed, 2e7 N is not (linear: 35 %)."""
    p = check({})
    assert p.startTimeStep() == pytest.approx(0.8 * 0.01025 * (2600 / 3e11) ** 0.5, rel=1e-12)
    assert 1 / 8 / p.startTimeStep() == pytest.approx(1.637e5, rel=1e-3)
    kn = 2 * 3e11 * 0.01025 * 3e12 * 0.01025 / (3e11 * 0.01025 + 3e12 * 0.01025)
    assert p.singleContactOverlap(1.5e6) == pytest.approx(1.5e6 / kn, rel=1e-12)
    assert p.singleContactOverlap(1.5e6) / 0.01025 == pytest.approx(0.02617, rel=1e-3)
    estar = 1 / ((1 - 0.3 ** 2) / 3e11 + (1 - 0.25 ** 2) / 3e12)
    ph = check({'law': 'hertz'})
    assert ph.singleContactOverlap(1.5e6) == pytest.approx((1.5e6 / (4 / 3 * estar * (0.01025 / 2) ** 0.5)) ** (2 / 3),
                                                           rel=1e-12)
    assert ph.singleContactOverlap(1.5e6) / 0.01025 == pytest.approx(0.1369, rel=1e-3)


def test_parameters_are_frozen_and_give_the_derived_values():
    """One checked value: frozen, read as p.f or p['f']; derived values by hand: T = 1/f, the peak of eq. 8 at
    T/2, Fmax/2 first at T/4, the crushing period Tc as a YADE period (every step for Tc = 0)."""
    p = check({'f': 4, 'Tc': 2.5e-3})
    assert p.f == p['f'] == 4.0 and p.T == 0.25 and p.peakTime() == 0.125 and p.halfLoadTime() == 0.0625
    assert p.crushPeriod() == {'virtPeriod': 2.5e-3} and check({'Tc': 0}).crushPeriod() == {'iterPeriod': 1}
    with pytest.raises(AttributeError, match='frozen'):
        p.f = 8
    assert check(p) is p                                  # checked once: a checked set is taken as it is
    q = p.replace(f=2)
    assert q.T == 0.5 and p.T == 0.25                     # a new value is a new, checked object
    with pytest.raises(ParamError, match='f = -1'):
        p.replace(f=-1)


@pytest.mark.parametrize('values,name,words', [
    ({'Tc': '1'}, 'Tc', 'longer than the load cycle'), ({'f': '8', 'Tc': '0.2'}, 'Tc', 'longer than the load cycle'),
    ({'vtk': '-1'}, 'vtk', 'a finite number >= 0'), ({'saveEvery': '-0.2'}, 'saveEvery', 'load cycles, in every experiment (the oedometer\'s were seconds'),
    ({'abrasionPeriod': '10000000'}, 'abrasionPeriod', 'longer than the load cycle'),
    ({'crush': 'yes'}, 'crush', 'expected 0 or 1'), ({'fatigue': 'True'}, 'fatigue', 'expected 0 or 1'),
    ({'seed': '0x10'}, 'seed', 'decimal'), ({'f': '1_000'}, 'f', 'decimal'), ({'seed': '0o17'}, 'seed', 'decimal')])
def test_what_cannot_make_sense_is_refused(values, name, words):
    """The audit: --Tc 1, --f 8 --Tc 0.2 ran without a check in the cycle; --crush yes, --seed 0x10, --f 1_000 were read."""
    with pytest.raises(ParamError) as e:
        check(values, text=True)
    assert e.value.name == name and words in str(e.value)


def test_periods_within_their_bounds_are_taken():
    p = check({'f': '8', 'Tc': '0.125', 'cycles': '3', 'saveEvery': '0.3', 'vtk': '0.375', 'crush': '0', 'seed': '16'},
              text=True)
    assert (p['Tc'], p['saveEvery'], p['crush'], p['seed']) == (0.125, 0.3, False, 16)
