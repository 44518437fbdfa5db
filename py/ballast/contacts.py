"""Contacts consistent with a grain the engines resized (abrasion, section 3).

YADE computes a contact's stiffness once, when its IPhys functor creates the contact, from the
reference radii of its geometry. ``utils.growParticle`` changes the grain's radius, mass, inertia and
its own side's ``refR``, but neither the partner side's ``refR`` of a wall or facet contact (YADE sets
it from the sphere's radius: r for a wall, 2 r for a facet) nor the stiffness: after abrasion with
gamma = 0.95 a Hertz contact kept 1.026 times the stiffness of the new radius, and eq. 7 read
pressures up to 25 % too high after repeated abrasion (issue 15).

:func:`resize` gives every real contact of the grain what YADE would give a contact created at the
new radius, keeping its tangential force (its history):

* ``refR``: the grain's side is the new radius; a non-sphere partner's side scales with it.
* linear law (``FrictPhys``, Ip2_FrictMat_FrictMat_FrictPhys): kn = 2 Ea Ra Eb Rb / (Ea Ra + Eb Rb)
  and ks = 2 Ea Ra va Eb Rb vb / (Ea Ra va + Eb Rb vb) from the new reference radii.
* Hertz-Mindlin (``MindlinPhys``, Ip2_FrictMat_FrictMat_MindlinPhys): kno = 4/3 E* sqrt(R) and
  kso = 8 G* sqrt(R), R = Ra Rb / (Ra + Rb): both scale with sqrt(R_new / R_old).
* any other IPhys: the contact's physics is dropped and YADE's own functor creates it afresh at the
  next step (its tangential force restarts from zero).

A contact silenced by :func:`silence` (every stiffness 0: two pieces of a split clump still overlapping) keeps
its zero stiffness: at the new radius it would press the pieces apart by their whole overlap (issue 47).

It acts on one sphere body: a grain kind (ballast.grainkinds) calls it for each sphere it resized (the
sphere kind: the grain itself). A partner's side is judged by its shape, as YADE's Ig2 functors judge it:
a Sphere (a grain, a clump member, a grid node) has a reference radius of its own.

tests/python/test_contacts.py compares every case with a contact YADE creates at the new radius.
"""
import math

from yade import O
from yade.wrapper import Sphere

from . import _ballast
from .geometry import frictPhysStiffness


def _pair(own, partner):
    """The reference radii YADE's IPhys functors use: a zero side takes the other's value."""
    return (own if own > 0 else partner), (partner if partner > 0 else own)


def resize(bid, rOld, rNew):
    """After the sphere body `bid` changed its radius from rOld to rNew [m] (by utils.growParticle, which
    sets its own side's refR only; called by its grain kind): every real contact of it as YADE would
    create it at rNew.
    Returns the number of contacts updated."""
    factor = rNew / rOld
    n = 0
    for i in O.bodies[bid].intrs():
        if not i.isReal:
            continue
        mine1 = i.id1 == bid
        g, p = i.geom, i.phys
        partnerOld = g.refR2 if mine1 else g.refR1
        other = O.bodies[i.id2 if mine1 else i.id1]
        partnerNew = partnerOld if isinstance(other.shape, Sphere) else partnerOld * factor
        g.refR1, g.refR2 = (rNew, partnerNew) if mine1 else (partnerNew, rNew)
        kind = type(p).__name__
        if silenced(p):
            pass   # two pieces of a split clump still overlapping: stiffness at the new radius would press them apart
        elif kind == 'FrictPhys':
            m1, m2 = O.bodies[i.id1].material, O.bodies[i.id2].material
            Ra, Rb = _pair(g.refR1, g.refR2)
            p.kn, p.ks = frictPhysStiffness(m1.young, m1.poisson, Ra, m2.young, m2.poisson, Rb)
        elif kind == 'MindlinPhys':
            s = math.sqrt(_ballast.effectiveRadius(*_pair(rNew, partnerNew)) /
                          _ballast.effectiveRadius(*_pair(rOld, partnerOld)))
            p.kno *= s
            p.kso *= s
        else:
            i.phys = None
        n += 1
    return n


# stiffness attributes of YADE's IPhys classes the package's laws use: FrictPhys (kn, ks), MindlinPhys (kno, kso and
# the current kn, ks), CohFrictPhys (kn, ks, kr, ktw)
_STIFFNESS = ('kn', 'ks', 'kno', 'kso', 'kr', 'ktw')


def silenced(phys):
    """Whether a contact's physics was silenced (:func:`silence`): it has stiffness attributes and all are 0."""
    ks = [getattr(phys, k) for k in _STIFFNESS if hasattr(phys, k)]
    return bool(ks) and not any(ks)


def silence(i):
    """A contact (a real interaction) that carries no force: every stiffness of its physics set to 0. For two
    members of a split clump that overlapped inside it (issue 47, item 2): their overlap is the clump's own
    volume, not a pressed contact; YADE erases the interaction when they part, and a later contact between
    them is created afresh with its full stiffness. Returns the interaction."""
    for k in _STIFFNESS:
        if hasattr(i.phys, k):
            setattr(i.phys, k, 0.0)
    return i
