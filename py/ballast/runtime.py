"""How the package's Python objects live inside a YADE scene: one registry, one PyRunner dispatcher,
one persistence protocol, one JSON document under one ``O.tags`` key.

YADE runs Python only through a ``PyRunner``'s command string, and ``O.save()`` keeps only the C++
fields of the engines. So every object that acts during a run (an engine, a piece of an experiment,
the experiment itself) is registered here:

* ``register(obj)`` gives it an id in the current scene; ``callback(obj, method, **periodic)`` makes
  a PyRunner that calls ``obj.method()``; an engine that is itself a PyRunner (:class:`Runner`) gets
  the command from :func:`command`. Every command is ``fire(id, method)`` of this module.
* persistence: a class declares a stable type name with :func:`persistent` and has ``state()`` (a
  JSON-able dict) and ``fromState(state)``. ``O.save``/``O.saveTmp`` write the state of every live
  object into ``O.tags['ballast']`` first (the runtime wraps them); nothing is written while running.
* after ``O.load``/``O.loadTmp``/``O.reset`` (wrapped too) the live objects belong to another scene.
  The next ``fire`` (or :func:`restore`) rebuilds the objects of the loaded scene from its document
  and puts full engines and callbacks back in ``O.engines`` in place of the plain PyRunners YADE
  gives back. That is the only path by which objects come back.

A state saved by an older version (before this document, several ``ballast.*`` keys) is refused with
:class:`StateFormatError`: one line saying why.
"""
import base64
import builtins
import json
import re
import sys
import uuid

import numpy as np
from yade import O
from yade.wrapper import Omega, PyRunner

TAG = 'ballast'          # the one O.tags key of the package
FORMAT = 2               # version of the document; 1 was the per-object keys of commit ba51e1d and before
COMMAND = "import ballast.runtime as _r; _r.fire(%r, %r)"
_COMMAND_RE = re.compile(r"^import ballast\.runtime as _r; _r\.fire\('([^']*)', '([^']*)'\)$")
# PeriodicEngine's settings and counters, copied from a loaded PyRunner to the object replacing it;
# the periods first (an engine refuses all periods 0 on the way)
PERIODIC = ('realPeriod', 'virtPeriod', 'iterPeriod', 'nDo', 'initRun', 'firstIterRun', 'ompThreads', 'dead',
            'label', 'iterLast', 'virtLast', 'realLast', 'nDone')

_types = {}              # type name -> class


class StateFormatError(RuntimeError):
    """A scene whose saved state this version cannot continue."""


def persistent(name):
    """Class decorator: objects of the class can be saved in a scene and rebuilt under `name`."""
    def deco(cls):
        if _types.get(name, cls) is not cls:
            raise ValueError('persistent type name %r is taken by %s' % (name, _types[name].__qualname__))
        _types[name] = cls
        cls.persistentType = name
        return cls
    return deco


class Runner(PyRunner):
    """Base of the objects that are themselves engines in O.engines (a PyRunner whose command fires
    their method `fire`)."""


class Callback(PyRunner):
    """A PyRunner calling one method of a registered object (its command says which)."""


class _Scene:
    """The live objects of the current scene."""

    def __init__(self, token):
        self.token = token
        self.objects = {}     # id -> object
        self.ids = {}         # id(object) -> id


_scene = None            # the live scene, None after a load or reset until restored
_epoch = [0]             # incremented whenever the current scene changes (harvest's caches key on it)


def epoch():
    """A number that changes whenever the scene in O changes (reset, load, restore)."""
    return _epoch[0]


def _newScene():
    global _scene
    _scene = _Scene(uuid.uuid4().hex)
    _epoch[0] += 1
    return _scene


def current():
    """The live scene, restored from O.tags first if the scene was loaded, new if there is none."""
    if _scene is None:
        restore()
    return _scene if _scene is not None else _newScene()


def register(obj):
    """The id of obj in the current scene (given on first call)."""
    s = current()
    oid = s.ids.get(id(obj))
    if oid is None or s.objects.get(oid) is not obj:
        oid = uuid.uuid4().hex[:12]
        s.objects[oid], s.ids[id(obj)] = obj, oid
    return oid


def unregister(obj):
    """obj no longer lives in the scene (not saved, its callbacks fail)."""
    if _scene is not None:
        oid = _scene.ids.pop(id(obj), None)
        _scene.objects.pop(oid, None)


def command(obj, method):
    """The PyRunner command that calls obj.method() (obj registered)."""
    return COMMAND % (register(obj), method)


def callback(obj, method, **periodic):
    """A PyRunner (Callback) calling obj.method() with YADE's periodic settings (iterPeriod, virtPeriod, label...)."""
    return Callback(command=command(obj, method), **periodic)


def get(oid):
    """The live object with id `oid`, rebuilt from the saved document if the scene was loaded. An engine of the
    package built before this scene (before an O.reset(), as YADE's own engines may be) and put in its O.engines
    is adopted by it under its id."""
    s = current()
    obj = s.objects.get(oid)
    if obj is None:
        obj = _engineBuiltBefore(oid)
        if obj is not None:
            s.objects[oid], s.ids[id(obj)] = obj, oid
    if obj is None:
        raise RuntimeError('ballast: no object %r in this scene (O.tags[%r] does not hold it): its PyRunner belongs '
                           'to another scene' % (oid, TAG))
    return obj


def _engineBuiltBefore(oid):
    """The engine of the package (a Runner, a Python object) in this scene's O.engines whose command fires `oid`, or
    None."""
    for e in O.engines:
        if isinstance(e, Runner):
            m = _COMMAND_RE.match(e.command)
            if m and m.group(1) == oid:
                return e
    return None


def fire(oid, method):
    """What every command of the package calls. YADE turns an error inside a PyRunner into 'PyRunner error.':
    the cause is printed first, in one line."""
    try:
        obj = get(oid)
    except Exception as e:
        sys.stderr.write('%s: %s\n' % (type(e).__name__, e))
        raise
    getattr(obj, method)()


def document():
    """The document of the live scene: every object's type and state."""
    s = current()
    objects = {}
    while len(objects) < len(s.objects):  # a state may register the objects it refers to
        for oid, obj in list(s.objects.items()):
            if oid not in objects:
                objects[oid] = {'type': type(obj).persistentType, 'state': obj.state()}
    return {'format': FORMAT, 'token': s.token, 'objects': objects}


def flush():
    """The live objects' state into O.tags[TAG] (called before every save); first each object's optional
    beforeSave(), for what the scene must hold when it is saved."""
    if _scene is not None:
        for obj in list(_scene.objects.values()):
            if hasattr(obj, 'beforeSave'):
                obj.beforeSave()
        O.tags[TAG] = json.dumps(document())


def checkFormat():
    """Refuse a scene saved by an older version, with one line."""
    keys = O.tags.keys()
    old = sorted(k for k in keys if k.startswith(TAG + '.'))
    if old and TAG not in keys:
        raise StateFormatError('ballast: this state was saved by an older version (state format 1: O.tags keys %s; this '
                               'version reads format %d); continue it with commit ba51e1d or run it again'
                               % (', '.join(old[:3]) + (', ...' if len(old) > 3 else ''), FORMAT))


def _readDocument(text):
    """The saved document, checked for its shape; StateFormatError in one line if it is damaged."""
    def bad(why):
        raise StateFormatError('ballast: O.tags[%r] of this scene is damaged: %s' % (TAG, why))
    if not text.strip():
        bad('it is blank')
    try:
        doc = json.loads(text)
    except ValueError as e:
        bad('not a JSON document (%s)' % e)
    if not isinstance(doc, dict) or not isinstance(doc.get('objects'), dict) or not isinstance(doc.get('token'), str):
        bad('expected a JSON object with "format", "token" and "objects", got %.60s' % text.strip())
    for oid, entry in doc['objects'].items():
        if not isinstance(entry, dict) or not isinstance(entry.get('type'), str) or 'state' not in entry:
            bad('object %r is not {"type": ..., "state": ...}' % oid)
    return doc


def savedTypes():
    """The type names of the objects saved in the current scene's document (an empty set without one); not
    rebuilt. StateFormatError if the document is damaged."""
    if TAG not in O.tags.keys():
        return set()
    return {entry['type'] for entry in _readDocument(O.tags[TAG])['objects'].values()}


def restore():
    """Rebuild the objects saved in the current scene (if it is not live) and put them back in O.engines.
    Returns {id: object}."""
    global _scene
    if _scene is not None:
        return dict(_scene.objects)
    checkFormat()
    if TAG not in O.tags.keys():
        return {}
    doc = _readDocument(O.tags[TAG])
    if doc.get('format') != FORMAT:
        raise StateFormatError('ballast: this state has format %r; this version reads format %d' % (doc.get('format'),
                                                                                                  FORMAT))
    saved = doc['objects']
    s = _newScene()
    s.token = doc['token']
    pending = {}

    def build(oid):
        if oid in s.objects:
            return s.objects[oid]
        if oid in pending:
            raise RuntimeError('ballast: saved objects refer to each other in a circle (%s)' % oid)
        entry = saved[oid]
        cls = _types.get(entry['type'])
        if cls is None:
            raise StateFormatError('ballast: this state holds an object of type %r, unknown to this version'
                                   % entry['type'])
        pending[oid] = True
        try:
            obj = cls.fromState(entry['state'], _Resolver(build))
        except (KeyError, TypeError, ValueError, AttributeError, IndexError) as e:
            raise StateFormatError('ballast: O.tags[%r] is damaged: the saved %s %s cannot be rebuilt (%s: %s)'
                                   % (TAG, entry['type'], oid, type(e).__name__, e)) from None
        del pending[oid]
        for other in [k for k, o in s.objects.items() if o is obj]:  # an id its constructor registered
            del s.objects[other]
        s.objects[oid], s.ids[id(obj)] = obj, oid
        if isinstance(obj, Runner):
            PyRunner.__setattr__(obj, 'command', COMMAND % (oid, 'fire'))
        return obj

    for oid in saved:
        build(oid)
    _reattach(s)
    for obj in list(s.objects.values()):
        if hasattr(obj, 'restored'):
            obj.restored()
    return dict(s.objects)


class _Resolver:
    """Given to fromState: ``ref(oid)`` is the rebuilt object of another saved id."""

    def __init__(self, build):
        self._build = build

    def __call__(self, oid):
        return None if oid is None else self._build(oid)


def packArray(a):
    """An array of a saved state, bitwise: base64 of its float64 bytes (None stays None)."""
    return None if a is None else base64.b64encode(np.ascontiguousarray(a, dtype=float).tobytes()).decode('ascii')


def unpackArray(s):
    """packArray's text back as a flat float64 array (a copy, writable; None stays None)."""
    return None if s is None else np.frombuffer(base64.b64decode(s), dtype=float).copy()


def packRows(rows):
    """Rows of numbers (tuples of equal length; a column is of ints where the first row's is) as a saved
    state holds them: one packArray, bitwise. A long record packs in a tenth of the time JSON takes to
    write it as numbers, and compresses faster. Rows of unequal length, or a column begun with an int that
    holds a fraction, stay a list."""
    if not rows or len({len(r) for r in rows}) != 1:
        return [list(r) for r in rows]
    ints = [j for j, v in enumerate(rows[0]) if isinstance(v, (int, np.integer)) and not isinstance(v, bool)]
    a = np.array(rows, dtype=float)
    if not np.all(a[:, ints] == np.trunc(a[:, ints])):   # a column not of ints after all: kept as it is
        return [list(r) for r in rows]
    return {'shape': list(a.shape), 'ints': ints, 'data': packArray(a)}


def unpackRows(s):
    """packRows's value back as a list of tuples (ints where they were); a list (states of before) as tuples."""
    if isinstance(s, list):
        return [tuple(r) for r in s]
    a = unpackArray(s['data']).reshape(s['shape'])
    cells = a.astype(object)
    for j in s['ints']:
        cells[:, j] = [int(v) for v in a[:, j]]
    return [tuple(r) for r in cells.tolist()]


def fromAttributes(cls, s):
    """An object of `cls` whose state() is its attributes by name, back from that state (a persistent class's
    fromState in one line)."""
    obj = cls()
    for k, v in s.items():
        setattr(obj, k, v)
    return obj


def ref(obj):
    """What a state stores for a reference to another registered object (None stays None)."""
    return None if obj is None else register(obj)


def _reattach(s):
    """Full objects in O.engines in place of the plain PyRunners running the package's commands."""
    chain, changed = list(O.engines), False
    for k, e in enumerate(chain):
        m = _COMMAND_RE.match(e.command) if type(e) is PyRunner else None
        if m is None:
            continue
        oid, method = m.groups()
        obj = s.objects.get(oid)
        if obj is None:
            raise RuntimeError('ballast: O.engines[%d] calls object %r, which O.tags[%r] does not hold' % (k, oid, TAG))
        new = obj if isinstance(obj, Runner) and method == 'fire' else Callback(command=e.command)
        for name in PERIODIC:
            setattr(new, name, getattr(e, name))
        chain[k], changed = new, True
    if changed:
        O.engines = chain
        for e in chain:
            if isinstance(e, Runner) and e.label:
                setattr(builtins, e.label, e)


# ---------------------------------------------------------------- YADE's scene changes
def _wrap(name, before=None, after=None):
    original = getattr(Omega, name)

    def method(self, *args, **kw):
        if before:
            before()
        out = original(self, *args, **kw)
        if after:
            after()
        return out
    method.__name__, method.__doc__ = name, original.__doc__
    method._ballastOriginal = original
    setattr(Omega, name, method)


def saveAsYade(path):
    """O.save as YADE itself does it, without the flush of the package's objects into O.tags that the runtime
    adds to it (for a caller that has written O.tags itself: bench/bench_save.py)."""
    Omega.save._ballastOriginal(O, path)


def _forget():
    global _scene
    _scene = None
    _epoch[0] += 1


if not hasattr(Omega.save, '_ballastOriginal'):  # once per process
    for _n in ('save', 'saveTmp'):
        _wrap(_n, before=flush)
    for _n in ('load', 'loadTmp', 'reload', 'reset', 'resetThisScene', 'resetCurrentScene', 'resetAllScenes',
               'switchScene', 'switchToScene'):
        if hasattr(Omega, _n):
            _wrap(_n, after=_forget)
