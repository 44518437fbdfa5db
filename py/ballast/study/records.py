"""Compact records of finished runs, kept in the repository so that a study outlives the session and
the machine that ran it (issue 14, item 4).

A record folder (``scripts/study.py run TABLE --records DIR``, for example ``docs/studies/<study>``) is a
study directory that :mod:`ballast.study.data` and ``scripts/aggregate.py`` read as they read the
full one:

    study.json              the rows of the table (run ids, cells), as in the study directory
    runs/<run id>/          per finished run, a few tens of kB:
        summary.json        the run's summary.json as written
    (an experiment whose declaration names its recordFiles keeps those whole instead of what follows)
        row.json            the runner's row.json (table row, code sha1, host, command, duration)
        fd.csv              fd.csv thinned to at most MAX_FD_ROWS rows (:func:`thinCurve`), same columns
        checks.csv          the per-check log thinned (:func:`thinChecks`): every check where a grain
                            crushed, the two around each of the experiment's recordTimes (the
                            oedometer: half the peak load, t = 1/(4f)) and the largest stress ratio
                            to 1/200 of its range
        crushes.csv         per crush (events.csv): t [s], the grain's radius [m] and its ratio, the
                            criterion's stress over the strength it crushed at [-]
        record.json         what was left out: rows of fd.csv and checks.csv, the largest stress ratio
                            of all checks; files over MAX_RECORD_FILE bytes (leftOut: size, SHA-1 and
                            the run's folder, where the file stays)
        psd.csv, cycles.csv, jumps.csv   copied if the run wrote them

The study runner skips a row whose record exists (the same test as for a finished run: its
summary.json parses), so a session runs a slice, commits the records, and the next one, on any
machine, carries on with the rest. The raw results stay out of git. :func:`writeRecord` is the one
writer of records, also of runs kept outside a study (the many-cycle runs of docs/studies/cycles,
their summary cut to a few entries).
"""
import json
import os
import shutil
import uuid

import numpy as np

from ..runfiles import column
from .data import Run
from ..runfiles import moveSynced, readSummary, sha1, writeAtomic
from .options import experimentDeclaration

MAX_FD_ROWS = 600          # rows of a recorded F-delta curve [-]: ~40 kB, enough for the paper's figures
MAX_CHECK_ROWS = 400       # rows of a recorded per-check log [-]
COPIED = ('summary.json', 'row.json', 'psd.csv', 'cycles.csv', 'jumps.csv')
# a file larger than this [bytes] stays in the run's folder, named in record.json's leftOut with its size and SHA-1
# (records are committed; a box's end state is 1.1-1.8 MB, a clump triaxial specimen's 3.7 MB)
MAX_RECORD_FILE = 2000000
# the thinning keeps every step of these to its resolution; F, the grains' force on the plate, saws at
# the plate's impacts and is recorded at the rows kept (its peak is in summary.json)
FD_QUANTITIES = ('delta', 'Fapplied')


def recordPath(records, runId):
    return os.path.join(records, 'runs', runId)


def hasRecord(records, runId):
    """The test of a finished run (files.readSummary) on the record."""
    return readSummary(recordPath(records, runId))[0] is not None


def thinCurve(columns, quantities, forced=(), maxRows=MAX_FD_ROWS):
    """Indices of the rows of a curve kept in its record: the first and the last, the `forced` ones, the
    extremes of each of `quantities`, and a row whenever one of them has moved by more than a step eps
    of its range since the row before it (eps = 1/200 of the range, doubled until at most maxRows rows
    are kept; evenly among the forced ones if they are more). columns: {name: array}."""
    n = len(columns[quantities[0]])
    if n <= maxRows:
        return np.arange(n)
    must = {0, n - 1} | set(int(i) for i in forced)
    for q in quantities:
        x = np.asarray(columns[q], dtype=float)
        if np.isfinite(x).any():
            must.update((int(np.nanargmax(x)), int(np.nanargmin(x))))
    must = np.array(sorted(must))
    eps = 1 / 200
    while True:
        keep = np.zeros(n, dtype=bool)
        keep[must] = True
        for q in quantities:
            x = np.nan_to_num(np.asarray(columns[q], dtype=float))
            span = float(np.ptp(x)) or 1.0
            level = np.floor((x - x.min()) / (eps * span))  # which step of the quantity each row is on
            keep[1:] |= level[1:] != level[:-1]
        rows = np.flatnonzero(keep)
        if len(rows) <= maxRows:
            return rows
        if eps >= 1:
            return rows[np.unique(np.linspace(0, len(rows) - 1, maxRows).round().astype(int))]
        eps *= 2


def thinFd(columns, maxRows=MAX_FD_ROWS):
    """thinCurve of an F-delta curve (fd.csv): every step of FD_QUANTITIES, the extremes of F and the
    rows where the crushed count changes (the start of each jump)."""
    forced = [int(np.nanargmax(columns['F'])), int(np.nanargmin(columns['F']))] if 'F' in columns else []
    if 'nCrushed' in columns:
        forced += list(np.flatnonzero(np.diff(np.asarray(columns['nCrushed'])) != 0) + 1)
    return thinCurve(columns, [q for q in FD_QUANTITIES if q in columns], forced, maxRows)


def thinChecks(columns, maxRows=MAX_CHECK_ROWS, times=()):
    """thinCurve of the per-check log (checks.csv): every check where a grain crushed, the checks on
    either side of each of `times` [s] (what a value at that time is interpolated from; beyond maxRows)
    and the largest stress ratios to 1/200 of their range (what the ft0 of another criterion is read
    from)."""
    around = []
    if len(times):
        t = np.asarray(columns['t'], dtype=float)
        around = sorted(set(int(i) for x in times for i in (np.searchsorted(t, x, 'right') - 1, np.searchsorted(t, x, 'left'))
                            if 0 <= i < len(t)))  # on top of maxRows: they do not coarsen the rest
    return thinCurve(columns, [q for q in ('maxStressRatio', 'maxCrushableRatio') if q in columns],
                     list(np.flatnonzero(np.asarray(columns['crushes']) > 0)) + around, maxRows + len(around))


def keptLines(path, rows):
    """The header and the data lines `rows` (0-based) of the CSV file at path, as they are written
    there: a record copies its rows, it does not print them again."""
    with open(path, newline='') as fh:
        lines = [l for l in fh.read().splitlines() if l.strip()]  # as readTable, which skips blank lines
    return '\n'.join([lines[0]] + [lines[1 + int(i)] for i in rows]) + '\n'


def columns(frame):
    """{name: float array} of a DataFrame (what thinCurve takes)."""
    return {name: column(frame, name) for name in frame.columns}


def writeRecord(runDir, dest, declaration=None, summaryKeys=None):
    """Writes the record of the finished run in runDir to the folder dest (replacing an older one whole:
    it appears only once complete): COPIED, fd.csv and checks.csv thinned (checks around the
    `declaration`'s recordTimes of the run's parameters: a name or a Declaration, default the
    oedometer), crushes.csv, record.json (see the module). summaryKeys: the summary cut to these
    entries and the parameters (a record that needs no more than they). Returns dest; ValueError for a
    run that did not finish."""
    run = Run(runDir)
    if run.summary is None:
        raise ValueError('%s is not a finished run: %s' % (runDir, run.why))
    os.makedirs(os.path.dirname(os.path.abspath(dest)), exist_ok=True)
    tmp = '%s.%s.tmp' % (dest, uuid.uuid4().hex[:6])
    os.makedirs(tmp)
    info = {'runId': os.path.basename(os.path.normpath(dest))}
    decl = experimentDeclaration(declaration)
    for name in COPIED if decl.recordFiles is None else decl.recordFiles:
        src = os.path.join(runDir, name)
        if not os.path.isfile(src):
            continue
        size = os.path.getsize(src)
        if size > MAX_RECORD_FILE:   # a clump specimen's end state (3.7 MB): git is no place for it
            with open(src, 'rb') as fh:
                info.setdefault('leftOut', {})[name] = {'bytes': size, 'sha1': sha1(fh.read()),
                                                        'run': os.path.abspath(runDir)}
        else:
            shutil.copyfile(src, os.path.join(tmp, name))
    if summaryKeys is not None:
        keep = {k: run.summary[k] for k in summaryKeys if k in run.summary}
        keep['params'] = run.summary['params']
        writeAtomic(os.path.join(tmp, 'summary.json'), json.dumps(keep, indent=1))
    if decl.recordFiles is None:   # the oedometer's: its long files thinned
        thinned(run, runDir, tmp, info, decl)
    writeAtomic(os.path.join(tmp, 'record.json'), json.dumps(info, indent=1))
    if os.path.isdir(dest):
        shutil.rmtree(dest)
    moveSynced(tmp, dest)
    return dest


def thinned(run, runDir, tmp, info, decl):
    """fd.csv, checks.csv (around decl's recordTimes) and crushes.csv of the run, thinned into tmp."""
    if run.fd is not None:
        kept = thinFd(columns(run.fd))
        writeAtomic(os.path.join(tmp, 'fd.csv'), keptLines(os.path.join(runDir, 'fd.csv'), kept))
        info['fdRows'] = {'run': len(run.fd), 'record': int(len(kept))}
    if run.checks is not None:
        cols, n = columns(run.checks), len(run.checks)
        times = decl.recordTimes(run.params) if run.params else ()
        kept = thinChecks(cols, times=times) if n else []
        writeAtomic(os.path.join(tmp, 'checks.csv'), keptLines(os.path.join(runDir, 'checks.csv'), kept))
        info['checks'] = {'run': n, 'record': int(len(kept)), 'crushing': int(np.sum(cols['crushes'] > 0)) if n else 0,
                          'maxStressRatio': float(np.max(cols['maxStressRatio'])) if n else None}
    if run.crushes is not None:
        rows = zip(*(column(run.crushes, c) for c in ('t', 'radius', 'ratio')))
        writeAtomic(os.path.join(tmp, 'crushes.csv'), 't,radius,ratio\n' + ''.join('%.10g,%.10g,%.10g\n' % r for r in rows))


def keepRecord(runDir, records, runId, declaration=None):
    """The record of the finished run in runDir as records/runs/<runId> (writeRecord)."""
    return writeRecord(runDir, recordPath(records, runId), declaration)


def writeIndex(records, info):
    """records/study.json: the study's description as the aggregation reads it, without the paths of
    the machine that ran it."""
    os.makedirs(records, exist_ok=True)
    keep = {k: v for k, v in info.items() if k not in ('script', 'packings', 'lines')}  # lines: of one start
    keep['table'] = os.path.basename(info['table'])
    writeAtomic(os.path.join(records, 'study.json'), json.dumps(keep, indent=1))
