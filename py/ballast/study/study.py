"""A study: the rows of a table run into a study directory, with the bookkeeping that lets it stop
and carry on.

A study directory holds
    runs/<run id>/      finished runs: the experiment's output (summary.json, fd.csv, ...) and row.json
    logs/<run id>.log   the log of the last attempt of every run, with yade-batch's job summary at the end
    failed/<run id>/    what the last failed attempt left (removed once the run succeeds)
    status.csv          one line per table row: status, exit code, duration, host
    journal.jsonl       every attempt, appended as it ends (one whose runner died: when the study starts again)
    table, study.json   the table as it was run (the runs read their row from it, as under yade-batch)
                        and the study's description (experiment, rows, run ids, script, code sha1)
A run counts as finished when runs/<run id>/summary.json parses (files.readSummary, the test of
the aggregation too): a study started again skips those and redoes the rest. With `records` (a folder
in the repository, ballast.study.records) every finished run also leaves a compact record there, and
a row whose record exists counts as finished: a study goes on from the records on any machine.

The experiment is known by its declaration (ballast.experiments: its parameters and their check,
its script, the parameters the study sets, which runs share a prepared sample, the cost of a run).
Prepared samples (the oedometer's packings) are stored in the packings directory (default:
'packings' next to the study directory, shared by the studies there) under the name the
declaration's sampleKey gives, and reused by every run that gets the same name. Of the rows that need
the same sample not stored yet, the cheapest (the declaration's cost) runs first and builds it; the
others wait for it.
"""
import csv
import io
import json
import os
import re
import time
import uuid

from ..names import fmtTime
from ..params import ParamError
from ..runfiles import codeSha1, readSummary, sha1, writeAtomic
from .options import OPTIONS, StudyError, experimentDeclaration, optionValue
from .records import hasRecord, keepRecord, recordPath, writeIndex
from .attempts import KEEP, clearWork
from .progress import Progress
from ..tables import Table, resolvePaths, tableDir

# yade-batch's !COLUMNS that are not environment variables of the run
BATCH_COLUMNS = ('!SCRIPT', '!EXEC', '!AFFINITY', '!COUNT')


def defaultOut(table):
    """results/studies/<table name without .table>."""
    return os.path.join('results', 'studies', re.sub(r'\.table$', '', os.path.basename(table)))


class Study:
    """The rows of `table` (a yade-batch table of the parameters of `experiment`: a name or a
    Declaration, default the oedometer) run by `script` (the experiment's command line, its
    declaration's script) into `out` (default :func:`defaultOut`). packings: the store of prepared
    samples (default 'packings' next to `out`); lines: yade-batch's --lines (default: every row);
    yade: the executable on the machines that run; nice, timeout, progress: see options.OPTIONS;
    ship: send script, table and packings with every Dask task and the results back, even to workers
    that see `out`; skipFailed: do not redo runs that failed before; verbose: a line when a run
    starts; records: a folder for the compact records of the finished runs (records.py), whose rows
    are skipped. Everything is checked here, before any run: a bad table row is refused naming line
    and column."""

    def __init__(self, table, script, out=None, packings=None, lines=None, yade='yade', nice=OPTIONS['nice'].default,
                 timeout=None, ship=False, skipFailed=False, progress=OPTIONS['progress'].default, verbose=False,
                 records=None, experiment=None):
        self.declaration = experimentDeclaration(experiment)
        if not os.path.isfile(table):
            raise StudyError('TABLE: no such file: %s' % table)
        if not os.path.isfile(script):
            raise StudyError('--script: no such file: %s' % script)
        self.tablePath, self.script = table, os.path.abspath(script)
        with open(self.script) as fh:
            self.scriptText = fh.read()
        self.codeSha1 = codeSha1(self.scriptText)
        self.yade, self.ship, self.skipFailed, self.verbose = yade, ship, skipFailed, verbose
        self.nice, self.timeout = optionValue('nice', nice), optionValue('timeout', timeout)
        self.progress = optionValue('progress', progress)
        lines = optionValue('lines', lines)
        self.table = Table(table)
        self.params = self.table.check(self.declaration)  # line -> every parameter of its run
        self.out = os.path.abspath(out or defaultOut(table))
        self.packings = os.path.abspath(packings or os.path.join(os.path.dirname(self.out), 'packings'))
        self.records = os.path.abspath(records) if records else None
        for name, p in (('--out', self.out), ('--packings', self.packings)) + ((('--records', self.records),) if records else ()):
            if ':' in p:
                raise StudyError("%s: %s contains ':', which YADE_BATCH (table:line) cannot carry" % (name, p))
            if os.path.exists(p) and not os.path.isdir(p):
                raise StudyError('%s: %s exists and is not a directory' % (name, p))
        have = [n for n, _ in self.table.rows]
        self.lines = lines or have
        if set(self.lines) - set(have):
            raise StudyError('--lines: line(s) %s of %s hold no row; rows are on lines %s' % (
                ','.join(str(n) for n in self.lines if n not in have), table, ','.join(map(str, have))))
        self.rows = dict(self.table.rows)
        self.t0 = time.time()

    def say(self, msg):
        print('[study %8s] %s' % (fmtTime(time.time() - self.t0), msg), flush=True)

    def sampleName(self, line):
        """File name of the prepared sample the run of this line needs (in the packings directory), None
        if it needs none."""
        return self.declaration.sampleKey(self.params[line])

    def finishedRow(self, line):
        """None if the run is not finished (in runs/, or as a record); else its row.json ({} if unreadable)."""
        rid = self.table.runId(line)
        d = os.path.join(self.out, 'runs', rid)
        if readSummary(d)[0] is None:
            if not (self.records and hasRecord(self.records, rid)):
                return None
            d = recordPath(self.records, rid)
        try:
            with open(os.path.join(d, 'row.json')) as fh:
                return json.load(fh)
        except (OSError, ValueError):
            return {}

    def runParameters(self, row):
        """Every parameter of the run a recorded row gave (its cells checked as the table's are); None if
        they no longer pass the check."""
        cells = {k: v if isinstance(v, str) else str(v) for k, v in row.items() if k in self.declaration.params and v != '*'}
        try:
            return dict(self.declaration.check(resolvePaths(cells, self.declaration, tableDir(self.tablePath)), text=True))
        except ParamError:
            return None

    def dryRun(self):
        for n in self.lines:
            print('%4d  %-40s %s' % (n, self.table.runId(n), 'to run' if self.finishedRow(n) is None else 'finished (skipped)'))

    def keepRecord(self, line):
        """The record of the finished run of `line` into `records` (if a records folder is given)."""
        rid = self.table.runId(line)
        if self.records and os.path.isdir(os.path.join(self.out, 'runs', rid)):
            keepRecord(os.path.join(self.out, 'runs', rid), self.records, rid, self.declaration)

    def lock(self):
        import fcntl
        os.makedirs(self.out, exist_ok=True)
        self.lockFile = open(os.path.join(self.out, '.lock'), 'a+')
        try:
            fcntl.flock(self.lockFile, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            raise StudyError('--out: %s is being run by another study right now' % self.out) from None

    def prepare(self):
        """The study directory set up before the first run starts; returns how many unfinished
        attempts a runner that died had left (removed: they are redone; in the journal). The
        attempts another runner still holds are left alone."""
        self.lock()
        for d in ('runs', 'logs', 'failed'):
            os.makedirs(os.path.join(self.out, d), exist_ok=True)
        os.makedirs(self.packings, exist_ok=True)
        # a finished run made from a row that has changed since would be mixed into the results
        # (compared as parameters: a column added or dropped at its default changes no run)
        stale = []
        for n in self.lines:
            rr = self.finishedRow(n)
            if rr and rr.get('row') is not None:
                made, now = self.runParameters(rr['row']), dict(self.params[n])
                other = [k for k in sorted(set(rr['row']) | set(self.rows[n])) if k not in self.declaration.params
                         and rr['row'].get(k) != self.rows[n].get(k)]   # columns that are no parameter: as text
                if made != now or other:
                    diff = ['%s %s -> %s' % (k, made.get(k) if made else '?', now.get(k))
                            for k in sorted(now) if made is None or made.get(k) != now.get(k)]
                    diff += ['%s %s -> %s' % (k, rr['row'].get(k), self.rows[n].get(k)) for k in other]
                    stale.append('%s (line %d: %s)' % (self.table.runId(n), n, ', '.join(diff)))
        if stale:
            raise StudyError('%s: finished run(s) in %s/runs were made from other values than the table now gives: %s. '
                             'Remove those run directories or choose another --out.' % (
                                 self.tablePath, self.out, '; '.join(stale[:5])))
        left = clearWork(os.path.join(self.out, 'work'),
                         keep=os.path.join(self.out, KEEP) if self.declaration.sets.get('resume') else None)
        lineOf = {self.table.runId(n): n for n, _ in self.table.rows}
        with open(os.path.join(self.out, 'journal.jsonl'), 'a') as fh:
            for rec in left:
                fh.write(json.dumps({'runId': rec['runId'], 'line': lineOf.get(rec['runId']), 'status': rec['status'],
                                     'error': rec['error']}) + '\n')
        self.token = uuid.uuid4().hex
        writeAtomic(os.path.join(self.out, '.study-token'), self.token)
        writeAtomic(os.path.join(self.out, 'table'), self.table.text)
        info = {'experiment': self.declaration.name, 'table': os.path.abspath(self.tablePath),
                'tableSha1': sha1(self.table.text), 'script': self.script,
                'codeSha1': self.codeSha1, 'packings': self.packings, 'columns': self.table.columns,
                'rows': [{'line': n, 'runId': self.table.runId(n), 'row': r} for n, r in self.table.rows],
                'lines': list(self.lines)}   # the rows this start runs (--lines): what status counts as to run
        writeAtomic(os.path.join(self.out, 'study.json'), json.dumps(info, indent=1))
        if self.records:
            writeIndex(self.records, info)
            # runs finished before the records were asked for (or before a record was lost) get theirs
            for n in self.lines:
                if not hasRecord(self.records, self.table.runId(n)) and readSummary(
                        os.path.join(self.out, 'runs', self.table.runId(n)))[0] is not None:
                    self.keepRecord(n)
        self.status = {}
        for n in self.lines:
            failed = os.path.isdir(os.path.join(self.out, 'failed', self.table.runId(n)))
            self.status[n] = {'status': 'finished' if self.finishedRow(n) is not None else ('failed' if failed else 'todo')}
        self.kept = sum(1 for rec in left if rec['kept'])
        return len(left)

    def tasks(self, todo, executorName):
        """The runs of `todo` in table order: {'spec': what runner.runRow needs, 'leader': None or the
        run id of the run that builds the sample this one needs}. Of the runs that need the same
        sample not stored yet, the cheapest (the declaration's cost; the first in the table of equals)
        leads."""
        groups = {}
        for n in todo:
            if self.sampleName(n) is not None:
                groups.setdefault(self.sampleName(n), []).append(n)
        leaderOf = {}
        for name, lines in groups.items():
            if len(lines) > 1 and not os.path.exists(os.path.join(self.packings, name)):
                lead = min(lines, key=lambda n: (self.declaration.cost(self.params[n]), lines.index(n)))
                leaderOf.update((n, self.table.runId(lead)) for n in lines if n != lead)
        tasks = []
        for n in todo:
            env = {'OMP_NUM_THREADS': '1'}
            for c, v in self.rows[n].items():  # yade-batch's !COLUMNS: threads of the run, or an environment variable
                if c in ('!OMP_NUM_THREADS', '!THREADS'):
                    env['OMP_NUM_THREADS'] = str(v)
                elif c.startswith('!') and c not in BATCH_COLUMNS:
                    env[c[1:]] = str(v)
            pfiles = {}
            name = self.sampleName(n)
            if name is not None and os.path.exists(os.path.join(self.packings, name)):
                with open(os.path.join(self.packings, name), 'rb') as fh:
                    pfiles[name] = fh.read()
            spec = {'runId': self.table.runId(n), 'line': n, 'row': self.rows[n], 'tableText': self.table.text,
                    'tableName': os.path.abspath(self.tablePath), 'scriptPath': self.script, 'scriptText': self.scriptText,
                    'yade': self.yade, 'nice': self.nice, 'env': env, 'out': self.out, 'token': self.token,
                    'sets': self.declaration.sets,
                    'packings': self.packings, 'packingFiles': pfiles, 'timeout': self.timeout, 'executor': executorName,
                    'ship': self.ship}
            tasks.append({'spec': spec, 'leader': leaderOf.get(n)})
        return tasks

    def writeStatus(self):
        buf = io.StringIO()
        w = csv.writer(buf, lineterminator='\n')  # run ids hold commas: quoted
        w.writerow(['line', 'runId', 'status', 'exitCode', 'wallSeconds', 'host', 'error'])
        for n in self.lines:
            s = self.status[n]
            w.writerow([n, self.table.runId(n), s['status'], '' if s.get('rc') is None else s['rc'],
                        '' if s.get('wall') is None else '%.1f' % s['wall'], s.get('host', ''), s.get('error') or ''])
        writeAtomic(os.path.join(self.out, 'status.csv'), buf.getvalue())

    def run(self, executor):
        """Run (or carry on) the study with `executor` (ballast.study.executors). Returns the exit
        status of scripts/study.py: 0 all finished, 1 some run failed, 130 interrupted. The study's lock is
        let go when it returns, not when the object is collected."""
        try:
            return self._run(executor)
        finally:
            if getattr(self, 'lockFile', None) is not None:
                self.lockFile.close()
                self.lockFile = None

    def _run(self, executor):
        cleaned = self.prepare()
        todo = [n for n in self.lines if self.status[n]['status'] != 'finished']
        nDone = len(self.lines) - len(todo)
        if self.skipFailed:
            todo = [n for n in todo if self.status[n]['status'] != 'failed']
        self.say('%s: %d rows%s, %d finished before (skipped), %d to run; results in %s' % (
            self.tablePath, len(self.lines), '' if len(self.lines) == len(self.table.rows) else ' (--lines)', nDone, len(todo),
            self.out))
        if cleaned:
            self.say('removed %d unfinished attempt(s) left by an interrupted study; their runs are redone%s' % (
                cleaned, ', %d from the last state it saved (kept in %s/)' % (self.kept, KEEP) if self.kept else ''))
        old = {}
        for n in self.lines:
            made = (self.finishedRow(n) or {}).get('codeSha1')
            if made not in (None, self.codeSha1):
                old[made] = old.get(made, 0) + 1
        if old:
            self.say('warning: %d finished run(s) were made by another version of %s or of the ballast package (code sha1 %s); '
                     'they are kept, not redone' % (sum(old.values()), self.script, ', '.join(k[:10] for k in old)))
        tasks = self.tasks(todo, executor.name)
        nLead = len(set(t['leader'] for t in tasks if t['leader']))
        if nLead:
            self.say('%d run(s) wait for the prepared sample one of %d other run(s) builds first' % (
                len([t for t in tasks if t['leader']]), nLead))
        self.say('executor %s: %s' % (executor.name, executor.describe()))
        self.writeStatus()
        if not todo:
            self.say('nothing to run')
            return 0
        return Progress(self, executor, len(todo)).run(tasks)
