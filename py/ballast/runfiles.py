"""The files of runs and studies, below both: written atomically and synced (on disk before their name
is), figures saved the same way, identified by sha1 (a table, the code of a run), read back (a summary,
a column, the state a killed run left); the test of a finished run. No YADE."""
import hashlib
import json
import math
import os
import uuid


def column(frame, name):
    """A column of a DataFrame (a run's CSV file) as a float array."""
    return frame[name].to_numpy(dtype=float)


def sha1(data):
    return hashlib.sha1(data if isinstance(data, bytes) else data.encode()).hexdigest()


def strictJson(value):
    """`value` with every float that is not finite (NaN, inf) as None: JSON has no NaN, and strict readers
    (jq, JavaScript, json.loads with parse_constant) refuse the NaN Python's json writes."""
    if isinstance(value, dict):
        return {k: strictJson(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [strictJson(v) for v in value]
    return None if isinstance(value, float) and not math.isfinite(value) else value


def writeAtomic(path, data):
    """Readers never see half a file (a status.csv being written, a packing being shipped)."""
    tmp = '%s.%d.%s.tmp' % (path, os.getpid(), uuid.uuid4().hex[:6])
    with open(tmp, 'wb' if isinstance(data, bytes) else 'w') as fh:
        fh.write(data)
        fh.flush()
        os.fsync(fh.fileno())
    os.replace(tmp, path)
    syncDir(os.path.dirname(path) or '.')


def _fsync(path, flags=0):
    fd = os.open(path, os.O_RDONLY | flags)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def syncDir(path):
    """fsync a directory: the names created, renamed or removed in it are on disk."""
    _fsync(path, os.O_DIRECTORY)


def syncTree(path):
    """fsync a file, or every file and directory below a directory, the directory last."""
    if not os.path.isdir(path):
        _fsync(path)
        return
    for d, dirs, names in os.walk(path, topdown=False):
        for n in names:
            syncTree(os.path.join(d, n))
        syncDir(d)


def moveSynced(src, dst):
    """os.replace that a crash cannot undo halfway: what src holds is on disk before dst names it,
    and the new name is on disk when this returns (a finished run is never an empty or cut file)."""
    syncTree(src)
    os.replace(src, dst)
    syncDir(os.path.dirname(dst) or '.')


def readSummary(runDir):
    """The one test of a finished run, for the study (which runs it skips) and the aggregation
    (which runs it reads) alike: runDir/summary.json parses as a JSON object. Returns (summary,
    None), or (None, why not)."""
    try:
        with open(os.path.join(runDir, 'summary.json')) as fh:
            summary = json.load(fh)
    except FileNotFoundError:
        return None, 'no summary.json'
    except OSError as e:
        return None, 'summary.json unreadable: %s' % e.strerror
    except ValueError as e:
        return None, 'summary.json is not JSON (cut short?): %s' % e
    if not isinstance(summary, dict):
        return None, 'summary.json holds a %s, not a JSON object' % type(summary).__name__
    return summary, None


def packageSha1():
    """sha1 of the ballast package this process imports, as installed now: its .py files and the
    compiled core (_ballast*.so), with their paths (read every time, a few ms: a worker outlives
    a reinstall)."""
    import ballast
    top = os.path.dirname(os.path.abspath(ballast.__file__))
    h = hashlib.sha1()
    for d, dirs, names in os.walk(top):
        dirs[:] = sorted(x for x in dirs if x != '__pycache__')  # in place: walk in a fixed order
        for n in sorted(names):
            if n.endswith('.py') or (n.startswith('_ballast') and n.endswith('.so')):
                path = os.path.join(d, n)
                h.update(os.path.relpath(path, top).encode() + b'\0')
                with open(path, 'rb') as fh:
                    h.update(fh.read())
    return h.hexdigest()


def codeSha1(scriptText):
    """What identifies the code that decides a run's result: the script's text and the installed
    ballast package (row.json's codeSha1)."""
    return sha1(sha1(scriptText) + packageSha1())


def readFiles(top):
    """{relative path: bytes} of every file below top (a run's output sent back over Dask)."""
    files = {}
    for d, _, names in os.walk(top):
        for n in names:
            p = os.path.join(d, n)
            with open(p, 'rb') as fh:
                files[os.path.relpath(p, top)] = fh.read()
    return files


def saveFigure(fig, path, dpi=120):
    """A matplotlib figure as a PNG at path, written atomically (writeAtomic); the figure closed."""
    import io
    import matplotlib.pyplot as plt
    buf = io.BytesIO()
    fig.savefig(buf, dpi=dpi, format='png')
    plt.close(fig)
    writeAtomic(path, buf.getvalue())


def plainLogTicks(ax, axes='x'):
    """A log axis (`axes`: 'x', 'y' or 'xy') labelled in plain numbers: 1, 2, 3, 5, 10, 20, ... over at most 2.5
    decades (matplotlib's default gives 2x10^0, 3x10^0 there, or labels only a few minor ticks within a decade), the
    decades only (1, 10, 100, ...) over more; the other ticks unlabelled."""
    import math
    from matplotlib.ticker import FuncFormatter

    def formatter(limits):
        def label(v, _):
            if not v > 0:
                return ''
            lo, hi = limits()
            if abs(math.log10(v) - round(math.log10(v))) < 1e-9:
                return '%g' % v
            few = lo > 0 and math.log10(hi / lo) <= 2.5
            # a tick whose mantissa is 2, 3 or 5 exactly: one at 1.6 or 1.8 (within a decade) rounds to 2, and is not
            d = v / 10 ** math.floor(math.log10(v))
            return '%g' % v if few and min(abs(d - k) for k in (2, 3, 5)) < 1e-9 else ''
        return FuncFormatter(label)
    for name in axes:
        axis, limits = (ax.xaxis, ax.get_xlim) if name == 'x' else (ax.yaxis, ax.get_ylim)
        axis.set_major_formatter(formatter(limits))
        axis.set_minor_formatter(formatter(limits))


def runStatus(runDir):
    """run.json of a run's folder (what :meth:`ballast.experiments.base.Experiment.markRunning` and its saves
    write) as a dict, or None when there is none or it does not parse."""
    try:
        with open(os.path.join(runDir, 'run.json')) as fh:
            doc = json.load(fh)
    except (OSError, ValueError):
        return None
    return doc if isinstance(doc, dict) else None


def killedRunState(runDir):
    """The state a killed run saved last in its folder, to go on from: run.json says 'running' and its
    lastState is a file there. None otherwise (no folder, a finished run, no state saved yet). Whether the
    run's process is gone is the caller's to know (a runner's lock, the pid in run.json)."""
    doc = runStatus(runDir)
    if doc is None or doc.get('status') != 'running' or not doc.get('lastState'):
        return None
    path = os.path.join(runDir, os.path.basename(doc['lastState']))
    return path if os.path.isfile(path) else None
