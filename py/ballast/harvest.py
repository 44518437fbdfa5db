"""What the engines read from YADE at each check, read in C++ wherever YADE offers it.

* The grain table (ids, radii, group masks of the dynamic spheres) is cached and rebuilt only when
  the scene changed: its signature is the body count and ``utils.getSpheresVolume()`` (both C++), so
  any added, erased or resized sphere invalidates it, and so does O.iter going back (O.reset, O.load). The engines update it in place after their own
  changes. After changing which bodies are dynamic by hand, call :func:`refresh`.
* Fabric stresses come from ``utils.bodyStressTensors()`` (YADE's C++ Love-Weber stress per body,
  eq. 3), converted to one NumPy array in C++ (``ballast.matricesToArray``).
* Contact data for abrasion (normal force, overlap) has no C++ accessor in YADE 2023.02a; it is read
  in one list comprehension over the real interactions.
"""
import numpy as np
from yade import O, utils
from yade.wrapper import Sphere

from . import _ballast


class GrainTable:
    """Dynamic, free (not clumped) spheres of the scene: ``ids``, ``radii`` [m], ``masks``; and for
    every body id ``radiusById`` [m] (0 for non-spheres, i.e. walls and facets)."""

    def __init__(self):
        ids, radii, masks = [], [], []
        self.radiusById = np.zeros(len(O.bodies))
        for b in O.bodies:
            if b is None or not isinstance(b.shape, Sphere):
                continue
            self.radiusById[b.id] = b.shape.radius
            if b.dynamic and not b.isClumpMember:
                ids.append(b.id)
                radii.append(b.shape.radius)
                masks.append(b.groupMask)
        self.ids = np.array(ids, dtype=np.int64)
        self.radii = np.array(radii, dtype=float)
        self.masks = np.array(masks, dtype=np.int64)
        self._sign()

    def _sign(self):
        self.signature = _signature()
        self.iter = O.iter
        self._selections = {}

    def select(self, mask):
        """Indices into ids of the grains a mask selects (0: all)."""
        sel = self._selections.get(mask)
        if sel is None:
            sel = np.arange(len(self.ids)) if mask == 0 else np.flatnonzero(self.masks & mask)
            self._selections[mask] = sel
        return sel

    def replaced(self, oldId, newIds, newRadii, mask):
        """Grain oldId erased, fragments newIds (radii newRadii) added."""
        keep = self.ids != oldId
        self.ids = np.concatenate([self.ids[keep], np.asarray(newIds, dtype=np.int64)])
        self.radii = np.concatenate([self.radii[keep], np.asarray(newRadii, dtype=float)])
        self.masks = np.concatenate([self.masks[keep], np.full(len(newIds), mask, dtype=np.int64)])
        grow = max(newIds) + 1 - len(self.radiusById) if len(newIds) else 0
        if grow > 0:
            self.radiusById = np.concatenate([self.radiusById, np.zeros(grow)])
        self.radiusById[oldId] = 0.0
        self.radiusById[np.asarray(newIds, dtype=np.int64)] = newRadii

    def resized(self, bid, radius):
        self.radii[self.ids == bid] = radius
        self.radiusById[bid] = radius

    def commit(self):
        """Call after the engine's own changes: the table is current again."""
        self._sign()


_table = None


def grains():
    """The current grain table, rebuilt only if the scene changed since it was made."""
    global _table
    if _table is None or _table.signature != _signature() or O.iter < _table.iter:
        _table = GrainTable()
    else:
        _table.iter = O.iter
    return _table


def _signature():
    return len(O.bodies), utils.getSpheresVolume()


def refresh():
    """Forget the cached grain table (after changing bodies' dynamic flags or masks by hand)."""
    global _table
    _table = None


def stresses(ids):
    """Fabric stress tensors (eq. 3) of the bodies ids, (n,3,3) [Pa], compression negative."""
    return _ballast.matricesToArray(utils.bodyStressTensors())[ids]


def contacts():
    """Real interactions as arrays: id1, id2 (int64), Fn [N] (compression positive), uN [m]."""
    rows = [(i.id1, i.id2, i.phys.normalForce.dot(i.geom.normal), i.geom.penetrationDepth)
            for i in O.interactions.all(True)]
    if not rows:
        return np.zeros(0, np.int64), np.zeros(0, np.int64), np.zeros(0), np.zeros(0)
    a = np.array(rows)
    return a[:, 0].astype(np.int64), a[:, 1].astype(np.int64), a[:, 2], a[:, 3]
