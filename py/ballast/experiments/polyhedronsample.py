"""Polyhedron grains of a sample (issue 47, item 4; docs/grains.md, "Polyhedra"): with grain 'polyhedron' every grain
of the cloud (centre, r) becomes one of YADE's polyhedra of volume-equivalent radius r drawn by the kind's shape
generator (:func:`ballast.grainkinds.polyhedron.randomVertices`, seed [seed, k, attempt]), inside its cloud sphere.

The cloud is made of the grains' circumscribed spheres, REACH r: a drawn shape whose farthest vertex lies beyond
REACH r_eq from its centroid is drawn again (the next attempt), so no two grains of the cloud overlap and the sizes
r_eq are those of the sphere sample's cloud (uniform in [dMin/2, dMax/2]). A stored sample keeps every grain's
vertices in the global frame (17 digits); the rebuilt grain is YADE's polyhedron of those vertices."""
import numpy as np

from ..grainkinds.polyhedron import addPolyhedron, globalVertices, randomVertices
from .scene import GRAIN_MASK

# [-] the farthest vertex over r_eq a grain may have: 14 random vertices give 1.20-1.91, median 1.33, 97 % below 1.5
# (2000 shapes); a larger reach would make the cloud and its fall taller for the few grains it admits
REACH = 1.5
ATTEMPTS = 100   # shapes drawn for one grain before giving up (the chance of 100 misses is below 1e-150)


def shape(rEq, seed):
    """(n, 3) vertices [m] about the centroid of the generator's polyhedron of r_eq rEq whose farthest vertex is within
    REACH rEq: the first of the attempts [*seed, 0], [*seed, 1], ... that fits."""
    for attempt in range(ATTEMPTS):
        v = randomVertices(rEq, list(seed) + [attempt])
        c = centroid(v)
        if np.max(np.linalg.norm(v - c, axis=1)) <= REACH * rEq:
            return v - c
    raise RuntimeError('polyhedron sample: no shape of the %d drawn from seed %r reaches less than %g r_eq'
                       % (ATTEMPTS, seed, REACH))


def centroid(v):
    """The centroid [m] of the convex hull of v ((n, 3) [m]): the tetrahedra from an inner point to its faces."""
    from scipy.spatial import ConvexHull
    hull = ConvexHull(v)
    o = v.mean(axis=0)
    a, b, c = (v[hull.simplices[:, i]] for i in range(3))
    vol = np.abs(np.einsum('ij,ij->i', a - o, np.cross(b - o, c - o))) / 6
    return (vol[:, None] * (o + a + b + c) / 4).sum(axis=0) / vol.sum()


def place(centres, radii, material, seed):
    """Grain k a polyhedron of r_eq radii[k] (shape(radii[k], [seed, k])) about centres[k], appended in that order."""
    for k, (c, r) in enumerate(zip(np.asarray(centres, dtype=float), np.asarray(radii, dtype=float))):
        addPolyhedron(shape(float(r), [int(seed), k]) + c, material, mask=GRAIN_MASK)


def document(ids):
    """What a stored sample keeps of its polyhedra: {'polyhedra': [[[x, y, z] of each vertex, as 17-digit text]]}."""
    return {'polyhedra': [[[repr(float(x)) for x in v] for v in globalVertices(i).tolist()] for i in ids]}


def rebuild(doc, material):
    """The stored polyhedra appended, in the stored order."""
    for verts in doc['polyhedra']:
        addPolyhedron(np.array([[float(x) for x in v] for v in verts]), material, mask=GRAIN_MASK)
