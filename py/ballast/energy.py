"""Energy of a few bodies and their contacts, for the records of a replacement (issue 13): what a
crush, and the fragments' growth with keep='volume', injects. A loop over the bodies' own contacts:
called at events, never per step.

* kinetic: 1/2 m v^2 + 1/2 w.I w over the bodies, I the principal moments of inertia in the body's frame
  (YADE's State.inertia), so that grains of any kind (ballast.grainkinds: a clump's inertia is not
  isotropic) and boxes are counted right; 1/2 I w^2 for an isotropic body (a sphere, a wall);
* elastic: over the real contacts with at least one of the bodies, each counted once. Linear law
  (FrictPhys): Fn^2 / (2 kn) + Fs^2 / (2 ks). Hertz-Mindlin (MindlinPhys): the normal energy of
  F = kno u^1.5 is 2/5 Fn uN, the tangential Fs^2 / (2 ks) with ks the current tangent stiffness.

A clump is one body to its motion and its members to its contacts (YADE integrates the clump; the members carry
the contacts): a member or a clump given, its clump moves (kinetic), its members' contacts store (elastic), and its
partners are the grains on the other side of those contacts. Bodies that are not in a clump are as before.
"""
from yade import O


def rotational(s):
    """Rotational kinetic energy [J] of a body's State s: 1/2 sum_k I_k w_k^2 with w in the body's frame."""
    j = s.inertia
    if j[0] == j[1] == j[2]:  # isotropic: frame-free, and the bits of 1/2 I |w|^2
        return 0.5 * j[0] * s.angVel.squaredNorm()
    w = s.ori.conjugate() * s.angVel
    return 0.5 * (j[0] * w[0] ** 2 + j[1] * w[1] ** 2 + j[2] * w[2] ** 2)


def _grain(b):
    """The body that moves for b: its clump for a clump member, else b itself."""
    return O.bodies[b.clumpId] if b.isClumpMember else b


def _contactBodies(b):
    """The bodies that carry b's contacts: a clump's members, else b itself."""
    return [O.bodies[m] for m in sorted(b.shape.members.keys())] if b.isClump else [b]


def _carriers(grains):
    """The bodies that carry the contacts of `grains` (bodies from :func:`_grains`)."""
    return [m for g in grains for m in _contactBodies(g)]


def _grains(ids):
    """The bodies that move for `ids` (missing ones skipped; a clump given twice, or with its members, once), in
    the order given."""
    seen, out = set(), []
    for i in ids:
        b = O.bodies[i]
        if b is None:
            continue
        g = _grain(b)
        if g.id not in seen:
            seen.add(g.id)
            out.append(g)
    return out


def kinetic(ids):
    """Kinetic energy [J] of the bodies `ids` (missing ones skipped; a clump member counts as its clump, once)."""
    e = 0.0
    for b in _grains(ids):
        s = b.state
        e += 0.5 * s.mass * s.vel.squaredNorm() + rotational(s)
    return e


def partners(ids):
    """The bodies in real contact with `ids` (ids themselves excluded): for a clump, the grains (a clump, not its
    member) its members touch."""
    grains = _grains(ids)
    own = set(ids) | {g.id for g in grains}
    out = set()
    for b in _carriers(grains):
        for c in b.intrs():
            if c.isReal:
                other = O.bodies[c.id2 if c.id1 == b.id else c.id1]
                if other is not None:
                    out.add(_grain(other).id)
    return sorted(out - own)


def elastic(ids):
    """Elastic energy [J] stored in the real contacts of the bodies `ids` (of a clump: of its members)."""
    seen, e = set(), 0.0
    for b in _carriers(_grains(ids)):
        for c in b.intrs():
            key = (min(c.id1, c.id2), max(c.id1, c.id2))
            if not c.isReal or key in seen:
                continue
            seen.add(key)
            p = c.phys
            fn, fs = p.normalForce.norm(), p.shearForce.squaredNorm()
            if type(p).__name__ == 'MindlinPhys':
                e += 0.4 * fn * max(c.geom.penetrationDepth, 0.0)
            elif p.kn > 0:
                e += 0.5 * fn * fn / p.kn
            if p.ks > 0:
                e += 0.5 * fs / p.ks
    return e


def snapshot(ids, also=()):
    """[kinetic, elastic] [J] of the bodies `ids`, of those in contact with them and of the bodies `also`."""
    group = sorted(set(ids) | set(also) | set(partners(ids)))
    return [kinetic(group), elastic(group)]
