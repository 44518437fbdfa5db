"""Tests of ballast.study.options: the runner's options, checked in one place for the command line
(argparse) and the library, each error naming the flag, the value and what is allowed."""
import argparse

import pytest

from ballast.experiments import Declaration, declaration
from ballast.study.options import OPTIONS, StudyError, argument, experimentDeclaration, flag, optionValue


def test_the_experiment_is_a_name_a_declaration_or_the_oedometer():
    oedometer = declaration('oedometer')
    assert experimentDeclaration() is oedometer and experimentDeclaration('oedometer') is oedometer
    other = Declaration('other', {}, lambda v, text=False: v, 'x.py', {'results': 'r', 'runId': 'i', 'sampleStore': None})
    assert experimentDeclaration(other) is other and other.studySets() == ('r', 'i')
    with pytest.raises(StudyError, match="--experiment: experiment = 'sleeper' is not allowed: expected one of .*oedometer"):
        experimentDeclaration('sleeper')


def test_values_are_checked_against_their_declaration():
    assert optionValue('timeout', '2.5', text=True) == 2.5 and optionValue('jobs', 3) == 3 and optionValue('timeout', None) is None
    for name, bad, allowed in [('jobs', '0', 'an integer >= 1'), ('jobs', 1.5, 'an integer >= 1'), ('timeout', '-5', '> 0'),
                               ('progress', 'x', '> 0'), ('connectTimeout', 0, '> 0'), ('nice', 20, '-20 to 19')]:
        with pytest.raises(StudyError) as e:
            optionValue(name, bad, text=isinstance(bad, str))
        assert str(e.value).startswith(flag(name) + ': ') and repr(bad) in str(e.value) and allowed in str(e.value)
    assert flag('connectTimeout') == '--connect-timeout'
    with pytest.raises(StudyError, match="--timeout: study: timeout = '5' is not allowed"):
        optionValue('timeout', '5')  # from Python, a number is a number: text only from the command line


def test_lines_in_yade_batch_format():
    assert optionValue('lines', '2,3-4,2') == [2, 3, 4] and optionValue('lines', [5, 3]) == [3, 5]
    for bad in ('2-x', '2,,3', '0-2'):
        with pytest.raises(StudyError, match="--lines: study: lines = '%s' is not allowed: expected a list like 2,3-5,8" % bad):
            optionValue('lines', bad, text=True)


def test_argparse_reports_a_bad_value_naming_the_option(capsys):
    ap = argparse.ArgumentParser(prog='p')
    ap.add_argument('--timeout', **argument('timeout'))
    ap.add_argument('--nice', **argument('nice'))
    assert ap.parse_args([]).nice == OPTIONS['nice'].default and ap.parse_args(['--timeout', '3']).timeout == 3
    with pytest.raises(SystemExit) as e:
        ap.parse_args(['--timeout', '-5'])
    assert e.value.code == 2
    err = capsys.readouterr().err
    assert 'argument --timeout' in err and "'-5'" in err and 'a finite number > 0' in err
    assert '[s]' in ap.format_help() and 'default 10' in ap.format_help()  # unit, range and default in --help
