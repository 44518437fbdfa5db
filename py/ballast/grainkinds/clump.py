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
C++ (``_ballast.clumpStresses``) from YADE's per-member tensors.

A crushed clump splits (issue 47, item 2, :meth:`ClumpKind.split`, docs/grains.md "Crushing a clump"): its
members are shared out among pieces cut by planes through its centre oriented by its principal stresses
(``_ballast.clumpSplit``); a piece of several members is clumped again, a piece of one member is a free
sphere. A free sphere (``Sphere``, not a member) is a grain of this kind too and follows the paper's sphere
model (the sphere kind's volume, stress, replacement and resizing). Chipping a clump is item 3:
:meth:`ClumpKind.resize` refuses a clump.
"""
import math

import numpy as np
from yade import O, Quaternion, Vector3, utils
from yade.wrapper import Sphere

from .. import _ballast, contacts, runtime
from ..geometry import equivalentRadius, sphereVolume
from . import GrainKind, Replaced, Resized, register
from .clumpshapes import (ELONGATION, FLATNESS, N_SPHERES, ROUNDNESS, absorbEmpty, clumpMembers, containers,
                          crossPairs, pieceShares)
from .sphere import SphereKind
from .clumpshapes import shellOutside

DISCRETIZATION = 40   # YADE's grid for the clump's mass and inertia: cells of rMin/40 (see the module doc)
# Monte Carlo points for the pieces' shares of a split clump's volume: a crush costs about 0.3 s of Python for
# 8 members, and a share's relative standard error is about sqrt((1 - q)/(q N)) < 0.5 % for shares q > 0.05
SPLIT_SAMPLES = 100000
_SPHERE = SphereKind()   # a free sphere of a clump scene is a grain of the paper's model


@runtime.persistent('ClumpVolumes')
class ClumpVolumes:
    """Union volume [m^3] of every clump grain of a scene, by clump body id; saved with the scene."""

    def __init__(self, volumes=None, splits=0):
        self.volumes = dict(volumes or {})
        self.splits = splits   # clumps split so far: the kind's signature (a split may add no sphere and no body)

    def state(self):
        ids = sorted(self.volumes)
        return {'ids': ids, 'volumes': runtime.packArray([self.volumes[i] for i in ids]), 'splits': self.splits}

    @classmethod
    def fromState(cls, s, ref):
        return cls(zip(s['ids'], runtime.unpackArray(s['volumes']).tolist()), s.get('splits', 0))


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
             seed=0, color=None, mask=None, discretization=DISCRETIZATION, roundness=ROUNDNESS):
    """Append a clump grain of equivalent radius rEq [m] (union volume 4/3 pi rEq^3) at centre [m], its
    frame turned by orientation (a Quaternion; the long axis along the clump frame's x), members of
    material from clumpshapes.clumpMembers(rEq, elongation, flatness, n, seed, roundness). Returns the clump's id;
    its volume is stored with the scene."""
    c, r, V, _ = clumpMembers(rEq, elongation=elongation, flatness=flatness, n=n, seed=seed, roundness=roundness)
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
    O.bodies[cid].material = spheres[0].material   # YADE leaves the clump body none; moduli() reads it
    _store(create=True).volumes[int(cid)] = float(volume)
    return int(cid)


def _isSphere(body):
    """A free sphere: exactly Sphere (a GridNode is a membrane's node) and no clump's member."""
    return type(body.shape) is Sphere and not body.isClumpMember


class ClumpKind(GrainKind):
    name = 'clump'
    oneSphere = False

    def __init__(self):
        self._owners = (None, None)   # ((epoch, signature, len(O.bodies)), what _scene gives)

    def isGrain(self, body):
        """A clump, or a free sphere (a piece of one member of a split clump, or a sphere put in the scene)."""
        return body.isClump or _isSphere(body)

    def volumes(self, ids):
        """Union volumes [m^3] kept when each clump was built or split (KeyError naming a clump built otherwise);
        4/3 pi r^3 of a free sphere."""
        v = _store().volumes
        bodies = [O.bodies[int(i)] for i in ids]
        missing = [b.id for b in bodies if b.isClump and b.id not in v]
        if missing:
            raise KeyError('clump kind: no stored volume for clump(s) %s; build clump grains with '
                           'grainkinds.clump.addClump' % missing[:5])
        return np.array([v[b.id] if b.isClump else sphereVolume(b.shape.radius) for b in bodies], dtype=float)

    def radii(self, ids):
        """r_eq [m]: of the sphere of a clump's union volume; a free sphere's own radius (the sphere model's)."""
        bodies = [O.bodies[int(i)] for i in ids]
        v = _store().volumes
        return np.array([float(equivalentRadius(v[b.id])) if b.isClump else b.shape.radius for b in bodies],
                        dtype=float)

    def stepRadii(self, ids):
        """A clump's smallest member [m] (YADE's PWaveTimeStep() reads the members: the clump's own step is theirs, not
        r_eq's, which is about twice as long for the default shape), a free sphere's radius. From the cache of
        _scene: no loop over the members."""
        ids = np.asarray(ids, dtype=np.int64)
        own, _, members, _, _, _, _, _, radii = self._scene()
        smallest = np.full(len(O.bodies), np.inf)
        if len(members):
            np.minimum.at(smallest, own[members], radii)
        out = smallest[ids]
        free = ~np.isfinite(out)
        if free.any():
            out[free] = self.radii(ids[free])
        return out

    def signature(self):
        """(Total volume of the scene's spheres, clump members included [m^3] (YADE, C++), clumps split so far):
        changes when a clump is added or erased with its members, or split (which keeps every sphere)."""
        return (utils.getSpheresVolume(), _store().splits)

    def _ownerMap(self):
        """(Array: body id -> the clump it belongs to (itself when not a member), ids of the free spheres); rebuilt
        when the scene's bodies change (runtime epoch, signature, number of ids)."""
        return self._scene()[:2]

    def _scene(self):
        """(own, free, members, clumps, index, row, member volumes, clump volumes, member radii), rebuilt when the
        scene's bodies change (runtime epoch, signature: a member added, erased or worn, a clump split; number of ids):
        own and free as _ownerMap; the member ids, the clumps they belong to (sorted) and each member's index among
        them; row: body id -> its row among the bodies there are (the order of YADE's C++ readers,
        harvest.positions); the members' sphere volumes and the clumps' union volumes [m^3] and the members' radii
        [m], which change only with the signature."""
        key = (runtime.epoch(), self.signature(), len(O.bodies))
        if self._owners[0] != key:
            nb = len(O.bodies)
            own = np.arange(nb, dtype=np.int64)
            row = np.full(nb, -1, dtype=np.int64)
            pairs, free, radii = [], [], []
            k = -1
            for b in O.bodies:
                if b is None:
                    continue
                k += 1
                row[b.id] = k
                if b.isClumpMember:
                    pairs.append((b.id, b.clumpId))
                    radii.append(b.shape.radius)
                elif _isSphere(b):
                    free.append(b.id)
            if pairs:
                p = np.array(pairs, dtype=np.int64)
                own[p[:, 0]] = p[:, 1]
            members = np.nonzero(own != np.arange(nb))[0]   # sorted ids, as pairs came in id order
            clumps = np.unique(own[members])
            radii = np.array(radii, dtype=float)
            self._owners = (key, (own, np.array(free, dtype=np.int64), members, clumps,
                                  np.searchsorted(clumps, own[members]), row, sphereVolume(radii),
                                  self.volumes(clumps) if len(clumps) else np.zeros(0), radii))
        return self._owners[1]

    def bounds(self, ids):
        """(lo, hi), each (n, 3) [m]: the box a grain's spheres fill, a clump's members' (not its centre -+ r_eq:
        lying flat it stands lower, and a plate seated there fell onto the bed, docs/grains.md "Seating"), a free
        sphere's centre -+ its radius. Centres from YADE's C++ reader, no loop over the members."""
        ids = np.asarray(ids, dtype=np.int64)
        own, _, members, clumps, _, row, _, _, radii = self._scene()
        from ..harvest import bodyPositions   # here: harvest reads the grain kinds
        x = bodyPositions()
        lo = np.full((len(O.bodies), 3), np.inf)
        hi = np.full((len(O.bodies), 3), -np.inf)
        if len(members):
            xm, rm = x[row[members]], radii[:, None]
            np.minimum.at(lo, own[members], xm - rm)
            np.maximum.at(hi, own[members], xm + rm)
        plain = ~np.isin(ids, clumps)   # free spheres: what the base answers exactly
        if plain.any():
            lo[ids[plain]], hi[ids[plain]] = GrainKind.bounds(self, ids[plain])
        return lo[ids], hi[ids]

    def grainOf(self, bodyIds):
        """The clump of each member id; any other body maps to itself."""
        ids = np.asarray(bodyIds, dtype=np.int64)
        return self._ownerMap()[0][ids]

    def stressTensors(self):
        """Love-Weber stress [Pa] of every clump as one grain, (len(O.bodies), 3, 3) by body id (rows of
        other bodies zero): sigma V = sum_m [sigma_m V_m + F_m (x) (x_m - X)] (ClumpStress.hpp), sigma_m
        YADE's bodyStressTensors (V_m = 4/3 pi r_m^3), F_m the member's contact forces summed here. A free
        sphere's row is YADE's own tensor, as the sphere kind's. Positions come from YADE's C++ reader, what
        changes only with the bodies from the cache of _scene: no Python loop over the members."""
        nb = len(O.bodies)
        out = np.zeros((nb, 3, 3))
        own, free, members, clumps, index, row, memberVolumes, clumpVolumes, _ = self._scene()
        if len(members) == 0 and len(free) == 0:
            return out
        S = _ballast.matricesToArray(utils.bodyStressTensors())
        out[free] = S[free]
        if len(members) == 0:
            return out
        rows = [(i.id1, i.id2, *(i.phys.normalForce + i.phys.shearForce)) for i in O.interactions if i.isReal]
        F = np.zeros((nb, 3))
        if rows:
            a = np.array(rows, dtype=float)
            i1, i2 = a[:, 0].astype(np.int64), a[:, 1].astype(np.int64)
            np.add.at(F, i1, -a[:, 2:])    # YADE's force f acts on id2, -f on id1
            np.add.at(F, i2, a[:, 2:])
        from ..harvest import bodyPositions   # here: harvest reads the grain kinds
        x = bodyPositions()
        out[clumps] = _ballast.clumpStresses(S[members], memberVolumes, F[members], x[row[members]], index,
                                             x[row[clumps]], clumpVolumes)
        return out

    def crush(self, bid, stress, fragments, keepMass):
        """A clump splits (:meth:`split`, under its stress tensor [Pa]), unless it is one sphere (:meth:`_asSphere`);
        a free sphere is replaced by the paper's fragments (the sphere kind), and those in an overlap it had through a
        silenced contact get a silenced contact too."""
        if O.bodies[bid].isClump:
            arrays = _members(O.bodies[bid])
            whole = self._asSphere(bid, arrays)
            if whole is None:
                return self.split(bid, stress, arrays)
            bid = whole   # its union is one member: no plane cuts it, it crushes as that sphere
        # a piece still overlapping another through a silenced contact: its fragments lie in that overlap too, and
        # contacts the collider made there would start with full stiffness at that depth
        quiet = [i.id2 if i.id1 == bid else i.id1 for i in O.bodies[bid].intrs()
                 if i.isReal and contacts.silenced(i.phys)]
        rep = _SPHERE.replace(bid, fragments(), keepMass)
        for f in rep.ids:
            for o in quiet:
                a, b = O.bodies[f], O.bodies[o]
                if (a.state.pos - b.state.pos).norm() < a.shape.radius + b.shape.radius:
                    contacts.silence(utils.createInteraction(f, o))
        return rep

    def replace(self, bid, fragments, keepMass):
        """A free sphere: as the sphere kind. A clump is never replaced by spheres: it splits (crush)."""
        if O.bodies[bid].isClump:
            raise ValueError('clump kind: grain %d is a clump; a crushed clump splits into pieces of its members '
                             '(ClumpKind.crush, issue 47 item 2), it is not replaced by sphere fragments' % bid)
        return _SPHERE.replace(bid, fragments, keepMass)

    def resize(self, bid, factor):
        """A free sphere: as the sphere kind. A clump is not scaled whole: abrasion wears its members (abrade)."""
        if O.bodies[bid].isClump:
            raise NotImplementedError('clump kind: scaling a whole clump is not implemented; abrasion wears its '
                                      'members (ClumpKind.abrade; issue 47, item 3)')
        return _SPHERE.resize(bid, factor)

    def _asSphere(self, bid, arrays):
        """A clump whose members all lie inside one of them (containers) is that sphere: its union is the member's, so
        every cut gives one piece, which was clumped again under a new id and crushed again at the next check
        (measured: 12 of 76 splits in the clump box, at successive checks). It becomes a free sphere at the member's
        centre of the clump's volume V and mass M (radius r_eq, so it never grows; the held members, inside it, are
        erased, adding nothing to the union), moving with the clump's rigid motion; returns its id. None when the clump
        has two members or more that no other holds. arrays: _members of the clump."""
        c = O.bodies[bid]
        members, pos, radii, holder = arrays
        free = np.flatnonzero(holder < 0)
        if len(free) != 1:
            return None
        keep = members[int(free[0])]
        st, store = c.state, _store(create=True)
        M, X, v, w, mask = st.mass, Vector3(st.pos), Vector3(st.vel), Vector3(st.angVel), c.groupMask
        scaling, blocked = st.densityScaling, st.blockedDOFs
        V = store.volumes.pop(bid)
        O.bodies.erase(bid)
        for m in members:
            if m != keep:
                O.bodies.erase(m)
        store.splits += 1
        _SPHERE.resize(keep, min(1.0, float(equivalentRadius(V)) / O.bodies[keep].shape.radius))
        b = O.bodies[keep]
        b.state.inertia = b.state.inertia * (M / b.state.mass)
        b.state.mass = M
        b.groupMask = mask
        b.state.vel = v + w.cross(b.state.pos - X)
        b.state.angVel = w
        b.state.densityScaling = scaling
        b.state.blockedDOFs = blocked
        return keep

    def split(self, bid, stress, arrays=None):
        """Clump bid split into pieces under its stress tensor (3,3) [Pa] (docs/grains.md, "Crushing a clump"):
        the pieces of ``_ballast.clumpSplit`` (planes through its centre of mass, by its principal stresses) take
        its members. The clump's volume V is partitioned among them (clumpshapes.pieceShares: the overlap of members
        of two pieces goes to the one a point lies deeper in), each piece's volume V q_p and mass M q_p, so volume
        and mass are kept exactly and the density with them: a piece of several members is clumped again (YADE's
        inertia, scaled to its mass), a piece of one is a free sphere shrunk to its volume (it gives up its part of
        the lenses it shared; a smaller sphere creates no overlap). Each piece moves with the clump's rigid velocity
        about the pieces' joint centre of mass, so momentum is kept. Members of different pieces that still
        overlap (inside the clump they had no contact) get a contact of zero stiffness, which carries no force
        until they part (:func:`ballast.contacts.silence`). Returns :class:`Replaced` (volume ratio 1: nothing to
        regrow) with ``split``: pieces, the plane normals, whether the median fallback was used, the silenced
        pairs and the pieces' shares of the volume. arrays: _members of the clump, if the caller has them."""
        c = O.bodies[bid]
        st, mask, material = c.state, c.groupMask, c.material
        M, v, w, scaling, blocked = st.mass, Vector3(st.vel), Vector3(st.angVel), st.densityScaling, st.blockedDOFs
        # members held whole by another add nothing to the union: cut without them, then put with their holders
        members, pos, radii, holder = _members(c) if arrays is None else arrays
        free = np.flatnonzero(holder < 0)
        cut = _ballast.clumpSplit(np.asarray(stress, dtype=float), tuple(st.pos), pos[free], radii[free])
        piece = np.empty(len(members), dtype=np.int64)
        piece[free] = cut['piece']
        piece[holder >= 0] = piece[holder[holder >= 0]]
        store = _store(create=True)
        V0 = store.volumes.pop(bid)
        piece, shares = absorbEmpty(pos, radii, piece, pieceShares(pos, radii, piece, samples=SPLIT_SAMPLES))
        n = len(shares)
        O.bodies.erase(bid)   # its members stay, free (YADE's erase without eraseClumpMembers)
        ids = []
        for k in range(n):
            own = [members[j] for j in np.flatnonzero(piece == k).tolist()]
            if len(own) == 1:   # a free sphere of its share of the volume: shrunk from its member's radius
                i = own[0]
                r = O.bodies[i].shape.radius
                _SPHERE.resize(i, min(1.0, (3 * V0 * float(shares[k]) / (4 * math.pi)) ** (1 / 3) / r))
                ids.append(i)
            else:
                cid = O.bodies.clump(own, discretization=DISCRETIZATION)
                O.bodies[cid].material = material   # YADE's clump() leaves none; moduli() and the grain table read it
                store.volumes[cid] = V0 * float(shares[k])
                ids.append(cid)
        store.splits += 1
        new = [O.bodies[i] for i in ids]
        for b, q in zip(new, shares):   # each piece its share of the mass: the masses sum to M, the density kept
            f = M * float(q) / b.state.mass
            b.state.mass *= f
            b.state.inertia = b.state.inertia * f
        Xn = sum((b.state.pos * b.state.mass for b in new), Vector3(0, 0, 0)) / M
        for b in new:
            b.groupMask = mask
            b.state.vel = v + w.cross(b.state.pos - Xn)
            b.state.angVel = w
            b.state.densityScaling = scaling
            b.state.blockedDOFs = blocked
        # every pair of members of two pieces that still overlap (a shrunk free sphere may have parted), held members
        # and absorbed ones included: a contact without force. The planes' own pairs (cut['pairs']) miss those
        now = np.array([O.bodies[m].shape.radius for m in members], dtype=float)
        pairs = [[members[i], members[j]] for i, j in crossPairs(pos, now, piece).tolist()]
        for i, j in pairs:
            contacts.silence(utils.createInteraction(i, j))
        Va = float(np.sum(self.volumes(ids)))
        note = {'pieces': n, 'normals': cut['normals'].tolist(), 'median': bool(cut['median']),
                'silenced': pairs, 'shares': [float(q) for q in shares]}
        return Replaced(ids, self.radii(ids), mask, V0, Va, M, sum(b.state.mass for b in new), 1.0, note)

    # ---------------------------------------------------------------- corner wear (issue 47, item 3)
    # YADE's grid for a worn clump's inertia: cells of rMin/20. Its mass is set from the volume, so only the inertia
    # per mass comes from the grid: within 0.3 % of rMin/40's for a default grain, at 2.7 ms instead of 38 (measured)
    wearDiscretization = 20

    def abrasionUnits(self, ids, radii, radiusById):
        """The spheres eq. 7 is read at: the members of the clumps among ids and the free spheres among them, in id
        order, with their own radii [m] (from radiusById, by body id: rMin is compared with a member's radius, which
        never exceeds its clump's r_eq) and their grain's id. See docs/grains.md, "Corner wear of a clump"."""
        own, _ = self._ownerMap()
        n = min(len(own), len(radiusById))
        spheres = np.flatnonzero(np.asarray(radiusById[:n]) > 0)   # members, free spheres (and nodes: not in ids)
        grain = own[spheres]
        keep = np.isin(grain, np.asarray(ids, dtype=np.int64))
        units = spheres[keep]
        return units, np.asarray(radiusById, dtype=float)[units], grain[keep]

    def unitOf(self, bodyIds):
        """A contact's sphere is its own abrasion unit (a member or a free sphere): the ids themselves."""
        return np.asarray(bodyIds, dtype=np.int64)

    def abrade(self, unitId, factor):
        """Unit unitId abraded by factor in (0, 1] [-]: a free sphere as the sphere kind (radius x factor, the paper's
        abrasion); a clump member shrunk by factor about its own centre (:meth:`_wear`). Returns :class:`Resized` of
        the grain (for a clump: r_eq [m], volume [m^3] and mass [kg] before, r_eq, mass and volume after)."""
        b = O.bodies[int(unitId)] if 0 <= int(unitId) < len(O.bodies) else None
        if not (np.isscalar(factor) and 0 < factor <= 1):
            raise ValueError('factor: expected a radius factor in (0, 1] (abrasion shrinks), got %r' % (factor,))
        if b is not None and b.isClumpMember:
            return self._wear(b, float(factor))
        if b is not None and _isSphere(b):
            return _SPHERE.resize(b.id, factor)
        raise ValueError('unitId: expected a clump member or a free sphere of the clump kind, got body %r (%s)'
                         % (unitId, 'no body' if b is None else type(b.shape).__name__))

    def _wear(self, member, factor):
        """Clump member shrunk by factor about its centre (its contacts as YADE makes them at the new radius,
        ballast.contacts.resize). The clump's union loses the part of the shell between the two radii outside its
        other members (clumpshapes.shellOutside, sampled in that shell alone), V' = V - dV; its mass becomes
        M V' / V (the density kept), its inertia YADE's for the new members (Clump::updateProperties of this clump
        alone, through addToClump with no body) scaled to M'; its velocity is its rigid motion at the new centre of
        mass (YADE's update zeroes it). The stored volume becomes V', so r_eq and the strength f_t0 / r_eq^m follow."""
        cid, mid = member.clumpId, member.id
        c = O.bodies[cid]
        store = _store(create=True)
        if cid not in store.volumes:
            raise KeyError('clump kind: no stored volume for clump %d; build clump grains with '
                           'grainkinds.clump.addClump' % cid)
        V, st = store.volumes[cid], c.state
        M, X, v, w = st.mass, Vector3(st.pos), Vector3(st.vel), Vector3(st.angVel)
        others = [O.bodies[i] for i in sorted(c.shape.members.keys()) if i != mid]
        r = member.shape.radius
        # the seed from the member and the step: reproducible, and the Monte Carlo errors of successive wears of
        # one member independent rather than repeated
        dV, _ = shellOutside(tuple(member.state.pos), r, factor * r, [tuple(o.state.pos) for o in others],
                             [o.shape.radius for o in others], seed=[mid, O.iter])
        utils.growParticle(mid, factor, True)   # radius, the member's own mass and inertia, its side's refR
        contacts.resize(mid, r, factor * r)
        O.bodies.addToClump([], cid, self.wearDiscretization)   # this clump's mass, centre, principal axes and inertia
        V1 = V - dV
        M1 = M * V1 / V
        st.inertia = st.inertia * (M1 / st.mass)
        st.mass = M1
        st.vel = v + w.cross(st.pos - X)
        st.angVel = w
        store.volumes[cid] = V1
        return Resized(float(equivalentRadius(V)), float(equivalentRadius(V1)), V, M, M1, V1)


def _members(c):
    """(member ids in order, their centres (n, 3) [m], radii (n,) [m], and the member holding each whole or -1:
    clumpshapes.containers) of the clump body c: what a crush reads, once."""
    members = sorted(c.shape.members.keys())
    pos = np.array([tuple(O.bodies[m].state.pos) for m in members], dtype=float)
    radii = np.array([O.bodies[m].shape.radius for m in members], dtype=float)
    return members, pos, radii, containers(pos, radii)


register(ClumpKind())
