"""Clump grains of a sample (issue 47, item 1; docs/grains.md, "Clumps in the experiments"): with grain 'clump' every
grain of the cloud (centre, r) becomes a clump of volume-equivalent radius r, a copy of one of a few shapes, the
templates, scaled and turned.

A shape costs about 1 s (its union volume by Monte Carlo, :func:`ballast.grainkinds.clumpshapes.clumpMembers`), so
a sample builds ``clumpTemplates`` of them once, at r_eq = 1, from its seed, and each grain takes one of them at
random, a random orientation (uniform on the rotations) and its radius. A grain is built at the origin in its
template's frame and then moved and turned as a rigid body: YADE integrates its mass and inertia on a grid in that
frame, so every copy of a template has the same mass over r^3 whatever its orientation, and a rebuilt grain is the
same to rounding.

What a stored sample keeps of its clumps (:meth:`ClumpSample.document`, back by :meth:`ClumpSample.fromDocument`):
the templates (members' centres and radii at r_eq = 1, the union volume) and per grain its template, the
orientation q (w, x, y, z) and the centre c that map the template onto it (member at c + q (r t_i)), and r. The
scene keeps, per clump it placed, where its template's origin and frame lie in the clump's own frame, so the
grain's (q, c) follow from its state wherever the preparation moved it."""
import numpy as np
from yade import O, Quaternion, Vector3, utils

from .. import runtime
from ..grainkinds import clump
from ..grainkinds.clumpshapes import clumpMembers, principalTemplate
from ..templatefile import readTemplates
from .scene import GRAIN_MASK

ROW = 9   # a stored grain: template, q (w, x, y, z), c (x, y, z) [m], r [m]


def _quaternion(w, x, y, z):
    return Quaternion(float(w), float(x), float(y), float(z))


def _wxyz(q):
    """minieigen lists a Quaternion as (x, y, z, w)."""
    return (q[3], q[0], q[1], q[2])


@runtime.persistent('ClumpSample')
class ClumpSample:
    """The templates of the scene's clump grains (members' centres (n, 3) and radii at r_eq = 1, union volume) and,
    per clump it placed, (template, r [m], P0, R0): the clump's centre of mass [m] and frame as YADE gave them when it
    was built in its template's frame (how that frame sits in the clump's)."""

    def __init__(self, templates=(), placed=None):
        self.templates = [(np.asarray(c, dtype=float).reshape(-1, 3), np.asarray(r, dtype=float), float(v))
                          for c, r, v in templates]
        self.placed = dict(placed or {})

    @classmethod
    def build(cls, p):
        """clumpTemplates shapes from p's seed and clump parameters, or with clumpFile that file's templates (each in
        its principal frame at r_eq = 1), registered with the scene."""
        if p.get('clumpFile'):
            shapes = [principalTemplate(c0, r0, seed=[p['seed'], j])
                      for j, (_, c0, r0) in enumerate(readTemplates(p['clumpFile']))]
        else:
            shapes = [clumpMembers(1.0, elongation=p['clumpElongation'], flatness=p['clumpFlatness'],
                                   n=p['clumpSpheres'], seed=[p['seed'], j], roundness=p['clumpRoundness'])
                      for j in range(p['clumpTemplates'])]
        obj = cls([(c, r, v) for c, r, v, _ in shapes])
        runtime.register(obj)
        return obj

    @classmethod
    def current(cls):
        """The scene's, or None."""
        found = [o for o in runtime.restore().values() if isinstance(o, cls)]
        return found[-1] if found else None

    @classmethod
    def ofScene(cls, p):
        """The scene's templates: those registered, else built from p (the first layer of a sample)."""
        return cls.current() or cls.build(p)

    def state(self):
        ids = sorted(self.placed)
        return {'templates': [[runtime.packArray(c), runtime.packArray(r), v] for c, r, v in self.templates],
                'ids': ids, 'placed': runtime.packArray([self._row(i) for i in ids])}

    def _row(self, i):
        k, r, P0, R0 = self.placed[i]
        return [k, r, *P0, *_wxyz(R0)]

    @classmethod
    def fromState(cls, s, ref=None):
        rows = runtime.unpackArray(s['placed']).reshape(-1, 9) if s['ids'] else []
        placed = {i: (int(a[0]), a[1], Vector3(*a[2:5]), _quaternion(*a[5:9])) for i, a in zip(s['ids'], rows)}
        return cls([(runtime.unpackArray(c), runtime.unpackArray(r), v) for c, r, v in s['templates']], placed)

    def reach(self):
        """The largest circumscribed radius of the templates about their origin over r_eq [-]: a cloud of spheres this
        much larger holds the clumps without overlap (they fall apart, off the walls)."""
        return max(float(np.max(np.linalg.norm(c, axis=1) + r)) for c, r, _ in self.templates)

    # ---------------------------------------------------------------- placing
    def add(self, k, q, centre, r, material):
        """A clump of template k scaled to r_eq r [m], turned by q (a unit Quaternion) about its template's origin put
        at centre [m]; returns its id."""
        C, R, V = self.templates[k]
        spheres = [utils.sphere(tuple(ci), float(ri), material=material, mask=GRAIN_MASK)
                   for ci, ri in zip((C * r).tolist(), (R * r).tolist())]
        cid = clump.appendClump(spheres, V * r ** 3)
        b = O.bodies[cid]
        b.groupMask = GRAIN_MASK   # a piece of a split clump takes its mask: it must meet the walls as a grain does
        P0, R0 = Vector3(b.state.pos), Quaternion(b.state.ori)
        X = Vector3(*(float(v) for v in centre))
        b.state.pos, b.state.ori = X + q * P0, q * R0
        for s in spheres:   # the members where the clump puts them (the collider sees them before Newton moves them)
            s.state.pos, s.state.ori = X + q * s.state.pos, q * s.state.ori
        self.placed[cid] = (k, float(r), P0, R0)
        return cid

    def draw(self, n, seed, flat=False):
        """(templates, orientations) of n grains drawn from seed: a template uniformly, a unit Quaternion uniform on
        the rotations (a normalised Gaussian 4-vector); flat: a turn about z only, uniform in angle (the grain on its
        flat side: its short axis, the template's z, vertical)."""
        rng = np.random.default_rng(seed)
        ks = rng.integers(len(self.templates), size=n)
        if flat:
            return ks.tolist(), [Quaternion(Vector3(0, 0, 1), a) for a in rng.uniform(0, 2 * np.pi, n).tolist()]
        qs = rng.normal(size=(n, 4))
        qs /= np.linalg.norm(qs, axis=1)[:, None]
        return ks.tolist(), [_quaternion(*q) for q in qs.tolist()]

    def place(self, centres, radii, material, seed):
        """The cloud's grains as clumps, in the order given, their templates and orientations drawn from seed.
        Returns the ids."""
        ks, qs = self.draw(len(radii), seed)
        return [self.add(k, q, c, float(r), material) for k, q, c, r in zip(ks, qs, centres, radii)]

    # ---------------------------------------------------------------- the store
    def rows(self):
        """Per clump grain of the scene that it placed, O.bodies order: [template, w, x, y, z, cx, cy, cz, r] (ROW)."""
        out = []
        for b in O.bodies:
            if b is None or not b.isClump or b.id not in self.placed:
                continue
            k, r, P0, R0 = self.placed[b.id]
            q = b.state.ori * R0.conjugate()
            c = b.state.pos - q * P0
            out.append([k, *_wxyz(q), c[0], c[1], c[2], r])
        return out

    def document(self):
        """What a stored sample keeps of its clumps (JSON: numbers as repr text, exact)."""
        return {'clumpTemplates': [{'centres': [[repr(float(v)) for v in ci] for ci in c], 'radii': [repr(float(v))
                                    for v in r], 'volume': repr(v)} for c, r, v in self.templates],
                'clumps': [[repr(float(v)) for v in row] for row in self.rows()]}

    @classmethod
    def fromDocument(cls, doc):
        """The templates of a stored sample, registered with the scene."""
        t = [([[float(v) for v in ci] for ci in d['centres']], [float(v) for v in d['radii']], float(d['volume']))
             for d in doc['clumpTemplates']]
        obj = cls(t)
        runtime.register(obj)
        return obj

    def rebuild(self, doc, material):
        """The stored clumps placed again, O.bodies order of the store. Returns their ids."""
        g = np.array([[float(v) for v in row] for row in doc['clumps']]).reshape(-1, ROW)
        return [self.add(int(a[0]), _quaternion(*a[1:5]), a[5:8], a[8], material) for a in g]
