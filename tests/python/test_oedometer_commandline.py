"""ballast.oedometer.commandline (scripts/oedometer.py): names it does not know and bad values stop it
with exit status 2 and a message naming them, before any work; --help lists the parameters; a
yade-batch table row sets them."""
import os
import shutil
import subprocess

import pytest

pytest.importorskip('yade')
from ballast.oedometer import commandline  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPT = os.path.join(ROOT, 'scripts', 'oedometer.py')
ENV = dict(os.environ, OMP_NUM_THREADS='1')
ENV.pop('YADE_BATCH', None)


def yade(args, env=ENV, cwd=None):
    return subprocess.run([shutil.which('yade'), '-n', '-x', SCRIPT] + [str(a) for a in args], env=env, cwd=cwd,
                          capture_output=True, text=True, timeout=120)


@pytest.mark.parametrize('argv,named', [(['--F', '2'], '--F'), (['--Fm', '2'], '--Fm'), (['--frequency', '2'], '--frequency')])
def test_abbreviations_and_unknown_names_exit_2(argv, named, capsys):
    with pytest.raises(SystemExit) as e:
        commandline.readParams(argv)
    assert e.value.code == 2
    assert named in capsys.readouterr().err


def test_values_from_the_command_line_are_checked():
    p = commandline.readParams(['--f', '2', '--pattern', '14', '--crush', '0'])
    assert p['f'] == 2.0 and p['pattern'] == 14 and p['crush'] is False


def test_script_refuses_abbreviation_before_any_work(tmp_path):
    p = yade(['--F', '2', '--results', tmp_path / 'r'])
    assert p.returncode == 2
    assert 'oedometer.py: unknown option --F: ' in p.stderr and 'did you mean --f' in p.stderr
    assert not (tmp_path / 'r').exists()


@pytest.mark.parametrize('args,name', [(['--f', '-1'], 'f'), (['--pattern', '5'], 'pattern'), (['--rMin', '0.05'], 'rMin'),
                                       (['--ft0', 'abc'], 'ft0'), (['--gamma', '1.2'], 'gamma')])
def test_bad_value_exits_2_naming_it(args, name, tmp_path):
    p = yade(args + ['--results', tmp_path / 'r'])
    assert p.returncode == 2, p.stderr[-2000:]
    assert ('bad parameter %s: Oedometer: %s = ' % (name, name)) in p.stderr
    assert not (tmp_path / 'r').exists()


def test_help_lists_parameters_with_units():
    p = yade(['--help'])
    assert p.returncode == 0
    for name in ('--f ', '--pattern', '--ft0', '--rMin', '--Tc', '--strength', '--gamma', '--seed', '--saveEvery'):
        assert name in p.stdout, name
    text = ' '.join(p.stdout.split())  # argparse wraps the lines
    assert 'f_t = ft0 / r^m [Pa m^m]' in text and 'loading frequency of eq. 8' in text and '[Hz]' in text


@pytest.mark.parametrize('table,message', [
    ('seed pattern\n1 planar5\n', 'bad parameter pattern:'),                                # a bad cell
    ('seed Fm\n1 2\n', 'bad parameter Fm: Oedometer: Fm is not a parameter'),               # an unknown column
])
def test_bad_table_is_named_before_any_work(table, message, tmp_path):
    path = tmp_path / 'bad.table'
    path.write_text(table)
    p = yade(['--results', tmp_path / 'r'], env=dict(ENV, YADE_BATCH='%s:2' % path))
    assert p.returncode == 2
    assert message in p.stderr
    assert not (tmp_path / 'r').exists()


@pytest.mark.parametrize('args,name,words', [
    (['--seed', '1e30'], 'seed', '[0, 2^31 - 1]'),
    (['--f', '1e-300'], 'f', 'more than the 1e+09'),
    (['--Fmax', '1e300'], 'Fmax', 'outside rigid-sphere DEM'),
    (['--Fmax', '-1e6'], 'Fmax', 'a finite number > 0'),     # a negative value is a value, not an option
    (['--Fmin', '-5'], 'Fmin', 'a finite number >= 0'),
    (['--results', '/dev/null/x'], 'results', 'can be created and written to'),
    (['--packingDir', 'FILE'], 'packingDir', 'can be created and written to'),  # a regular file
])
def test_audit_cases_exit_2_before_any_work(args, name, words, tmp_path, capsys):
    """Issue 15: each failed minutes later or never ended; now exit status 2, one line naming the parameter,
    the value and what is allowed, before anything is built (checked in this process: main() exits
    before the preparation)."""
    from ballast.oedometer.commandline import main
    plain = tmp_path / 'plain-file'
    plain.write_text('not a folder')
    args = [str(plain) if a == 'FILE' else a for a in args]
    with pytest.raises(SystemExit) as e:
        main(args + ['--results', str(tmp_path / 'r')] if name != 'results' else args)
    assert e.value.code == 2
    err = capsys.readouterr().err
    assert err.startswith('oedometer.py: bad parameter %s: Oedometer: %s = ' % (name, name)), err
    assert words in err and err.count('\n') == 1
    assert not (tmp_path / 'r' / 'packings').exists() or name == 'packingDir'


@pytest.mark.parametrize('argv,words', [(['--F', '2'], 'unknown option --F: the options are the parameters of --help'),
                                        (['--foo', '1'], 'unknown option --foo'),
                                        (['--f'], 'option --f needs a value: a finite number > 0 [Hz]'),
                                        (['--f', '1', '--f', '2'], 'option --f given twice (1 and 2)')])
def test_argparse_errors_are_one_line_naming_the_option(argv, words, capsys):
    with pytest.raises(SystemExit) as e:
        commandline.readParams(argv)
    err = capsys.readouterr().err
    assert e.value.code == 2 and words in err and err.count('\n') == 1, err
