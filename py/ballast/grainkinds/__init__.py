"""Grain kinds: what a grain is, asked by every piece of the package that reads or changes grains
(issue 44, item 3). Two kinds: :mod:`.sphere` (a grain is one YADE ``Sphere``, the paper's) and
:mod:`.clump` (a grain is a YADE clump of overlapping spheres shaped like ballast, issue 47) and :mod:`.polyhedron`
(a grain is one of YADE's convex polyhedra, crushed by its PolyhedraSplitter: issue 47, item 4); each is a
module here, registered with :func:`register`.

The interface (:class:`GrainKind`) answers, for the grains of the current scene:

* which bodies are grains: :meth:`~GrainKind.isGrain` (one body), :meth:`~GrainKind.bodies`,
  :meth:`~GrainKind.ids` (``O.bodies`` order, whether dynamic or not). Walls, facets, boxes (platens,
  sleepers) and a membrane's nodes are not: each kind says positively what its grains are, so an
  excluded body is excluded by its kind, never by a group mask;
* their geometry and inertia, as arrays over ids: centres [m], volumes [m^3], masses [kg], principal
  inertia [kg m^2], the equivalent radius r_eq [m] (of the sphere of the same volume), Young's moduli
  [Pa], the box each grain fills (:meth:`~GrainKind.bounds`: where a plate or a sleeper seats on it); what goes
  to a grading (sieve diameters, 2 r_eq [m]) and to VTK (a radius [m]);
* the stress of a grain (the Love-Weber fabric stress, eq. 3), as one array by body id read in C++,
  and a cheap C++ signature that changes whenever a grain is added, erased or resized (ballast.harvest
  caches on it);
* the changes the engines make: :meth:`~GrainKind.crush` (a crushed grain: by default erased and
  replaced by sphere fragments, :meth:`~GrainKind.replace`; a clump splits into pieces: :class:`Replaced`),
  :meth:`~GrainKind.resize` (grown or shrunk whole: :class:`Resized`), :meth:`~GrainKind.abrade` (a surface
  layer lost where eq. 7's pressure is: the grain, or a clump's member; :meth:`~GrainKind.abrasionUnits`), and
  :meth:`~GrainKind.grainOf`, the grain a contact's body belongs to.

Which kind a scene holds. :func:`current` is the default kind, 'sphere', unless :func:`use` chose
another for the scene; ``use`` registers a small persistent object (:class:`SceneKind`) through
:mod:`ballast.runtime`, so the choice is saved by ``O.save`` and comes back after ``O.load`` as every
other object of the package does (no other key in ``O.tags``, no lookup by name elsewhere). Why a
default rather than an object in every scene: a scene of spheres, i.e. every scene, stored sample and
saved state made before this layer, holds the same ``O.tags`` document as before, so they load as
they are and the outputs stay byte for byte; a kind that is not the default is saved with its scene
and cannot be lost. The kind is looked up again only when the scene changes (``runtime.epoch``).
"""
from collections import namedtuple

import numpy as np
from yade import O, utils

from .. import runtime
from ..geometry import equivalentRadius

DEFAULT = 'sphere'

# What replace() or crush() did: the new grains' ids, their r_eq [m] and group mask, the volume [m^3] and mass
# [kg] of the grain and of its fragments or pieces, the grain's volume over theirs [-] (the growth target; 1:
# nothing to regrow), and for a split clump a dict of what the split did (None otherwise).
Replaced = namedtuple('Replaced', 'ids radii mask volumeBefore volumeAfter massBefore massAfter volumeRatio split',
                      defaults=(None,))
# What resize() or abrade() did: r_eq before and after [m], the volume before [m^3], the mass before and after [kg],
# and the volume after [m^3] when the grain was not scaled whole (a worn clump member), None when it was (then it is
# the volume before times factor^3).
Resized = namedtuple('Resized', 'radiusBefore radiusAfter volumeBefore massBefore massAfter volumeAfter',
                     defaults=(None,))


class GrainKind:
    """The questions every kind answers. Arrays follow the order of the ids given; ids are body ids of
    grains (an int64 array or a list). The generic answers read the body's rigid-body State, valid for
    any kind; a kind overrides what depends on its shape."""

    name = None
    oneSphere = False   # whether a grain is one sphere, so its contacts have its radius (eq. 7's bounds)

    def isGrain(self, body):
        """Whether a body (a yade Body, not None) is a grain of this kind."""
        raise NotImplementedError

    def bodies(self):
        """The grains, in O.bodies order (dynamic or not). A loop over the bodies: not for every step."""
        return [b for b in O.bodies if b is not None and self.isGrain(b)]

    def ids(self):
        """Body ids of the grains, O.bodies order (int64)."""
        return np.array([b.id for b in self.bodies()], dtype=np.int64)

    def centres(self, ids):
        """(n, 3) centres of mass [m]."""
        return np.array([[p[0], p[1], p[2]] for p in (O.bodies[int(i)].state.pos for i in ids)],
                        dtype=float).reshape(-1, 3)

    def masses(self, ids):
        """Masses [kg] (YADE's, with any keep='mass' scaling of fragments)."""
        return np.array([O.bodies[int(i)].state.mass for i in ids], dtype=float)

    def inertias(self, ids):
        """(n, 3) principal moments of inertia [kg m^2], in each grain's own frame."""
        return np.array([[j[0], j[1], j[2]] for j in (O.bodies[int(i)].state.inertia for i in ids)],
                        dtype=float).reshape(-1, 3)

    def moduli(self, ids):
        """Young's modulus [Pa] of each grain's material (eq. 5's P-wave speed)."""
        return np.array([O.bodies[int(i)].material.young for i in ids], dtype=float)

    def volumes(self, ids):
        """Volumes [m^3]."""
        raise NotImplementedError

    def volume(self, bid):
        """Volume [m^3] of the grain bid, as a float (the engines' ledgers)."""
        return float(self.volumes([bid])[0])

    def radii(self, ids):
        """Equivalent radii r_eq [m]: of the sphere of the grain's volume."""
        return equivalentRadius(self.volumes(ids))

    def sieveDiameters(self, ids):
        """The size a sieve sees [m]: 2 r_eq (ballast.grading)."""
        return 2 * self.radii(ids)

    def vtkRadii(self, ids):
        """The radius VTK draws a grain with [m]: r_eq."""
        return self.radii(ids)

    def bounds(self, ids):
        """(lo, hi), each (n, 3) [m]: the axis-aligned box each grain fills, where a plate or a sleeper is seated on
        it; here its centre -+ r_eq (exact for a sphere; a kind whose grain is not its equivalent sphere overrides
        it)."""
        x, r = self.centres(ids), self.radii(ids)[:, None]
        return x - r, x + r

    def tops(self, ids):
        """The height of each grain's highest point [m] (bounds)."""
        return self.bounds(ids)[1][:, 2]

    def stepRadii(self, ids):
        """The radius [m] of each grain's own P-wave step r sqrt(rho / E) (eq. 5), the one density scaling sets: the
        radius YADE's PWaveTimeStep() reads for it. Default r_eq (a sphere's radius)."""
        return self.radii(ids)

    def pWaveTimeStep(self):
        """Eq. 5's critical step [s] of the scene's grains: YADE's PWaveTimeStep() (spheres, clump members)."""
        return utils.PWaveTimeStep()

    def signature(self):
        """A value compared for equality (C++, no loop in Python) that changes when a grain is added, erased or
        resized."""
        raise NotImplementedError

    def stressTensors(self):
        """Love-Weber fabric stress (eq. 3) [Pa] of every grain, an (len(O.bodies), 3, 3) array whose row
        bid is grain bid's (compression negative); rows of other bodies are not used."""
        raise NotImplementedError

    def grainOf(self, bodyIds):
        """The grain (body id) each body of a contact belongs to, an int64 array of bodyIds' shape."""
        raise NotImplementedError

    def replace(self, bid, fragments, keepMass):
        """Grain bid erased and replaced by spheres fragments ((n, 4): x, y, z, r [m]) of its material,
        colour and mask, moving with it as a rigid body; keepMass: their masses and inertia scaled to its
        mass. Returns :class:`Replaced`."""
        raise NotImplementedError

    def crush(self, bid, stress, fragments, keepMass):
        """Grain bid crushed (section 2) under its stress tensor stress (3,3) [Pa]; fragments() gives the paper's
        sphere fragments ((n, 4): x, y, z, r [m]) and is called only by a kind that uses them. The kind decides
        what a crush does: by default the grain is replaced by those fragments (:meth:`replace`). Returns
        :class:`Replaced`."""
        return self.replace(bid, fragments(), keepMass)

    def resize(self, bid, factor):
        """Grain bid scaled by factor [-] about its centre at its density, its contacts as YADE would make
        them at the new size (ballast.contacts). Returns :class:`Resized`."""
        raise NotImplementedError

    # Abrasion (section 3, eqs. 6-7) is decided per abrasion unit, a sphere whose contacts eq. 7 reads and that
    # loses the surface layer: by default the grain itself (the sphere kind's, unchanged); a clump's are its
    # members, so a corner wears where its pressure is (docs/grains.md, "Corner wear of a clump").
    def abrasionUnits(self, ids, radii, radiusById):
        """(unit ids, their radii [m] (rMin is compared with them), the grain id of each unit) for the grains ids of
        r_eq radii [m]; radiusById: every body's sphere radius [m] (the grain table's). Default: the grains."""
        return ids, radii, ids

    def unitOf(self, bodyIds):
        """The abrasion unit each body of a contact belongs to (int64 array of bodyIds' shape). Default: its grain."""
        return self.grainOf(bodyIds)

    def abrade(self, unitId, factor):
        """Unit unitId abraded: its radius times factor [-]; returns :class:`Resized` of its grain. Default: the
        grain resized whole (:meth:`resize`)."""
        return self.resize(unitId, factor)


_kinds = {}


def register(k):
    """Make a kind (an instance of a GrainKind subclass, without state) known by its name."""
    if not isinstance(k, GrainKind) or not k.name:
        raise TypeError('grainkinds.register: a named GrainKind instance, got %r' % (k,))
    _kinds[k.name] = k
    return k


def names():
    return sorted(_kinds)


def kind(name=DEFAULT):
    """The kind of that name; ValueError naming the known kinds otherwise."""
    k = _kinds.get(name)
    if k is None:
        raise ValueError('grain kind %r is unknown; known kinds: %s' % (name, ', '.join(names())))
    return k


@runtime.persistent('GrainKind')
class SceneKind:
    """A scene's kind when it is not the default, saved with the scene (see the module doc)."""

    def __init__(self, name):
        self.name = kind(name).name

    def state(self):
        return {'name': self.name}

    @classmethod
    def fromState(cls, s, ref):
        return cls(s['name'])


_current = (None, None)   # (runtime epoch, the kind of that scene)


def current():
    """The current scene's kind: the one :func:`use` chose, else the default. Looked up again only when
    the scene changed (O.reset, O.load: a loaded scene's objects are restored here, as at its next check)."""
    global _current
    if _current[0] == runtime.epoch():
        return _current[1]
    chosen = [o.name for o in runtime.restore().values() if isinstance(o, SceneKind)]
    _current = (runtime.epoch(), kind(chosen[-1] if chosen else DEFAULT))
    return _current[1]


def use(name):
    """Make the kind `name` the current scene's, saved with it (the default: no object at all). Choose it
    before the scene has grains; the engines' grain table reads the scene afresh. Returns the kind."""
    global _current
    k = kind(name)
    for o in list(runtime.restore().values()):
        if isinstance(o, SceneKind):
            runtime.unregister(o)
    if k.name != DEFAULT:
        runtime.register(SceneKind(k.name))
    _current = (runtime.epoch(), k)
    return k


from . import sphere  # noqa: E402  (the kinds register themselves; they need the interface above)
from . import clump  # noqa: E402
from . import polyhedron  # noqa: E402

__all__ = ['DEFAULT', 'GrainKind', 'Replaced', 'Resized', 'SceneKind', 'clump', 'current', 'kind', 'names',
           'polyhedron', 'register', 'sphere', 'use']
