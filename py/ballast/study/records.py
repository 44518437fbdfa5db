"""Compact records of finished runs, kept in the repository so that a study outlives the session and
the machine that ran it (issue 14, item 4).

A record folder (``scripts/study.py run TABLE --records DIR``, for example ``docs/studies/<study>``) is a
study directory that :class:`ballast.study.StudyData` and ``scripts/aggregate.py`` read as they read
the full one:

    study.json              the rows of the table (run ids, cells), as in the study directory
    runs/<run id>/          per finished run, a few tens of kB:
        summary.json        the run's summary.json as written
        row.json            the runner's row.json (table row, code sha1, host, command, duration)
        fd.csv              fd.csv thinned to at most MAX_FD_ROWS rows (:func:`thinCurve`), same columns
        checks.csv          the per-check log thinned (:func:`thinChecks`): every check where a grain
                            crushed, the two around half the peak load (t = 1/(4f)) and the largest
                            stress ratio to 1/200 of its range
        crushes.csv         per crush (events.csv): t [s], the grain's radius [m] and its ratio, the
                            criterion's stress over the strength it crushed at [-]
        record.json         what was left out: rows of fd.csv and checks.csv, the largest stress ratio
                            of all checks
        psd.csv, cycles.csv copied if the run wrote them

The study runner skips a row whose record exists (the same test as for a finished run: its
summary.json parses), so a session runs a slice, commits the records, and the next one, on any
machine, carries on with the rest. The raw results stay out of git.
"""
import csv
import io
import json
import os
import shutil
import uuid

import numpy as np

from ..oedometer.loadcurve import halfLoadTime
from .files import moveSynced, readSummary, writeAtomic

MAX_FD_ROWS = 600          # rows of a recorded F-delta curve [-]: ~40 kB, enough for the paper's figures
MAX_CHECK_ROWS = 400       # rows of a recorded per-check log [-]
COPIED = ('summary.json', 'row.json', 'psd.csv', 'cycles.csv')
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
                     list(np.flatnonzero(np.asarray(columns['nCrushed']) > 0)) + around, maxRows + len(around))


def readCsv(path):
    """(header, rows as lists of strings) of a CSV file."""
    with open(path, newline='') as fh:
        rows = list(csv.reader(fh))
    return rows[0], rows[1:]


def csvText(header, rows):
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator='\n')
    w.writerow(header)
    w.writerows(rows)
    return buf.getvalue()


def crushTable(runDir):
    """(t [s], radius [m], ratio [-]) arrays, one entry per crush of a run folder (events.csv) or a record
    (crushes.csv); ratio = the criterion's stress / the strength when the check crushed the grain. None
    without either file."""
    for name in ('crushes.csv', 'events.csv'):
        path = os.path.join(runDir, name)
        if os.path.isfile(path):
            header, rows = readCsv(path)
            k = {h: i for i, h in enumerate(header)}
            if name == 'events.csv':
                rows = [r for r in rows if r[k['kind']] == 'crush']
            t, radius = (np.array([float(r[k[c]]) for r in rows]) for c in ('t', 'radius'))
            ratio = np.array([float(r[k['ratio']]) if 'ratio' in k else float(r[k['value']]) / float(r[k['strength']])
                              for r in rows])
            return t, radius, ratio
    return None


def keepRecord(runDir, records, runId):
    """Writes the record of the finished run in runDir to records/runs/<runId> (replacing an older one
    whole: it appears only once complete). Returns the record's folder."""
    summary, why = readSummary(runDir)
    if summary is None:
        raise ValueError('%s is not a finished run: %s' % (runDir, why))
    dest = recordPath(records, runId)
    os.makedirs(os.path.dirname(dest), exist_ok=True)
    tmp = '%s.%s.tmp' % (dest, uuid.uuid4().hex[:6])
    os.makedirs(tmp)
    info = {'runId': runId}
    for name in COPIED:
        if os.path.isfile(os.path.join(runDir, name)):
            shutil.copyfile(os.path.join(runDir, name), os.path.join(tmp, name))
    fd = os.path.join(runDir, 'fd.csv')
    if os.path.isfile(fd):
        header, rows = readCsv(fd)
        cols = {h: np.array([float(r[k]) if r[k] else np.nan for r in rows]) for k, h in enumerate(header)}
        kept = thinFd(cols)
        writeAtomic(os.path.join(tmp, 'fd.csv'), csvText(header, [rows[i] for i in kept]))
        info['fdRows'] = {'run': len(rows), 'record': int(len(kept))}
    checks = os.path.join(runDir, 'checks.csv')
    if os.path.isfile(checks):
        header, rows = readCsv(checks)
        cols = {h: np.array([float(r[k]) for r in rows]) for k, h in enumerate(header)}
        f = (summary.get('params') or {}).get('f')
        kept = thinChecks(cols, times=[halfLoadTime(float(f))] if f else ()) if rows else []
        writeAtomic(os.path.join(tmp, 'checks.csv'), csvText(header, [rows[i] for i in kept]))
        info['checks'] = {'run': len(rows), 'record': int(len(kept)), 'crushing': int(np.sum(cols['nCrushed'] > 0)) if rows else 0,
                          'maxStressRatio': float(np.max(cols['maxStressRatio'])) if rows else None}
    crushes = crushTable(runDir)
    if crushes is not None:
        writeAtomic(os.path.join(tmp, 'crushes.csv'), csvText(['t', 'radius', 'ratio'], [
            ['%.10g' % x for x in row] for row in zip(*crushes)]))
    writeAtomic(os.path.join(tmp, 'record.json'), json.dumps(info, indent=1))
    if os.path.isdir(dest):
        shutil.rmtree(dest)
    moveSynced(tmp, dest)
    return dest


def writeIndex(records, info):
    """records/study.json: the study's description as the aggregation reads it, without the paths of
    the machine that ran it."""
    os.makedirs(records, exist_ok=True)
    keep = {k: v for k, v in info.items() if k not in ('script', 'packings')}
    keep['table'] = os.path.basename(info['table'])
    writeAtomic(os.path.join(records, 'study.json'), json.dumps(keep, indent=1))
