"""Files of a study: written atomically, and identified by sha1 (a table, the code of a run)."""
import hashlib
import os
import uuid


def sha1(data):
    return hashlib.sha1(data if isinstance(data, bytes) else data.encode()).hexdigest()


def writeAtomic(path, data):
    """Readers never see half a file (a status.csv being written, a packing being shipped)."""
    tmp = '%s.%d.%s.tmp' % (path, os.getpid(), uuid.uuid4().hex[:6])
    with open(tmp, 'wb' if isinstance(data, bytes) else 'w') as fh:
        fh.write(data)
    os.replace(tmp, path)


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
