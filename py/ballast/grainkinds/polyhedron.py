"""The polyhedron kind (issue 47, item 4): a grain is one of YADE's own convex ``Polyhedra`` bodies, for comparison
with the paper's spheres and the clumps (docs/grains.md, "Polyhedra").

A body is a grain when its shape is exactly ``Polyhedra``; in a polyhedron scene the steel (platens, the cylinder,
plates) is facets and walls, never polyhedra, so the kind needs no mask or material to tell them apart. Volume,
centroid, mass and principal inertia are YADE's (``Polyhedra.GetVolume``, CGAL's hull of the vertices; mass density
x volume); r_eq is the volume-equivalent sphere's. The contacts are YADE's volumetric law
(``Law2_PolyhedraGeom_PolyhedraPhys_Volumetric``: Fn = kn V_overlap, 1/kn = 1/Y1 + 1/Y2 with Y the material's
``young``, a volumetric modulus [N/m^3]). A grain's stress is the splitter's: (1/V) sum_c f (x) (x_c - x), f the
contact's force on the grain, x_c the centroid of the overlap (compression negative, as the other kinds').

Crushing is YADE's ``PolyhedraSplitter`` (:class:`ballast.engines.polyhedra.PolyhedronCrushEngine` runs it and books
what it did), so :meth:`PolyhedronKind.crush` and :meth:`~PolyhedronKind.resize` refuse: a polyhedron is never
replaced by the paper's spheres, and neither YADE nor this package abrades one.
"""
import math

import numpy as np
from yade import O, Vector3, utils
from yade.wrapper import Polyhedra, PolyhedraGeom

from .. import runtime
from ..geometry import equivalentRadius
from . import GrainKind, register

VERTICES = 14   # a grain's vertices: the measured cost was for 14 (docs/grains.md, "Polyhedra")


@runtime.persistent('PolyhedronSplits')
class PolyhedronSplits:
    """How many polyhedra the splitter has split in the scene: a split changes a body in place as well as appending
    others, so the count joins the body count in the kind's signature; saved with the scene."""

    def __init__(self, splits=0):
        self.splits = splits

    def state(self):
        return {'splits': self.splits}

    @classmethod
    def fromState(cls, s, ref):
        return cls(s['splits'])


def splits(create=False):
    """The scene's PolyhedronSplits (registered on first need when create)."""
    found = [o for o in runtime.restore().values() if isinstance(o, PolyhedronSplits)]
    if found or not create:
        return found[-1] if found else PolyhedronSplits()
    s = PolyhedronSplits()
    runtime.register(s)
    return s


def randomVertices(rEq, seed, n=VERTICES):
    """(n, 3) vertices [m] about the origin whose convex hull has the volume 4/3 pi rEq^3: n points uniform on a unit
    sphere (a normalised Gaussian triple each, from the seed), scaled by the hull's volume from SciPy's Qhull. A
    roundish grain with n vertices: the choice of this comparison, not a measured ballast shape."""
    if not rEq > 0:
        raise ValueError('rEq: expected a radius > 0 [m], got %r' % (rEq,))
    # Qhull gives the same bits every call; CGAL's hull volume moved in the last digit, so one seed gave two grains
    from scipy.spatial import ConvexHull
    g = np.random.default_rng(seed).normal(size=(n, 3))
    v = g / np.linalg.norm(g, axis=1)[:, None]
    return v * (4 / 3 * math.pi * rEq ** 3 / ConvexHull(v).volume) ** (1 / 3)


def addPolyhedron(vertices, material, mask=None, fixed=False, color=None):
    """Append a polyhedron grain of global vertices ((n, 3) [m]) and material (a PolyhedraMat); returns its id. Its
    centroid, orientation, mass and inertia are YADE's (utils.polyhedron)."""
    kw = {'material': material, 'fixed': fixed, 'wire': False}
    if mask is not None:
        kw['mask'] = mask
    if color is not None:
        kw['color'] = color
    return O.bodies.append(utils.polyhedron([Vector3(*v) for v in np.asarray(vertices, dtype=float).tolist()], **kw))


def globalVertices(bid):
    """(n, 3) vertices [m] of polyhedron bid in the global frame."""
    b = O.bodies[int(bid)]
    q, x = b.state.ori, b.state.pos
    return np.array([tuple(x + q * v) for v in b.shape.v], dtype=float).reshape(-1, 3)


def contactRows():
    """The volumetric contacts as arrays: id1, id2 (int64), f (n, 3) [N] (normal + shear, the force on id2; -f on
    id1) and the overlap's centroid (n, 3) [m]. One pass over the interactions (no C++ accessor in YADE 2023.02a, as
    ballast.harvest.contacts)."""
    rows = [(i.id1, i.id2, *(i.phys.normalForce + i.phys.shearForce), *i.geom.contactPoint)
            for i in O.interactions if i.isReal and isinstance(i.geom, PolyhedraGeom)]
    a = np.array(rows, dtype=float).reshape(-1, 8)
    return a[:, 0].astype(np.int64), a[:, 1].astype(np.int64), a[:, 2:5], a[:, 5:8]


def stressSums(nBodies):
    """sum_c f (x) (x_c - x) [N m] of every body by id, (nBodies, 3, 3): PolyhedraSplitter's getStressForEachBody
    (the grain's tensor before it is divided by its volume)."""
    i1, i2, f, c = contactRows()
    out = np.zeros((nBodies, 3, 3))
    if len(i1) == 0:
        return out
    ids = np.unique(np.concatenate([i1, i2]))
    pos = np.zeros((nBodies, 3))
    pos[ids] = [tuple(O.bodies[int(i)].state.pos) for i in ids]
    np.add.at(out, i2, f[:, :, None] * (c - pos[i2])[:, None, :])
    np.add.at(out, i1, -f[:, :, None] * (c - pos[i1])[:, None, :])
    return out


class PolyhedronKind(GrainKind):
    name = 'polyhedron'
    oneSphere = False

    def isGrain(self, body):
        return type(body.shape) is Polyhedra

    def volumes(self, ids):
        """YADE's volume of each polyhedron [m^3]."""
        return np.array([O.bodies[int(i)].shape.GetVolume() for i in ids], dtype=float)

    def radii(self, ids):
        return equivalentRadius(self.volumes(ids))

    def signature(self):
        """(Body count, splits so far): changes when a polyhedron is added or split. Erasing one by hand in the middle
        of O.bodies does not change it: call ballast.harvest.refresh() then."""
        return (len(O.bodies), splits().splits)

    def stressTensors(self):
        """The splitter's stress [Pa] of every polyhedron, by body id (other rows zero)."""
        n = len(O.bodies)
        S = stressSums(n)
        ids = self.ids()
        out = np.zeros((n, 3, 3))
        if len(ids):
            out[ids] = S[ids] / self.volumes(ids)[:, None, None]
        return out

    def bounds(self, ids):
        """(lo, hi) [m]: each polyhedron's vertices' smallest and largest coordinates (a loop over the grains: for
        seating a plate)."""
        v = [globalVertices(i) for i in ids]
        return (np.array([np.min(a, axis=0) for a in v], dtype=float).reshape(-1, 3),
                np.array([np.max(a, axis=0) for a in v], dtype=float).reshape(-1, 3))

    def grainOf(self, bodyIds):
        return np.asarray(bodyIds, dtype=np.int64)

    def pWaveTimeStep(self):
        """Eq. 5's step for polyhedra [s]: a volumetric modulus Y [N/m^3] gives a grain of r_eq a contact stiffness
        about Y r_eq^2 / 2, as a sphere of modulus E = Y r_eq has E r (docs/grains.md), so the step of the smallest
        grain is r_eq sqrt(rho / (Y r_eq)). Infinite without grains."""
        best = math.inf
        for b in self.bodies():
            r = float(equivalentRadius(b.shape.GetVolume()))
            best = min(best, math.sqrt(b.material.density * r / b.material.young))
        return best

    def replace(self, bid, fragments, keepMass):
        raise ValueError('polyhedron kind: grain %d is a polyhedron; it crushes by YADE\'s PolyhedraSplitter '
                         '(ballast.engines.PolyhedronCrushEngine), never into sphere fragments' % bid)

    def crush(self, bid, stress, fragments, keepMass):
        return self.replace(bid, fragments, keepMass)

    def resize(self, bid, factor):
        raise NotImplementedError('polyhedron kind: a polyhedron is not resized or abraded (YADE has no abrasion of '
                                  'polyhedra; docs/grains.md, "Polyhedra")')


register(PolyhedronKind())
