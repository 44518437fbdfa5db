"""Tests of ballast.tables against hand-written tables: rows, line numbers, '=' repeats and run
ids as yade-batch gives them (YADE's own TableParamReader reads them), what is refused and how the
refusal names line, column and value; yade-batch's --lines."""
import os
import re
import subprocess
import sys

import pytest

from ballast.experiments import Declaration, declaration
from ballast.params import ParamError
from ballast.study.options import StudyError
from ballast.tables import Table, cellValue, tableRow

OEDOMETER, BOX = declaration('oedometer'), declaration('box')
PARAMS = OEDOMETER.params


def table(text):
    return Table('t.table', text)


def refused(text):
    with pytest.raises(StudyError) as e:
        table(text).check(OEDOMETER)
    return str(e.value)


def test_rows_keep_the_line_numbers_of_the_file_and_equals_repeats():
    t = table('# a comment line\n\nseed f   # columns\n1    0.5\n\n# gap\n2    =\n3    8 # last\n')
    assert [n for n, _ in t.rows] == [4, 7, 8]
    assert t.rows[1][1] == {'seed': '2', 'f': '0.5'}  # '=' repeats the row above
    assert t.columns == ['seed', 'f']
    assert t.runId(7) == 'seed=2,f=0.5'  # no '!' columns: every column


def test_run_ids_from_bang_columns_or_the_description():
    t = table("seed! f! pattern\n1 2 'planar4'\n")
    assert t.columns == ['seed', 'f', 'pattern'] and t.runId(2) == 'seed=1,f=2'
    t = table("description seed pattern\nfirst/try 1 'planar4'\n")
    assert t.runId(2) == 'first_try'  # made a directory name
    assert t.rows[0][1]['pattern'] == "'planar4'"  # cells are text; quotes stay, as yade-batch passes them
    assert table("seed pattern\n1 'planar4'\n").runId(2) == 'seed=1,pattern=planar4'  # quotes dropped, as yade-batch does


def test_the_last_line_needs_no_newline():
    assert table('seed f\n1 25').rows == [(2, {'seed': '1', 'f': '25'})]  # YADE's reader alone would read f=2


@pytest.mark.parametrize('text, words', [
    ('', ['empty']),
    ('# only a comment\nseed f\n', ['no rows', 'line 2']),
    ('seed f\n1 2\n3\n', ['t.table:3', '1 cells', '2 columns']),
    ('seed f\n1 2 3\n', ['t.table:2', '3 cells']),
    ('seed f\n= 2\n', ['t.table:2', "'='", 'seed', 'first row']),
    ('seed f f\n1 2 3\n', ['t.table:1', 'twice']),
    ('seed f! f\n1 2 3\n', ['twice']),
    ('seed! f\n1 2\n1 4\n', ['t.table:3', "'seed=1'", 'line 2', 'description']),  # YADE would make it seed=1__line=3__
    ('description seed\na 1\na 2\n', ['t.table:3', "'a'", 'line 2']),
    ('description seed\na/b 1\na_b 2\n', ['t.table:3', "'a_b'"]),  # the same directory name
])
def test_tables_yade_would_misread_are_refused_naming_the_line(text, words):
    with pytest.raises(StudyError) as e:
        table(text)
    for w in words:
        assert w in str(e.value), (w, str(e.value))


def test_every_cell_is_checked_before_any_run():
    params = table('seed f   Tc\n1 2 0\n2 0.5 1e-4\n').check(OEDOMETER)
    assert params[3]['f'] == 0.5 and params[3]['Tc'] == 1e-4 and params[2]['Fmax'] == PARAMS['Fmax'].default  # defaults filled in
    msg = refused('seed f\n1 2\n2 -1\n3 x\n')
    assert msg.startswith('2 row(s) refused')
    assert 't.table:3: column f, value -1' in msg and 'a finite number > 0 [Hz]' in msg
    assert 't.table:4: column f, value x' in msg
    # a check between parameters, on one the row does not set: the row is named
    msg = refused('seed diameter\n1 0.01\n')
    assert 't.table:2: ' in msg and 'dMax' in msg and 'diameter=0.01' in msg


def test_columns_that_are_not_parameters_are_named():
    msg = refused('seed fq Tcc\n1 2 3\n')
    assert 'fq, Tcc' in msg and 'not parameters' in msg
    assert 'runId' in refused('seed runId\n1 a\n') and 'set by the study' in refused('seed runId\n1 a\n')
    # the description and yade-batch's !COLUMNS are not parameters
    assert table('description seed !OMP_NUM_THREADS\na 1 2\n').check(OEDOMETER)[2]['seed'] == 1


def test_a_cell_star_is_the_default():
    params = table("seed f pattern\n1 * 'planar4'\n2 0.5 *\n").check(OEDOMETER)
    assert params[2]['f'] == PARAMS['f'].default and params[3]['pattern'] == PARAMS['pattern'].default
    assert params[2]['pattern'] == 'planar4' and params[3]['f'] == 0.5


def test_the_columns_are_checked_against_the_experiment_named():
    oedometer = declaration('oedometer')
    # an experiment with two parameters, its own check and no sample store: 'packingDir' is an ordinary column
    small = Declaration('small', {k: PARAMS[k] for k in ('seed', 'packingDir')}, lambda v, text=False: dict(v), 'x.py',
                        {'results': 'out', 'runId': 'name', 'sampleStore': None})
    assert table("seed packingDir\n1 '/tmp/p'\n").check(small) == {2: {'seed': '1', 'packingDir': "'/tmp/p'"}}
    assert 'set by the study' in refused("seed packingDir\n1 '/tmp/p'\n")  # the oedometer's study sets it
    with pytest.raises(StudyError, match='column.s. f are not parameters of the small; parameters: seed, packingDir'):
        table('seed f\n1 2\n').check(small)
    assert table('seed f\n1 2\n').check(oedometer)[2]['f'] == 2


def test_a_run_reads_its_row_with_the_same_reader(tmp_path):
    """tableRow: the cells of one row as a run under yade-batch reads them (YADE_BATCH=table:line), with
    the line numbers, '=' and '*' of the study's reader; no description, no !COLUMNS."""
    path = tmp_path / 't.table'
    path.write_text("# c\ndescription seed f !OMP_NUM_THREADS pattern\nslow 1 0.5 1 'planar4'\nfast 1 = 1 *\n")
    assert tableRow(str(path), 3, OEDOMETER) == {'seed': '1', 'f': '0.5', 'pattern': "'planar4'"}
    assert tableRow(str(path), 4, OEDOMETER) == {'seed': '1', 'f': '0.5'}
    with pytest.raises(StudyError, match=r't.table: line 5 holds no row; rows are on lines 3,4'):
        tableRow(str(path), 5, OEDOMETER)
    path.write_text('seed fq\n1 2\n')
    with pytest.raises(ParamError, match='Oedometer: fq is not a parameter .a column of .*t.table.; parameters: seed, ') as e:
        tableRow(str(path), 2, OEDOMETER)
    assert e.value.name == 'fq'
    path.write_text('seed f\n1 2)\n')
    with pytest.raises(ParamError, match=r"Oedometer: cannot read f = '2\)' from .*t.table:2") as e:
        tableRow(str(path), 2, OEDOMETER)
    assert e.value.name == 'f'
    # two rows with one run id: refused by a study, not by a run of one row (yade-batch runs both)
    path.write_text('seed! f\n1 2\n1 4\n')
    assert tableRow(str(path), 3, OEDOMETER) == {'seed': '1', 'f': '4'}


def test_cell_values_as_the_oedometer_reads_them():
    assert cellValue('f', '200', OEDOMETER) == 200 and cellValue('pattern', "'planar4'", OEDOMETER) == 'planar4'
    assert cellValue('abrasion', '0', OEDOMETER) is False  # a flag
    assert cellValue('notAParameter', '1e-4', OEDOMETER) == 1e-4


def test_reading_a_table_leaves_nothing_behind(tmp_path):
    """YADE's reader boots YADE: its banner stays off our standard output and its /tmp/yade-XXXXXX
    directory is removed at exit."""
    (tmp_path / 't.table').write_text('seed\n1\n')
    p = subprocess.run([sys.executable, '-c', 'import os, sys; from ballast.tables import Table; '
                        'print(Table(sys.argv[1]).runId(2)); from yade.wrapper import Omega; '
                        'print("yadeTmp=" + os.path.dirname(Omega().tmpFilename()), file=sys.stderr)',
                        str(tmp_path / 't.table')], capture_output=True, text=True, timeout=60, cwd=str(tmp_path))
    assert p.returncode == 0, p.stderr
    assert p.stdout == 'seed=1\n'
    # its own directory, named by YADE (other YADE processes on the machine make and remove theirs meanwhile)
    (yadeTmp,) = [line[len('yadeTmp='):] for line in p.stderr.splitlines() if line.startswith('yadeTmp=')]
    assert os.path.basename(yadeTmp).startswith('yade-') and not os.path.exists(yadeTmp)


@pytest.mark.parametrize('column,value,allowed', [
    ('seed', '1e30', '[0, 2^31 - 1]'), ('seed', '-3', '[0, 2^31 - 1]'), ('f', '1e-300', 'more than the 1e+09'),
    ('Fmax', '1e300', 'outside rigid-sphere DEM'), ('gamma', '1e-300', '[0.5, 1)'), ('m', '1e5', '[0, 3]'),
    ('criterion', "'tresca'", "'vonMises', 'maxContactForce' or 'majorPrincipal'"),
    ('weibullModulus', '0.5', '0 or a number in [1, 50]'),
])
def test_audit_cells_are_refused_naming_column_value_and_range(column, value, allowed):
    """Issue 15: values that passed a table's checks and failed minutes into a run, or never ended."""
    msg = refused('seed %s\n1 %s\n' % (column, value) if column != 'seed' else 'seed\n%s\n' % value)
    assert 't.table:2: ' in msg and allowed in msg, msg
    assert column in msg


@pytest.mark.parametrize('content', [b'seed f\n1 \xff\xfe\n', b'\x1f\x8b\x08\x00binary', b'seed\x00 f\n1 2\n'])
def test_a_binary_or_non_utf8_table_is_refused_naming_the_file(tmp_path, content):
    path = tmp_path / 'bad.table'
    path.write_bytes(content)
    with pytest.raises(StudyError, match='bad.table: not a text table'):
        Table(str(path))
    script = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), 'scripts', 'study.py')
    p = subprocess.run([sys.executable, script, 'run', str(path), '--dry-run'], capture_output=True, text=True, timeout=120)
    assert p.returncode == 2 and str(path) in p.stderr and 'Traceback' not in p.stderr, p.stderr[-2000:]


def test_a_tables_relative_paths_start_from_its_own_folder(tmp_path, monkeypatch):
    """continueFrom 'states/end.yade.gz' in a table under tmp/tables means tmp/tables/states/end.yade.gz, for
    the study that checks the table and for a run that reads a copy of it elsewhere (TABLE_DIR)."""
    from ballast.tables import TABLE_DIR, Table, resolvePaths, tableRow
    folder = tmp_path / 'tables'
    (folder / 'states').mkdir(parents=True)
    (folder / 'states' / 'end.yade.gz').write_bytes(b'state')
    (folder / 'box.table').write_text("description seed cycles continueFrom\nslice2 1 5 'states/end.yade.gz'\n")
    want = str(folder / 'states' / 'end.yade.gz')
    params = Table(str(folder / 'box.table')).check(BOX)
    assert params[2]['continueFrom'] == want
    copy = tmp_path / 'scratch' / 'table'
    copy.parent.mkdir()
    copy.write_text((folder / 'box.table').read_text())
    monkeypatch.setenv(TABLE_DIR, str(folder))
    assert tableRow(str(copy), 2, BOX)['continueFrom'] == repr(want)
    # absolute paths, empty ones and the paths the study sets itself are left as they are
    cells = {'continueFrom': "'/abs/x.yade.gz'", 'loadFile': "''", 'results': "'out'"}
    assert resolvePaths(cells, BOX, str(folder)) == cells


def test_a_cell_the_runs_reader_cannot_evaluate_is_refused_before_any_run():
    """Unquoted text passes the parameter's own parser but not the eval of YADE's readParamsFromTable, which every
    run applies at its start: the study refuses it first, naming line, column and value."""
    text = "seed pattern criterion\n1 planar4 'vonMises'\n2 'planar4' vonMises\n"
    message = refused(text)
    assert message.startswith('2 row(s) refused')
    assert "t.table:2: column pattern, value planar4: YADE's table reader evaluates every cell" in message
    assert 't.table:3: column criterion, value vonMises:' in message
    assert table(text.replace(' planar4', " 'planar4'").replace(' vonMises', " 'vonMises'")).check(OEDOMETER)[3]['pattern'] == 'planar4'


@pytest.mark.parametrize('path', sorted(os.path.join('studies', f) for f in os.listdir(os.path.join(
    os.path.dirname(__file__), '..', '..', 'studies')) if f.endswith('.table')))
def test_every_study_table_of_the_repository_passes_its_experiments_check(path):
    """Each table in studies/ against the experiment its comments name (--experiment X, else the oedometer):
    a table a session writes must run, not fail in its first seconds."""
    full = os.path.join(os.path.dirname(__file__), '..', '..', path)
    text = open(full).read()
    named = {l.split('--experiment')[1].split()[0] for l in text.splitlines() if l.startswith('#') and '--experiment' in l}
    assert len(named) <= 1, named
    root = os.path.dirname(full)
    for state in set(re.findall(r"'(\.\./results/studies/[^']+)'", text)):
        if not os.path.isfile(os.path.join(root, state)):
            # a state too large for git, made on this machine by a run of another table: that row must exist; the
            # rest of the row is checked without it (a fresh clone runs that row first, as the table says)
            study, run = re.fullmatch(r'\.\./results/studies/([^/]+)/runs/([^/]+)/state-end\.yade\.gz', state).groups()
            maker = os.path.join(root, study + '.table')
            assert os.path.isfile(maker) and run in Table(maker).ids.values(), (state, maker)
            assert '%s.table' % study in text, 'the table must say which row makes %s' % state
            text = text.replace("'%s'" % state, "''")
    params = Table(full, text=text).check(declaration(named.pop() if named else 'oedometer'))
    assert params and all(p['seed'] >= 1 for p in params.values())
