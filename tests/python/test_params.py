"""ballast.params: the one parameter system (declarations, text -> value, checks, error messages)."""
import math

import pytest

from ballast import params
from ballast.engineparams import ABRASION, CRUSH
from ballast.params import Param, ParamError, validate, validateAll

TABLE = {
    'x': Param(1.0, 'm', 'a length', params.positive, 'a finite number > 0'),
    'n': Param(3, '-', 'a count', params.positiveInt, 'an integer >= 1'),
    'on': Param(True, '-', 'a switch', params.boolean, '0 or 1', params.flag),
    'name': Param('a', 'path', 'a path', params.anyText, 'a path', params.text),
    'need': Param(None, 'Pa', 'required', params.positive, 'a finite number > 0'),
}


@pytest.mark.parametrize('raw,value', [('2.5', 2.5), ('1e6', 1e6), (' 7 ', 7.0), (4, 4.0)])
def test_numbers_from_text_and_values(raw, value):
    assert validate('T', TABLE, 'x', raw, text=True) == value


@pytest.mark.parametrize('raw', ['0', '-1', 'abc', 'nan', 'inf', True, None, '[1]'])
def test_bad_numbers_name_owner_parameter_value_and_range(raw):
    with pytest.raises(ParamError) as e:
        validate('T', TABLE, 'x', raw, text=True)
    assert e.value.name == 'x'
    assert str(e.value).startswith('T: x = %r is not allowed: expected a finite number > 0 [m]' % (raw,))


@pytest.mark.parametrize('raw,value', [('3', 3), (3.0, 3), ('12', 12)])
def test_integers(raw, value):
    v = validate('T', TABLE, 'n', raw, text=True)
    assert v == value and isinstance(v, int)


@pytest.mark.parametrize('raw', ['2.5', '0', 2.5, False])
def test_bad_integers(raw):
    with pytest.raises(ParamError, match='n = '):
        validate('T', TABLE, 'n', raw, text=True)


@pytest.mark.parametrize('raw,value', [('1', True), ('0', False), (" '1' ", True), (False, False)])
def test_flags(raw, value):
    assert validate('T', TABLE, 'on', raw, text=True) is value


@pytest.mark.parametrize('raw', ['maybe', '2', 'yes', 'off', 'True', '1.0'])
def test_a_flag_is_0_or_1(raw):
    """Text is read in the spelling --help gives: other words for a flag are refused, saying what is read."""
    with pytest.raises(ParamError) as e:
        validate('T', TABLE, 'on', raw, text=True)
    assert str(e.value) == "T: on = %r is not allowed: expected 0 or 1" % raw


@pytest.mark.parametrize('raw', ['0x10', '0X1f', '0o7', '0b1', '1_000', '1j', '2.5J', '-0x10', '[0x10]'])
def test_numbers_are_decimal_only(raw):
    with pytest.raises(ParamError) as e:
        validate('T', TABLE, 'x', raw, text=True)
    assert str(e.value) == ("T: x = %r is not allowed: expected a finite number > 0 [m], written in decimal (hexadecimal, "
                            "octal, binary, complex and 1_000 forms are refused)" % raw)


@pytest.mark.parametrize('raw,value', [('16', 16), ('1e1', 10), ('0', None), ('007', None)])
def test_decimal_integers(raw, value):
    """'0' is read and refused by the range (n >= 1); '007' is no Python number and stays text, refused as one."""
    if value is None:
        with pytest.raises(ParamError, match=r"expected an integer >= 1 \[-\]$"):
            validate('T', TABLE, 'n', raw, text=True)
    else:
        assert validate('T', TABLE, 'n', raw, text=True) == value


def test_text_of_a_path_is_not_read_as_a_number():
    """'0x10' is a name a path may have: only numbers are read strictly."""
    assert validate('T', TABLE, 'name', '0x10', text=True) == '0x10'


@pytest.mark.parametrize('name,raw', [('x', '2.5'), ('on', 1), ('on', 'yes'), ('n', '3')])
def test_python_values_are_not_parsed(name, raw):
    with pytest.raises(ParamError, match='%s = %r' % (name, raw)):
        validate('T', TABLE, name, raw)


def test_text_keeps_digits_and_drops_quotes():
    assert validate('T', TABLE, 'name', '123', text=True) == '123'
    assert validate('T', TABLE, 'name', "'res ults'", text=True) == 'res ults'


def test_validate_all_defaults_unknown_and_required():
    v = validateAll('T', TABLE, {'need': '5', 'n': 2}, text=True)
    assert v == {'x': 1.0, 'n': 2, 'on': True, 'name': 'a', 'need': 5.0}
    with pytest.raises(ParamError, match='unknown parameter.*bogus') as e:
        validateAll('T', TABLE, {'need': 1, 'bogus': 2})
    assert e.value.name == 'bogus'
    with pytest.raises(ParamError, match='need required') as e:
        validateAll('T', TABLE, {})
    assert e.value.name == 'need'


@pytest.mark.parametrize('raw,value', [(4, 4), ('6', 6), ('14', 14), ('planar4', 'planar4'), ("'octa6'", 'octa6')])
def test_patterns_are_the_cores_list(raw, value):
    assert validate('E', CRUSH, 'pattern', raw, text=True) == value


@pytest.mark.parametrize('raw', [5, 'planar5', 4.0, True])
def test_unknown_pattern(raw):
    with pytest.raises(ParamError, match='pattern'):
        validate('E', CRUSH, 'pattern', raw)


def test_with_default_keeps_unit_range_and_check():
    p = CRUSH['ft0'].withDefault(2.5e6)
    assert (p.default, p.unit, p.allowed) == (2.5e6, CRUSH['ft0'].unit, CRUSH['ft0'].allowed)
    assert CRUSH['ft0'].default is None  # the engine's own declaration is unchanged
    with pytest.raises(ParamError):
        validate('E', {'ft0': p}, 'ft0', 0)


def test_gamma_open_interval():
    for bad in (0, 1, 1.2):
        with pytest.raises(ParamError, match='gamma'):
            validate('E', ABRASION, 'gamma', bad)
    assert validate('E', ABRASION, 'gamma', 0.5) == 0.5


def test_between_bounds():
    check = params.between(0, math.pi / 2)
    assert check(0) == 0 and check(1.5) == 1.5
    with pytest.raises(ValueError):
        check(math.pi / 2)
