"""Tables: yade-batch tables whose columns are parameters of an experiment (its declaration,
:class:`ballast.experiments.Declaration`, given by the caller). They are read by YADE's own reader,
``yade.utils.TableParamReader``, so rows, line numbers and run descriptions are yade-batch's, and
every cell is checked against the declaration before any run starts. This module is the one reader of
the tables: a study reads them with :class:`Table`, a run of one row (YADE_BATCH=table:line) with
:func:`tableRow`.
"""
import atexit
import contextlib
import io
import math
import os
import re
import shutil
import sys
import tempfile
import warnings

from . import textfile
from .names import runDirName
from .params import ParamError, literal



class TableError(Exception):
    """A table YADE would misread, or a cell no run can take, found before any run starts; the message
    names the file, the line and the column. The study's StudyError is this class."""


# Where Debian 12's yade keeps its Python modules (the dist-packages link of python3-yade is broken).
YADE_PY = '/usr/lib/x86_64-linux-gnu/yade-double/py'
def tableReader():
    """yade.utils.TableParamReader in plain /usr/bin/python3. Importing YADE boots it (measured with
    YADE 2023.02a on Debian 12: 0.5 s, once a process). What else it does: it prints a banner on
    stdout (kept out of ours: `study.py grid` writes its table there) and deprecation warnings,
    makes an empty /tmp/yade-XXXXXX that only yade's own exit removes (removed here at exit), and
    starts one idle OpenMP thread unless OMP_NUM_THREADS=1; no Python thread, no signal handler."""
    if 'yade.utils' not in sys.modules:
        if YADE_PY not in sys.path:
            sys.path.append(YADE_PY)
        try:
            with contextlib.redirect_stdout(io.StringIO()), warnings.catch_warnings():
                warnings.simplefilter('ignore', DeprecationWarning)  # YADE's imports (imp, escapes), not ours
                import yade.utils
        except ImportError as e:
            raise TableError('reading a table needs YADE (yade.utils.TableParamReader), not importable here: %s' % e)
        atexit.register(shutil.rmtree, os.path.dirname(yade.Omega().tmpFilename()), True)
    return sys.modules['yade.utils'].TableParamReader


def readText(path):
    """A table's text; TableError naming the file if it is not UTF-8 text (a binary file, another encoding)."""
    try:
        return textfile.read(path)
    except textfile.NotText as e:
        raise TableError(str(e).replace('not a text file', 'not a text table')) from None


class Table:
    """A yade-batch table as yade-batch reads it. ``rows``: [(line, {column: cell text})] with the
    file's 1-based line numbers, '=' resolved (``byLine``: the same by line); ``columns`` as YADE
    names them ('!' of run-id columns removed unless there is a description column); ``runId(line)``:
    the row's description (the description column, else name=value of the 'name!' columns, else of
    all columns) made a directory name by :func:`ballast.names.runDirName`.

    Refused, naming the line, where YADE's reader would fail or guess: an empty table, a row with
    another number of cells than there are column names, '=' on the first row (YADE takes the last
    row's value), a column twice, and (unless ids=False: a run of one row needs no run ids) two rows
    with the same run id (YADE appends '__line=N__', an id that changes when lines move)."""

    def __init__(self, path, text=None, ids=True):
        self.path = path
        if text is None:
            text = readText(path)
        # the reader cuts the last character of every line, meant to be the newline
        self.text = text if text.endswith('\n') else text + '\n'
        # the lines as the reader splits them, only to name a line it would misread
        split = [re.sub(r'\s*#.*', '', l).split() for l in self.text.split('\n')[:-1]]
        cells = {n: c for n, c in enumerate(split, 1) if c}
        if not cells:
            raise TableError('%s: the table is empty (its first non-empty line names the columns)' % path)
        head = min(cells)
        heads = cells.pop(head)
        if not cells:
            raise TableError('%s: no rows below the column names on line %d' % (path, head))
        for n, c in sorted(cells.items()):
            if len(c) != len(heads):
                raise TableError('%s:%d: %d cells, but line %d names %d columns (cells are separated by blanks, '
                                 'no quoting of blanks)' % (path, n, len(c), head, len(heads)))
        top = min(cells)
        if '=' in cells[top]:
            raise TableError("%s:%d: '=' in column %s repeats the row above, but this is the first row" % (
                path, top, heads[cells[top].index('=')]))
        with tempfile.NamedTemporaryFile('w', prefix='study-', suffix='.table') as fh:
            fh.write(self.text)
            fh.flush()
            values = tableReader()(fh.name).paramDict()
        self.hasDescription = 'description' in heads
        self.columns = [c for c in values[top] if c != 'description' or self.hasDescription]
        if len(self.columns) != len(heads):
            raise TableError('%s:%d: a column appears twice in %s' % (path, head, ' '.join(heads)))
        self.rows = [(n, {c: values[n][c] for c in self.columns}) for n in sorted(values)]
        self.byLine = dict(self.rows)
        self.ids = {}
        seen = {}
        for n, _ in self.rows if ids else ():
            desc = values[n]['description']
            if not self.hasDescription and desc.endswith('__line=%d__' % n):  # YADE's mark of a repeat
                desc = desc[:-len('__line=%d__' % n)]
            rid = runDirName(desc)
            if rid in seen:
                raise TableError('%s:%d: the row gives the run id %r, as line %d does; make the rows differ or add a '
                                 'description column' % (path, n, rid, seen[rid]))
            seen[rid] = n
            self.ids[n] = rid

    def runId(self, line):
        return self.ids[line]

    def parameterColumns(self):
        """The columns that are parameters (not the description, not yade-batch's !COLUMNS)."""
        return [c for c in self.columns if c != 'description' and not c.startswith('!')]

    def cells(self, line):
        """{column: cell text} of the parameters the row on `line` sets: the parameter columns
        (parameterColumns), cells '*' left out (yade-batch's 'the default')."""
        row = self.byLine[line]
        return {c: row[c] for c in self.parameterColumns() if row[c] != '*'}

    def check(self, declaration):
        """{line: every parameter of its run} (the experiment's check of the row's cells; `declaration`:
        the experiment's Declaration), before any run starts. Columns that are no
        parameter or that the study sets itself, and every bad cell, are refused together in one
        TableError naming table, line, column and value."""
        d = declaration
        cols = self.parameterColumns()
        unknown = [c for c in cols if c not in d.params]
        if unknown:
            raise TableError('%s: column(s) %s are not parameters of the %s; parameters: %s' % (
                self.path, ', '.join(unknown), d.name, ', '.join(d.params)))
        ours = [c for c in cols if c in d.studySets()]
        if ours:
            raise TableError('%s: column(s) %s are set by the study for every run; remove them from the table' % (
                self.path, ', '.join(ours)))
        params, bad = {}, []
        for n, row in self.rows:
            cells = self.cells(n)
            unread = [c for c, raw in cells.items() if not readable(raw)]
            if unread:  # the run would fail on it at its start: readParamsFromTable evaluates every cell
                bad += ['%s:%d: column %s, value %s: %s' % (self.path, n, c, row[c], UNREADABLE) for c in unread]
                continue
            try:
                params[n] = d.check(resolvePaths(cells, d, tableDir(self.path)), text=True)
            except ParamError as e:
                if e.name in row:
                    bad.append('%s:%d: column %s, value %s: %s' % (self.path, n, e.name, row[e.name], e))
                else:  # a check between parameters, on one the row does not set
                    bad.append('%s:%d: %s (the row: %s)' % (self.path, n, e, ', '.join('%s=%s' % kv for kv in row.items())))
        if bad:
            raise TableError('%d row(s) refused:\n  %s%s' % (
                len(bad), '\n  '.join(bad[:10]), '\n  ...' if len(bad) > 10 else ''))
        return params


UNREADABLE = "YADE's table reader evaluates every cell: numbers as they are, text quoted ('planar4')"


def readable(raw):
    """Whether YADE's readParamsFromTable can evaluate the cell (it evals it, with math's names)."""
    try:
        eval(raw, dict(math.__dict__))
        return True
    except Exception:
        return False


TABLE_DIR = 'BALLAST_TABLE_DIR'   # a run's environment: the folder of the table its row came from


def resolvePaths(cells, declaration, base):
    """The cells with a relative path in a parameter of unit 'path' (but those the study sets) made absolute
    against `base`: a table's paths are relative to its own folder, wherever its runs run. Other cells as
    they are."""
    d = declaration
    out = dict(cells)
    for col, raw in cells.items():
        p = d.params.get(col)
        if p is None or p.unit != 'path' or col in d.studySets():
            continue
        value = p.fromText(raw)
        if isinstance(value, str) and value and not os.path.isabs(value):
            out[col] = repr(os.path.normpath(os.path.join(base, value)))
    return out


def tableDir(path):
    """The folder a table's relative paths start from: the run's TABLE_DIR if the study set it (the run reads a
    copy of the table in a scratch folder), else the table's own folder."""
    return os.environ.get(TABLE_DIR) or os.path.dirname(os.path.abspath(path))


def tableRow(path, line, declaration):
    """The row on `line` of the table at `path` as a run of it (YADE_BATCH=path:line) reads it:
    {parameter: cell text} (Table.cells: no description, no yade-batch !COLUMNS, no '*' cells), read
    as the study reads the table. Every column must be a parameter of the experiment (`declaration`: its
    Declaration) and every cell readable by the eval of YADE's
    readParamsFromTable: ParamError naming the column, the cell and what is allowed. The cells stay
    text; the experiment's check(values, text=True) turns them into values. A line without a row, or a
    table YADE would misread, raise TableError."""
    d = declaration
    table = Table(path, ids=False)
    if line not in table.byLine:
        raise TableError('%s: line %r holds no row; rows are on lines %s' % (path, line, ','.join(map(str, table.byLine))))
    cells = table.cells(line)
    for col, raw in cells.items():
        if col not in d.params:
            raise ParamError(col, '%s: %s is not a parameter (a column of %s); parameters: %s' % (
                d.owner, col, path, ', '.join(d.params)))
        if not readable(raw):
            raise ParamError(col, '%s: cannot read %s = %r from %s:%d: %s' % (d.owner, col, raw, path, line, UNREADABLE))
    return resolvePaths(cells, d, tableDir(path))


def cellValue(column, cell, declaration):
    """A cell as the experiment reads it (a parameter's own parser; other columns as literals)."""
    params = declaration.params
    return params[column].fromText(cell) if column in params else literal(cell)
