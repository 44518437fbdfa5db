"""ballast.experiments.commandline, the one command line of every experiment (oedometer, box, single_particle, triaxial:
scripts/oedometer.py, box_test.py, single_particle.py, triaxial.py): text is read strictly (a flag is 0 or 1, numbers in
decimal only), a repeated option, an abbreviation, an unknown name and a bad value are refused with exit status 2
and one line naming the option, the value and what is allowed, before any work; --help lists the parameters;
a yade-batch row sets them, and a study table's cells are read by the same reader. Most cases in this process
through each experiment's parser and readParams (no YADE); one real yade run per experiment."""
import importlib
import os
import shutil
import subprocess

import pytest

from ballast import experiments
from ballast.params import flag
from ballast.study.options import StudyError
from ballast.tables import Table

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ENV = dict(os.environ, OMP_NUM_THREADS='1')
ENV.pop('YADE_BATCH', None)
DECIMAL = 'written in decimal (hexadecimal, octal, binary, complex and 1_000 forms are refused)'

# per experiment: its script, its owner in messages, and an option of each kind with its allowed range in words
EXPERIMENTS = {
    'oedometer': dict(script='oedometer.py', owner='Oedometer', flag='crush', integer='cycles', integerWords='an integer >= 1 [-]',
                      number='f', numberWords='a finite number > 0 [Hz]', abbreviation='--Fma', full='--Fmax'),
    'box': dict(script='box_test.py', owner='BoxTest', flag='tilt', integer='cycles', integerWords='an integer >= 1 [-]',
                number='f', numberWords='a finite number > 0 [Hz]', abbreviation='--peak', full='--peakLoad'),
    'single_particle': dict(script='single_particle.py', owner='SingleParticle', flag=None, integer='n',
                            integerWords='an integer in [1, 10000] [-]', number='speed', numberWords='a number > 0 [m/s]',
                            abbreviation='--maxStr', full='--maxStrain'),
    'triaxial': dict(script='triaxial.py', owner='TriaxialTest', flag='reuseSpecimen', integer='cycles',
                     integerWords='an integer >= 1 [-]', number='f', numberWords='a finite number > 0 [Hz]',
                     abbreviation='--conf', full='--confining'),
}
NAMES = sorted(EXPERIMENTS)


def commandline(name):
    return importlib.import_module('ballast.experiments.%s.commandline' % name)


def refusal(name, argv, capsys):
    """The exit status and the stderr of a command line read in this process."""
    with pytest.raises(SystemExit) as e:
        commandline(name).readParams([str(a) for a in argv])
    return e.value.code, capsys.readouterr().err


def badValue(name, option, value, expected):
    """The one line refusing `value` of `option`."""
    x = EXPERIMENTS[name]
    return "%s: bad parameter %s: %s: %s = %r is not allowed: expected %s\n" % (x['script'], option, x['owner'], option,
                                                                                value, expected)


def test_the_table_covers_every_experiment_and_every_flag():
    """Each experiment is tested, and a flag case for every experiment that declares one (the single-particle
    test declares none: the flag case is read by the same reader, ballast.params.flag)."""
    assert sorted(experiments.names()) == NAMES
    for name in NAMES:
        flags = [k for k, p in experiments.declaration(name).params.items() if p.parse is flag]
        assert (EXPERIMENTS[name]['flag'] in flags) if flags else EXPERIMENTS[name]['flag'] is None, name


@pytest.mark.parametrize('name', [n for n in NAMES if EXPERIMENTS[n]['flag']])
@pytest.mark.parametrize('value', ['yes', 'True', 'on', '2'])
def test_a_flag_is_0_or_1(name, value, capsys):
    option = EXPERIMENTS[name]['flag']
    assert refusal(name, ['--' + option, value], capsys) == (2, badValue(name, option, value, '0 or 1'))


@pytest.mark.parametrize('name', NAMES)
@pytest.mark.parametrize('value', ['0x10', '0o7', '0b1', '1_000', '1j'])
def test_an_integer_is_decimal(name, value, capsys):
    x = EXPERIMENTS[name]
    assert refusal(name, ['--' + x['integer'], value], capsys) == (
        2, badValue(name, x['integer'], value, '%s, %s' % (x['integerWords'], DECIMAL)))


@pytest.mark.parametrize('name', NAMES)
@pytest.mark.parametrize('value', ['1_000', '0x10', '2.5j'])
def test_a_number_is_decimal(name, value, capsys):
    x = EXPERIMENTS[name]
    assert refusal(name, ['--' + x['number'], value], capsys) == (
        2, badValue(name, x['number'], value, '%s, %s' % (x['numberWords'], DECIMAL)))


@pytest.mark.parametrize('name', NAMES)
def test_a_repeated_option_is_refused(name, capsys):
    """argparse would keep the last silently, also when one is written --seed=3."""
    assert refusal(name, ['--seed', '2', '--seed=3'], capsys) == (
        2, '%s: option --seed given twice (2 and 3): give it once\n' % EXPERIMENTS[name]['script'])


@pytest.mark.parametrize('name', NAMES)
@pytest.mark.parametrize('spelling', ['%s 2', '%s=2'])
def test_an_abbreviation_is_refused(name, spelling, capsys):
    x = EXPERIMENTS[name]
    code, err = refusal(name, (spelling % x['abbreviation']).split(), capsys)
    assert code == 2 and err.count('\n') == 1
    assert err.startswith('%s: unknown option %s: the options are the parameters of --help (names in full); did you '
                          'mean %s' % (x['script'], x['abbreviation'], x['full'])), err


@pytest.mark.parametrize('argv,named', [(['--F', '2'], '--F'), (['--Fm', '2'], '--Fm'), (['--frequency', '2'], '--frequency')])
def test_oedometer_abbreviations_and_unknown_names_exit_2(argv, named, capsys):
    code, err = refusal('oedometer', argv, capsys)
    assert code == 2 and named in err


@pytest.mark.parametrize('name', NAMES)
def test_argparse_errors_are_one_line_naming_the_option(name, capsys):
    x = EXPERIMENTS[name]
    number = '--' + x['number']
    for argv, words in [(['--F', '2'], 'unknown option --F: the options are the parameters of --help'),
                        (['--foo', '1'], 'unknown option --foo'),
                        ([number], 'option %s needs a value: %s' % (number, x['numberWords'])),
                        ([number, '1', number, '2'], 'option %s given twice (1 and 2)' % number)]:
        code, err = refusal(name, argv, capsys)
        assert code == 2 and err.startswith(x['script'] + ': ') and words in err and err.count('\n') == 1, (argv, err)


@pytest.mark.parametrize('name,argv,expected', [
    ('oedometer', ['--f', '2', '--pattern', '14', '--crush', '0', '--seed', '16'],
     dict(f=2.0, pattern=14, crush=False, seed=16)),
    ('box', ['--cycles', '3', '--tilt', '0', '--f', '2', '--peakLoad', '3e4', '--fatigue', "'1'"],
     dict(cycles=3, tilt=False, f=2.0, peakLoad=3e4, fatigue=True)),
    ('single_particle', ['--diameters', '[0.025, 0.04]', '--pattern', 'planar4', '--speed', '0.02', '--Tc', '1e-6'],
     dict(diameters=(0.025, 0.04), pattern='planar4', speed=0.02, Tc=1e-6)),
])
def test_values_in_the_spellings_of_help_are_read(name, argv, expected, capsys):
    """Decimal numbers (16, 2, 3e4, 1e-6), flags 0 and 1 (quoted as in a table cell too), lists and names, each
    of the type its check gives; the defaults elsewhere."""
    p = commandline(name).readParams(argv)
    for k, v in expected.items():
        assert p[k] == v and type(p[k]) is type(v), k
    default = experiments.declaration(name).params
    assert p['progress'] == default['progress'].default


@pytest.mark.parametrize('name,argv,option,words', [
    ('oedometer', ['--f', '-1'], 'f', "f = '-1' is not allowed: expected a finite number > 0 [Hz]"),
    ('oedometer', ['--pattern', '5'], 'pattern', "pattern = '5' is not allowed"),
    ('oedometer', ['--rMin', '0.05'], 'rMin', 'larger than the largest grain radius dMax/2 = 0.02225'),
    ('oedometer', ['--ft0', 'abc'], 'ft0', "ft0 = 'abc' is not allowed"),
    ('oedometer', ['--gamma', '1.2'], 'gamma', "gamma = '1.2' is not allowed: expected a number in [0.5, 1)"),
    ('box', ['--seatLoad', '5e4'], 'seatLoad', 'seatLoad = 50000.0 is not allowed: must be smaller than peakLoad = 40000 N'),
    ('single_particle', ['--speed', '-1'], 'speed', "speed = '-1' is not allowed: expected a number > 0 [m/s]"),
])
def test_a_bad_value_exits_2_naming_it(name, argv, option, words, capsys):
    code, err = refusal(name, argv, capsys)
    x = EXPERIMENTS[name]
    assert code == 2 and err.count('\n') == 1
    assert err.startswith('%s: bad parameter %s: %s: %s' % (x['script'], option, x['owner'], option)) and words in err, err


@pytest.mark.parametrize('name,options,words', [
    ('oedometer', ('--f ', '--pattern', '--ft0', '--rMin', '--Tc', '--strength', '--gamma', '--seed', '--saveEvery'),
     ('f_t = ft0 / r^m [Pa m^m]', 'loading frequency of eq. 8', '[Hz]', 'Numbers are written in decimal')),
    ('box', ('--loadFile', '--sleeperMass', '--tilt'), ('[kg]',)),
    ('single_particle', ('--diameters', '--maxStrain'), ('[m/s]',)),
])
def test_help_lists_the_parameters_with_units(name, options, words, capsys):
    with pytest.raises(SystemExit) as e:
        commandline(name).readParams(['--help'])
    out = capsys.readouterr().out
    assert e.value.code == 0
    for option in options:
        assert option in out, option
    text = ' '.join(out.split())  # argparse wraps the lines
    for w in words:
        assert w in text, w


@pytest.mark.parametrize('table,message', [
    ('seed pattern\n1 planar5\n', 'bad parameter pattern:'),                    # a cell YADE cannot read
    ('seed Fm\n1 2\n', 'bad parameter Fm: Oedometer: Fm is not a parameter'),   # an unknown column
])
def test_a_bad_yade_batch_row_is_named_before_any_work(table, message, tmp_path, monkeypatch, capsys):
    path = tmp_path / 'bad.table'
    path.write_text(table)
    monkeypatch.setenv('YADE_BATCH', '%s:2' % path)
    code, err = refusal('oedometer', ['--results', tmp_path / 'r'], capsys)
    assert code == 2 and message in err and err.count('\n') == 1
    assert not (tmp_path / 'r').exists()


@pytest.mark.parametrize('name', NAMES)
def test_a_table_cell_is_read_as_strictly(name):
    """A study table's cells go through the same reader: 0x10 and True are refused, naming line and column."""
    x = EXPERIMENTS[name]
    good = Table('t.table', 'description %s\nok 3\n' % x['integer']).check(experiments.declaration(name))
    assert good[2][x['integer']] == 3
    for cell in ('0x10', '1_000'):
        with pytest.raises(StudyError) as e:
            Table('t.table', 'description %s\nbad %s\n' % (x['integer'], cell)).check(experiments.declaration(name))
        assert 't.table:2: column %s, value %s: %s: %s = %r is not allowed' % (
            x['integer'], cell, x['owner'], x['integer'], cell) in str(e.value) and DECIMAL in str(e.value)
    if x['flag']:
        with pytest.raises(StudyError, match="column %s, value True: .*expected 0 or 1" % x['flag']):
            Table('t.table', 'description %s\nbad True\n' % x['flag']).check(experiments.declaration(name))


# ---------------------------------------------------------------- in YADE
@pytest.mark.skipif(shutil.which('yade') is None, reason='needs yade')
@pytest.mark.parametrize('name,argv,line', [
    ('oedometer', ['--cycles', '0x10'], badValue('oedometer', 'cycles', '0x10', 'an integer >= 1 [-], ' + DECIMAL)),
    ('box', ['--tilt', 'yes'], badValue('box', 'tilt', 'yes', '0 or 1')),
    ('single_particle', ['--speed', '1_000'], badValue('single_particle', 'speed', '1_000', 'a number > 0 [m/s], ' + DECIMAL)),
])
def test_the_script_in_yade_refuses_before_any_work(name, argv, line, tmp_path):
    script = os.path.join(ROOT, 'scripts', EXPERIMENTS[name]['script'])
    p = subprocess.run([shutil.which('yade'), '-n', '-x', script] + argv + ['--results', str(tmp_path / 'r')], env=ENV,
                       cwd=str(tmp_path), capture_output=True, text=True, timeout=300)
    assert p.returncode == 2, p.stdout[-2000:] + p.stderr[-2000:]
    ours = [s for s in p.stderr.splitlines(True) if s.startswith(EXPERIMENTS[name]['script'] + ':')]
    assert ours == [line], p.stderr[-2000:]
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
def test_oedometer_audit_cases_exit_2_before_any_work(args, name, words, tmp_path, capsys):
    """Issue 15: each failed minutes later or never ended; now exit status 2, one line naming the parameter,
    the value and what is allowed, before anything is built (checked in this process: main() exits
    before the preparation; the outputs' folders are checked by the experiment, which needs YADE)."""
    pytest.importorskip('yade')
    from ballast.experiments.oedometer.commandline import main
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
