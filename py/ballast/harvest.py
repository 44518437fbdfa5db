"""What the engines read from YADE at each check, read in C++ wherever YADE offers it. What a grain is
(which bodies, their radius, their stress) is the scene's grain kind's answer (:mod:`ballast.grainkinds`).

* The grain table (ids, equivalent radii, group masks of the dynamic grains) is cached and rebuilt only
  when the scene changed: its signature is the scene's epoch (:func:`ballast.runtime.epoch`, new after
  O.reset() or O.load()), the body count, the kind and the kind's C++ signature (for spheres
  ``utils.getSpheresVolume()``), so any added, erased or resized grain invalidates it, and so does O.iter
  going back (O.load). The engines update it in place after their own changes. After changing which
  bodies are dynamic by hand, call :func:`refresh`.
* Fabric stresses come from the kind (spheres: ``utils.bodyStressTensors()``, YADE's C++ Love-Weber
  stress per body, eq. 3), converted to one NumPy array in C++ (``ballast.matricesToArray``).
* Contact data for abrasion (normal force, overlap) has no C++ accessor in YADE 2023.02a; it is read
  in one list comprehension, over all real interactions (:func:`contacts`) or only over those of a
  few bodies (:func:`contactsOf`) when a bound has ruled the others out.
* The stress tensors of one step are cached, so two engines checking at the same step read them once.
"""
import numpy as np
from yade import O, utils
from yade.wrapper import Sphere

from . import _ballast, grainkinds, runtime


class GrainTable:
    """The dynamic grains of the scene's kind (``kind``): ``ids``, equivalent radii ``radii`` [m], ``masks``;
    and, for the contact laws, every body id's ``radiusById`` [m]: the radius of a spherical body (a grain's
    sphere, a clump member, a membrane's node), 0 for a flat one (walls, facets, boxes), with the materials of
    both sets (``sphereMaterials``, ``otherMaterials``)."""

    def __init__(self):
        self.kind = kind = grainkinds.current()
        ids, masks, rows = [], [], []
        self.radiusById = np.zeros(len(O.bodies))
        self.sphereMaterials, self.otherMaterials = {}, {}   # the bodies' own material objects (see _material)
        row = -1   # the body's row among the bodies there are (positions() reads them in that order)
        for b in O.bodies:
            if b is None:
                continue
            row += 1
            if isinstance(b.shape, Sphere):  # the contact's geometry (Ig2_*_Sphere), whatever the grain kind
                _material(self.sphereMaterials, b.material)
                self.radiusById[b.id] = b.shape.radius
            elif not b.isClump:  # a clump body touches nothing: its members do
                _material(self.otherMaterials, b.material)
            if b.dynamic and kind.isGrain(b):
                ids.append(b.id)
                masks.append(b.groupMask)
                rows.append(row)
        self.ids = np.array(ids, dtype=np.int64)
        self.rows = np.array(rows, dtype=np.int64)
        self.nBodies = row + 1   # the bodies there were
        self.radii = np.asarray(kind.radii(self.ids), dtype=float)
        self.masks = np.array(masks, dtype=np.int64)
        self._sign()

    def _sign(self):
        self.signature = _signature()
        self.iter = O.iter
        self._selections = {}
        self._stepRadii = None

    def stepRadii(self):
        """The radius [m] of each grain's own P-wave step (GrainKind.stepRadii: a clump's smallest member) in ids'
        order: radii where a grain is one sphere, else the kind's, read once until the grains change."""
        if self.kind.oneSphere:
            return self.radii
        if self._stepRadii is None:
            self._stepRadii = np.asarray(self.kind.stepRadii(self.ids), dtype=float)
        return self._stepRadii

    def select(self, mask):
        """Indices into ids of the grains a mask selects (0: all)."""
        sel = self._selections.get(mask)
        if sel is None:
            sel = np.arange(len(self.ids)) if mask == 0 else np.flatnonzero(self.masks & mask)
            self._selections[mask] = sel
        return sel

    def replaced(self, oldId, newIds, newRadii, mask):
        """Grain oldId erased, fragments newIds (spheres of radii newRadii [m], group mask mask) added."""
        keep = self.ids != oldId
        self._stepRadii = None
        self.ids = np.concatenate([self.ids[keep], np.asarray(newIds, dtype=np.int64)])
        self.radii = np.concatenate([self.radii[keep], np.asarray(newRadii, dtype=float)])
        self.masks = np.concatenate([self.masks[keep], np.full(len(newIds), mask, dtype=np.int64)])
        grow = max(newIds) + 1 - len(self.radiusById) if len(newIds) else 0
        if grow > 0:
            self.radiusById = np.concatenate([self.radiusById, np.zeros(grow)])
        self.radiusById[oldId] = 0.0
        self.radiusById[np.asarray(newIds, dtype=np.int64)] = newRadii
        for i in newIds:
            _material(self.sphereMaterials, O.bodies[int(i)].material)

    def resized(self, bid, radius, sphere=None, sphereRadius=None):
        """Grain bid now of r_eq radius [m]; the sphere body whose radius changed, sphere (default: the grain, one
        sphere, then of radius), now of sphereRadius [m] (a worn clump member: the clump body keeps 0)."""
        self.radii[self.ids == bid] = radius
        self._stepRadii = None   # a worn member may be the clump's smallest now
        if sphere is None:
            self.radiusById[bid] = radius
        else:
            self.radiusById[sphere] = sphereRadius

    def commit(self):
        """Call after the engine's own changes: the table is current again, the step's caches not."""
        invalidate()
        self._sign()


def _material(known, m):
    """Keep the material object m of a body: by its id in O.materials, or, for a material never appended there
    (id -1, which O.materials[-1] would misread as the last one), by its moduli."""
    known.setdefault(m.id if m.id >= 0 else ('unlisted', m.young, m.poisson), m)


_table = None


def grains():
    """The current grain table, rebuilt only if the scene changed since it was made."""
    global _table
    if _table is None or _table.signature != _signature() or O.iter < _table.iter:
        _table = GrainTable()
    else:
        _table.iter = O.iter
    return _table


_sig = (None, None)           # ((scene epoch, O.iter, body count, kind), signature)
_stressCache = (None, None)  # ((O.iter, scene signature), all bodies' tensors)


def _signature():
    """Scene epoch (ballast.runtime: new after O.reset() or O.load()), body count, the grain kind and its C++
    signature, computed once per step: both engines of a step share it. Changes within a step are the
    engines' own, and they call invalidate()."""
    global _sig
    kind = grainkinds.current()  # first: after O.load it restores the scene, which moves the epoch
    key = (runtime.epoch(), O.iter, len(O.bodies), kind.name)  # the kind: grainkinds.use() within a step
    if _sig[0] != key:
        _sig = (key, (key[0], len(O.bodies), kind.name, kind.signature()))
    return _sig[1]


def invalidate():
    """Forget what was read at this step (the engines call it after changing the scene)."""
    global _sig, _stressCache
    _sig = _stressCache = (None, None)


def refresh():
    """Forget the cached grain table and this step's reads: call it after changing bodies by hand
    (dynamic flags, masks, or radii without a step in between)."""
    global _table
    _table = None
    invalidate()



def stresses(ids):
    """Fabric stress tensors (eq. 3) of the grains ids, (n,3,3) [Pa], compression negative (the kind's)."""
    global _stressCache
    key = (O.iter, _signature())
    if _stressCache[0] != key:
        _stressCache = (key, grainkinds.current().stressTensors())
    return _stressCache[1][ids]


def bodyPositions():
    """(n, 3) centres [m] of every body there is (None skipped), in id order, read in C++ (YADE's
    utils.coordsAndDisplacements, an axis at a time): no Python loop over the bodies."""
    return np.array([utils.coordsAndDisplacements(axis)[0] for axis in range(3)], dtype=float).reshape(3, -1).T


def positions():
    """(grain table, (n, 3) centres [m] of its grains), read in C++: YADE's utils.coordsAndDisplacements gives an
    axis of every body there is, in id order, without a Python loop over the bodies (a membrane update read them
    one by one in 4 ms of its 13 for 1 300 grains). A table that no longer matches the bodies (one erased or
    added by hand within this step) is rebuilt."""
    x = bodyPositions()
    table = grains()
    if table.nBodies != len(x):
        refresh()
        table = grains()
    return table, x[table.rows] if len(table.rows) else np.zeros((0, 3))


def _arrays(rows):
    if not rows:
        return np.zeros(0, np.int64), np.zeros(0, np.int64), np.zeros(0), np.zeros(0)
    a = np.array(rows)
    return a[:, 0].astype(np.int64), a[:, 1].astype(np.int64), a[:, 2], a[:, 3]


def contacts():
    """Real interactions as arrays: id1, id2 (int64), Fn [N] (compression positive), uN [m]."""
    return _arrays([(i.id1, i.id2, i.phys.normalForce.dot(i.geom.normal), i.geom.penetrationDepth)
                    for i in O.interactions.all(True)])


def contactsOf(ids):
    """As :func:`contacts`, for the real interactions of the bodies ids only (each contact once), read the same
    way, so that eq. 7 gives the same bits as after a full read."""
    rows = [(i.id1, i.id2, i.phys.normalForce.dot(i.geom.normal), i.geom.penetrationDepth)
            for b in ids.tolist() for i in O.interactions.withBody(b)]
    id1, id2, Fn, uN = _arrays(rows)
    _, first = np.unique(id1 * (len(O.bodies) + 1) + id2, return_index=True)  # a contact of two candidates comes twice
    return id1[first], id2[first], Fn[first], uN[first]


# Contact laws for which the prefilter bounds eq. 7: (Law2, Ip2) by name.
LAWS = {'hertz': ('Law2_ScGeom_MindlinPhys_Mindlin', 'Ip2_FrictMat_FrictMat_MindlinPhys'),
        'linear': ('Law2_ScGeom_FrictPhys_CundallStrack', 'Ip2_FrictMat_FrictMat_FrictPhys')}


def largestContactForces(ids):
    """The largest normal contact force [N] of each of the bodies `ids` (0 without a contact), over all real
    interactions, read in one pass (:func:`contacts`)."""
    id1, id2, Fn, _ = contacts()
    ids = np.asarray(ids, dtype=np.int64)
    n = max(int(ids.max(initial=-1)), int(id1.max(initial=-1)), int(id2.max(initial=-1))) + 1
    best = np.zeros(n)
    np.maximum.at(best, id1, Fn)
    np.maximum.at(best, id2, Fn)
    return best[ids]


def contactLaw():
    """('hertz' or 'linear', None) when every contact of the scene follows that law, purely elastic in
    the normal direction, with the stiffness its materials give; else (None, the reason why not)."""
    from yade.wrapper import InteractionLoop
    loops = [e for e in O.engines if isinstance(e, InteractionLoop)]
    if len(loops) != 1:
        return None, 'expected one InteractionLoop in O.engines, found %d' % len(loops)
    laws = [type(f).__name__ for f in loops[0].lawDispatcher.functors]
    ip2s = [type(f).__name__ for f in loops[0].physDispatcher.functors]
    name = next((k for k, v in LAWS.items() if [v[0]] == laws and [v[1]] == ip2s), None)
    if name is None:
        return None, 'contact law %s with %s, not one of %s' % (
            '+'.join(laws), '+'.join(ip2s), '; '.join('%s with %s' % v for v in LAWS.values()))
    law, ip2 = loops[0].lawDispatcher.functors[0], loops[0].physDispatcher.functors[0]
    if name == 'hertz':
        if getattr(law, 'includeAdhesion', False) or getattr(ip2, 'gamma', 0) != 0:
            return None, 'adhesive Mindlin contacts (gamma or includeAdhesion set)'
        if getattr(ip2, 'betan', None) is not None or getattr(ip2, 'en', None) is not None:
            return None, 'viscous normal damping in the Mindlin contacts (betan or en set)'
    elif getattr(ip2, 'kn', None) is not None:
        return None, 'normal stiffness set by Ip2_FrictMat_FrictMat_FrictPhys.kn, not by the materials'
    return name, None


def moduli(table):
    """Largest Hertz contact modulus E* [Pa] between sphere materials, and between a sphere material
    and the material of a non-sphere body (walls, facets); 0 where there is no such pair."""
    def props(materials):
        m = list(materials.values())
        return (np.array([x.young for x in m], dtype=float), np.array([x.poisson for x in m], dtype=float))

    def largest(a, b):
        (E1, n1), (E2, n2) = a, b
        if len(E1) == 0 or len(E2) == 0:
            return 0.0
        k, j = len(E1), len(E2)
        return float(np.max(_ballast.contactModulus(np.repeat(E1, j), np.repeat(n1, j), np.tile(E2, k), np.tile(n2, k))))
    s, o = props(table.sphereMaterials), props(table.otherMaterials)
    return largest(s, s), largest(s, o)


def linearBound(table):
    """Largest p0 of eq. 7 [Pa] any contact can have under the linear law: p0 = 3 Fn / (2 pi R uN) with
    Fn = kn uN, so p0 = 3 kn / (2 pi R) whatever the load. YADE's FrictPhys gives kn = 2 E1 r1 E2 r2 /
    (E1 r1 + E2 r2), so between spheres (R = r1 r2 / (r1 + r2)) p0 = 3 E1 E2 (r1 + r2) / (pi (E1 r1 +
    E2 r2)) <= 3 max(E1, E2) / pi, and with a wall or facet (YADE takes the sphere's radius for both
    sides; eq. 7 takes R = r) p0 = 3 E1 E2 / (pi (E1 + E2)). 0 where there is no such pair."""
    Es = [m.young for m in table.sphereMaterials.values()]
    Eo = [m.young for m in table.otherMaterials.values()]
    ss = 3 * max(Es) / np.pi if Es else 0.0
    sw = max((3 * a * b / (np.pi * (a + b)) for a in Es for b in Eo), default=0.0)
    return max(ss, sw)
