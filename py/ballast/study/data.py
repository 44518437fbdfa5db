"""What a study leaves, read back: one run (:func:`read_run`, :class:`Run`), the finished runs of a
study folder (:class:`StudyRuns`) and the same against the studied parameter (:class:`StudyData`).
A study folder is a study directory of Study.run or its records (records.py): the same layout.

The CSV files of a run are pandas DataFrames, read on first use by :func:`readTable`, the one CSV
reader of the package (numbers parsed to the last bit, as Python parses them); summary.json and
row.json stay dicts, :meth:`StudyRuns.frame` gives the runs as one DataFrame. The experiment that made
a study is read from study.json ('experiment'; DEFAULT_EXPERIMENT for the folders older than it), and
its declaration's ``derived`` adds to every summary the results the run's files give (the oedometer:
what the per-check log says, ballast.experiments.oedometer.checkstats). Needs no YADE.
"""
import json
import os

from ..runfiles import column, readSummary
from .options import StudyError, experimentDeclaration
from ..tables import cellValue

# the CSV files of a run, each a property of Run (crushes: see Run.crushes)
TABLES = ('fd', 'checks', 'events', 'cycles', 'psd')
# the oedometer's counts per cycle and per check under the names they had before 2026-12 (nCrushed, nAbraded: the
# engines' running totals, as fd.csv and the box's cycles.csv still use them), read under today's
LEGACY_COUNTS = {'cycles': {'nCrushed': 'crushes', 'nAbraded': 'abrasions'}, 'checks': {'nCrushed': 'crushes'}}


def readTable(path):
    """The CSV file at `path` as a pandas DataFrame, None if there is no such file (an empty file: a
    DataFrame without columns). Numbers are parsed as Python's float() does (float_precision=
    'round_trip'; pandas' own parser may miss the last bit), so a value read back is the value written;
    empty cells are NaN."""
    if not os.path.isfile(path):
        return None
    import pandas
    try:
        return pandas.read_csv(path, float_precision='round_trip')
    except pandas.errors.EmptyDataError:
        return pandas.DataFrame()


class Run:
    """One run folder or its record. dir; summary (summary.json as a dict, None if the run did not
    finish: `why` says why); params (the run's parameters, from its summary); row (row.json: table row,
    code sha1, host, command; {} without one); the CSV files as DataFrames, read on first use, None
    without the file: fd, checks, events, cycles, psd, and crushes. In a study also line, runId and
    cells (the table row), and in StudyData value and seed (the studied parameter's value and the
    realization)."""

    def __init__(self, path, line=None, runId=None, cells=None):
        self.dir = path
        self.summary, self.why = readSummary(path)
        self.line, self.runId, self.cells = line, runId, cells or {}
        self.value = self.seed = None
        self._tables = {}

    @property
    def params(self):
        return (self.summary or {}).get('params') or {}

    @property
    def row(self):
        if 'row' not in self._tables:
            try:
                with open(os.path.join(self.dir, 'row.json')) as fh:
                    self._tables['row'] = json.load(fh)
            except (OSError, ValueError):
                self._tables['row'] = {}
        return self._tables['row']

    def table(self, name):
        """<name>.csv of the run as a DataFrame (None without it), read once."""
        if name not in self._tables:
            t = readTable(os.path.join(self.dir, name + '.csv'))
            if t is not None and 'crushes' not in t:   # a record of before the names of today (LEGACY_COUNTS)
                t = t.rename(columns=LEGACY_COUNTS.get(name, {}))
            self._tables[name] = t
        return self._tables[name]

    fd = property(lambda self: self.table('fd'), doc='fd.csv: the force-displacement curve')
    checks = property(lambda self: self.table('checks'), doc='checks.csv: the per-check log')
    events = property(lambda self: self.table('events'), doc='events.csv: every crush and abrasion')
    cycles = property(lambda self: self.table('cycles'), doc='cycles.csv: a row per load cycle')
    psd = property(lambda self: self.table('psd'), doc='psd.csv: the grading before and after')

    @property
    def crushes(self):
        """A DataFrame of the crushes, t [s], radius [m] and ratio [-] (the criterion's stress over the
        strength the grain crushed at): a record's crushes.csv, else the crushes of events.csv with
        ratio = value / strength; None without either file."""
        if 'crushes' not in self._tables:
            c = readTable(os.path.join(self.dir, 'crushes.csv'))
            if c is None and self.events is not None and 'kind' in self.events:
                import pandas
                e = self.events[self.events['kind'] == 'crush']
                ratio = column(e, 'ratio') if 'ratio' in e else column(e, 'value') / column(e, 'strength')
                c = pandas.DataFrame({'t': column(e, 't'), 'radius': column(e, 'radius'), 'ratio': ratio})
            self._tables['crushes'] = c
        return self._tables['crushes']


def read_run(path):
    """The finished run in the folder `path` (a run folder or a record) as a :class:`Run`; StudyError
    naming the folder and why if it did not finish (the test of files.readSummary)."""
    run = Run(path)
    if run.summary is None:
        raise StudyError('RUN: %s is not a finished run: %s' % (path, run.why))
    return run


class StudyRuns:
    """The finished runs of the study folder `path`, every parameter and result, no parameter singled
    out. info: study.json; declaration: the experiment's (`experiment`, else study.json's, else
    DEFAULT_EXPERIMENT); runs: [Run] in table order, each summary with the declaration's derived
    results merged in (they replace a summary entry of the same name); missing: run ids not finished.
    StudyError for a folder that is no study or has no finished run."""

    def __init__(self, path, experiment=None):
        self.dir = os.path.abspath(path)
        if not os.path.isdir(self.dir):
            raise StudyError('STUDY: no such directory: %s' % path)
        info = os.path.join(self.dir, 'study.json')
        if not os.path.isfile(info):
            raise StudyError('STUDY: %s is not a study directory of scripts/study.py (no study.json)' % path)
        with open(info) as fh:
            self.info = json.load(fh)
        self.declaration = experimentDeclaration(experiment or self.info.get('experiment'))
        self.runs, self.missing = [], []
        for r in self.info['rows']:
            run = Run(os.path.join(self.dir, 'runs', r['runId']), r['line'], r['runId'], r['row'])
            if run.summary is None:
                self.missing.append(r['runId'])
                continue
            run.summary = dict(run.summary, **self.declaration.derived(run))
            self.runs.append(run)
        if not self.runs:
            raise StudyError('STUDY: no finished run in %s (run it with scripts/study.py run first)' % path)

    def frame(self):
        """The finished runs as one DataFrame, a row each in table order: line, runId, dir, value and
        seed (StudyData), then the summary flattened as pandas.json_normalize does (params.f,
        stepsByPhase.load, ...)."""
        import pandas
        head = pandas.DataFrame({'line': [r.line for r in self.runs], 'runId': [r.runId for r in self.runs],
                                 'dir': [r.dir for r in self.runs], 'value': [r.value for r in self.runs],
                                 'seed': [r.seed for r in self.runs]})
        return pandas.concat([head, pandas.json_normalize([r.summary for r in self.runs])], axis=1)

    def codeVersions(self):
        """The code sha1s (row.json) the finished runs were made with; None for runs without one."""
        return set(r.row.get('codeSha1') for r in self.runs)


class StudyData(StudyRuns):
    """The finished runs of a study folder against the studied parameter `param` (default: the only
    column that varies besides the seed; StudyError naming the columns otherwise). Every run has its
    value and seed (as the run read them; from the table's cells for a summary without its
    parameters); values, seeds: sorted; numeric: every value a number; response: the declaration's
    response the analyses test (the first of its names every run has; the oedometer: delta at the peak
    of the applied force, else of the measured force for runs of older versions)."""

    def __init__(self, path, param=None, experiment=None):
        StudyRuns.__init__(self, path, experiment)
        rows = self.info['rows']
        cols = [c for c in self.info['columns'] if c != 'description' and not c.startswith('!')]
        varying = [c for c in cols if c != 'seed' and len(set(r['row'][c] for r in rows)) > 1]
        if param is not None:
            if param not in cols:
                raise StudyError('--param: %r is not a column of the study table (columns: %s)' % (param, ', '.join(cols)))
            self.param = param
        elif len(varying) == 1:
            self.param = varying[0]
        elif not varying:
            raise StudyError('STUDY: no column but the seed varies in %s; nothing to aggregate against' % self.info['table'])
        else:
            raise StudyError('--param: the table varies %s; say which one is studied' % ', '.join(varying))
        for r in self.runs:
            r.value, r.seed = (r.params[k] if k in r.params else cellValue(k, r.cells.get(k), self.declaration)
                               for k in (self.param, 'seed'))
        vals = [r.value for r in self.runs]
        self.numeric = all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in vals)
        self.values = sorted(set(vals), key=(lambda v: v) if self.numeric else (lambda v: (isinstance(v, str), str(v).zfill(8))))
        self.seeds = sorted(set(r.seed for r in self.runs), key=lambda s: (str(type(s)), s))
        names = self.declaration.response
        self.response = next((k for k in names if all(r.summary.get(k) is not None for r in self.runs)),
                             names[-1] if names else None)
