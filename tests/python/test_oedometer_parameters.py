"""ballast.oedometer.parameters: the experiment's declarations (readable without YADE), the checks
between parameters, and the packing key."""
import subprocess

import pytest

from ballast.oedometer import parameters
from ballast.oedometer.parameters import PACKING_KEYS, PARAMS, check, packingKey
from ballast.params import CRUSH, ParamError


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
