"""The YADE engines of the crushable-ballast model (Dubina & Eliáš, sections 2 and 3):
:class:`BallastCrushEngine` (:mod:`.crush`) and :class:`BallastAbrasionEngine` (:mod:`.abrasion`) on
the base :mod:`.base`, and :class:`PolyhedronCrushEngine` (:mod:`.polyhedra`: polyhedron grains crushed by YADE's
PolyhedraSplitter); fatigue, what follows a replacement and the abrasion prefilter are components
(:mod:`.fatigue`, :mod:`.replacements`, :mod:`.prefilter`).

Both are Python subclasses of YADE's ``PyRunner``: put them in ``O.engines`` after
``NewtonIntegrator``. ``O.save()`` keeps their state with the scene (:mod:`ballast.runtime`); after
``O.load()`` they come back at their next check, or at once with :func:`restore`, and their labels
point to them again.
"""
from .. import runtime
from .abrasion import BallastAbrasionEngine
from .base import BallastEngine
from .crush import BallastCrushEngine
from .polyhedra import PolyhedronCrushEngine

__all__ = ['BallastCrushEngine', 'BallastAbrasionEngine', 'BallastEngine', 'PolyhedronCrushEngine', 'restore']


def restore():
    """Rebuild the objects of a loaded scene now (they also come back at their next check). Returns the
    ballast engines in O.engines."""
    runtime.restore()
    from yade import O
    return [e for e in O.engines if isinstance(e, BallastEngine)]


def _fire(key):
    """The command of engines saved by format 1 (commit ba51e1d and before): refused in one line."""
    runtime.checkFormat()
    raise runtime.StateFormatError('ballast: this engine (key %r) was saved by an older version; continue it with '
                                   'commit ba51e1d or run it again' % key)
