"""The clump kind (issue 47, item 1): a grain is a YADE clump of overlapping spheres shaped like ballast.

The grain is the clump body (``body.isClump``); its member spheres are not grains, and a contact of a
member belongs to its clump (:meth:`ClumpKind.grainOf`). A clump is built by :func:`addClump` from the
shape descriptors of :mod:`.clumpshapes` and appended with ``O.bodies.appendClumped``, which gives the
clump's centre of mass, mass and principal inertia by integrating the union of the members on a grid of
cell rMin/discretization (YADE's ``Clump::updateProperties``; with discretization 0 it sums the members,
counting overlaps twice). Measured on two spheres of radius 1 at distance 1.2 against the closed form:
mass error +0.8 % at discretization 20, +0.09 % at 40 (the default here, :data:`DISCRETIZATION`).

The volume of a grain is the union's, computed once when it is built (Monte Carlo, clumpshapes) and kept
in a persistent object of the scene (:class:`ClumpVolumes`), saved by O.save and back after O.load; r_eq
is the radius of the sphere of that volume. The stress of a grain is its Love-Weber tensor over its
members' contacts with other bodies, branch vectors from its centre of mass, over its volume, reduced in
C++ (``_ballast.clumpStresses``) from YADE's per-member tensors. Crushing (splitting) and chipping of
clumps are issue 47 items 2-3: :meth:`ClumpKind.replace` and :meth:`ClumpKind.resize` refuse.
"""
import numpy as np
from yade import O, Quaternion, Vector3, utils

from .. import _ballast, runtime
from ..geometry import sphereVolume
from . import GrainKind, register
from .clumpshapes import ELONGATION, FLATNESS, N_SPHERES, clumpMembers

DISCRETIZATION = 40   # YADE's grid for the clump's mass and inertia: cells of rMin/40 (see the module doc)


@runtime.persistent('ClumpVolumes')
class ClumpVolumes:
    """Union volume [m^3] of every clump grain of a scene, by clump body id; saved with the scene."""

    def __init__(self, volumes=None):
        self.volumes = dict(volumes or {})

    def state(self):
        ids = sorted(self.volumes)
        return {'ids': ids, 'volumes': runtime.packArray([self.volumes[i] for i in ids])}

    @classmethod
    def fromState(cls, s, ref):
        return cls(zip(s['ids'], runtime.unpackArray(s['volumes']).tolist()))


def _store(create=False):
    """The scene's ClumpVolumes (registered on first need when create)."""
    found = [o for o in runtime.restore().values() if isinstance(o, ClumpVolumes)]
    if found:
        return found[-1]
    if not create:
        return ClumpVolumes()
    s = ClumpVolumes()
    runtime.register(s)
    return s


def addClump(centre, rEq, material, orientation=None, elongation=ELONGATION, flatness=FLATNESS, n=N_SPHERES,
             seed=0, color=None, mask=None, discretization=DISCRETIZATION):
    """Append a clump grain of equivalent radius rEq [m] (union volume 4/3 pi rEq^3) at centre [m], its
    frame turned by orientation (a Quaternion; the long axis along the clump frame's x), members of
    material from clumpshapes.clumpMembers(rEq, elongation, flatness, n, seed). Returns the clump's id;
    its volume is stored with the scene."""
    c, r, V, _ = clumpMembers(rEq, elongation=elongation, flatness=flatness, n=n, seed=seed)
    q = Quaternion.Identity if orientation is None else orientation
    X = Vector3(*centre)
    kw = {'material': material}
    if color is not None:
        kw['color'] = color
    if mask is not None:
        kw['mask'] = mask
    spheres = [utils.sphere(X + q * Vector3(*ci), float(ri), **kw) for ci, ri in zip(c.tolist(), r.tolist())]
    return appendClump(spheres, V, discretization)


def appendClump(spheres, volume, discretization=DISCRETIZATION):
    """Append yade sphere bodies as one clump grain whose union volume is volume [m^3] (stored with the
    scene); returns the clump's id."""
    if not volume > 0:
        raise ValueError('volume: expected the union volume of the members > 0 [m^3], got %r' % (volume,))
    cid, _ = O.bodies.appendClumped(spheres, discretization=discretization)
    _store(create=True).volumes[int(cid)] = float(volume)
    return int(cid)


class ClumpKind(GrainKind):
    name = 'clump'
    oneSphere = False

    def __init__(self):
        self._owners = (None, None)   # ((epoch, signature, len(O.bodies)), member -> clump map)

    def isGrain(self, body):
        return body.isClump

    def volumes(self, ids):
        """Union volumes [m^3] kept when each clump was built (KeyError naming a clump built otherwise)."""
        v = _store().volumes
        missing = [int(i) for i in ids if int(i) not in v]
        if missing:
            raise KeyError('clump kind: no stored volume for clump(s) %s; build clump grains with '
                           'grainkinds.clump.addClump' % missing[:5])
        return np.array([v[int(i)] for i in ids], dtype=float)

    def signature(self):
        """Total volume of the scene's spheres, clump members included [m^3] (YADE, C++): changes when a
        clump is added or erased with its members."""
        return utils.getSpheresVolume()

    def _ownerMap(self):
        """Array: body id -> the clump it belongs to (itself when not a member); rebuilt when the scene's
        bodies change (runtime epoch, signature, number of ids)."""
        key = (runtime.epoch(), self.signature(), len(O.bodies))
        if self._owners[0] != key:
            own = np.arange(len(O.bodies), dtype=np.int64)
            pairs = [(b.id, b.clumpId) for b in O.bodies if b is not None and b.isClumpMember]
            if pairs:
                p = np.array(pairs, dtype=np.int64)
                own[p[:, 0]] = p[:, 1]
            self._owners = (key, own)
        return self._owners[1]

    def grainOf(self, bodyIds):
        """The clump of each member id; any other body maps to itself."""
        ids = np.asarray(bodyIds, dtype=np.int64)
        return self._ownerMap()[ids]

    def stressTensors(self):
        """Love-Weber stress [Pa] of every clump as one grain, (len(O.bodies), 3, 3) by body id (rows of
        other bodies zero): sigma V = sum_m [sigma_m V_m + F_m (x) (x_m - X)] (ClumpStress.hpp), sigma_m
        YADE's bodyStressTensors (V_m = 4/3 pi r_m^3), F_m the member's contact forces summed here."""
        nb = len(O.bodies)
        out = np.zeros((nb, 3, 3))
        own = self._ownerMap()
        members = np.nonzero(own != np.arange(nb))[0]
        if len(members) == 0:
            return out
        S = _ballast.matricesToArray(utils.bodyStressTensors())
        rows = [(i.id1, i.id2, *(i.phys.normalForce + i.phys.shearForce)) for i in O.interactions if i.isReal]
        F = np.zeros((nb, 3))
        if rows:
            a = np.array(rows, dtype=float)
            i1, i2 = a[:, 0].astype(np.int64), a[:, 1].astype(np.int64)
            np.add.at(F, i1, -a[:, 2:])    # YADE's force f acts on id2, -f on id1
            np.add.at(F, i2, a[:, 2:])
        clumps = np.unique(own[members])
        index = np.searchsorted(clumps, own[members])
        pos = np.array([tuple(O.bodies[int(m)].state.pos) for m in members], dtype=float)
        radii = np.array([O.bodies[int(m)].shape.radius for m in members], dtype=float)
        X = np.array([tuple(O.bodies[int(k)].state.pos) for k in clumps], dtype=float)
        out[clumps] = _ballast.clumpStresses(S[members], sphereVolume(radii), F[members], pos, index, X,
                                             self.volumes(clumps))
        return out

    def replace(self, bid, fragments, keepMass):
        raise NotImplementedError('clump kind: crushing a clump (splitting it into pieces) is not yet implemented '
                                  '(issue 47, item 2)')

    def resize(self, bid, factor):
        raise NotImplementedError('clump kind: chipping or resizing a clump is not yet implemented (issue 47, item 3)')


register(ClumpKind())
