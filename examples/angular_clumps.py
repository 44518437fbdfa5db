"""Angular clump templates for `--clumpFile`: random convex polyhedra filled with spheres, written as the CSV the
clump grains read (columns template, x, y, z, r; docs/grains.md, "Templates from a file").

    /usr/bin/python3 examples/angular_clumps.py OUT.csv [--templates 10] [--spheres 20] [--elongation 0.7]
        [--flatness 0.6] [--vertices 14] [--seed 1]
    yade -n -x scripts/oedometer.py --grain clump --clumpFile OUT.csv

Each template is the convex hull of `vertices` points uniform on the unit sphere, stretched to half-axes 1, e, e f
(e the elongation, f the flatness), then filled greedily: the largest sphere the hull holds first, then each time
the largest sphere that fits in the hull, overlaps a sphere already placed and whose centre none of them holds, out
of 20 000 candidate centres. The first spheres give the body, the later ones reach into its corners, so fewer
spheres give a rounder grain and more a sharper one (the union fills more of the hull: printed per template). A
choice of this example, not a measured ballast shape: replace it with spheres fitted to scanned grains where you
have them. Such a grain has no flat side: between the single-particle test's platens it tips and slides out instead
of carrying load (the built shapes lie on the flat of their core and tips); in a bed (oedometer, box, triaxial) it
interlocks as an angular grain does. No YADE needed: Debian's /usr/bin/python3 with python3-numpy and python3-scipy.
"""
import argparse
import sys

import numpy as np
from scipy.spatial import ConvexHull

CANDIDATES = 20000


def template(rng, elongation, flatness, vertices, spheres):
    """(centres (n, 3), radii (n,), the share of the hull's volume the union fills) of one filled polyhedron."""
    g = rng.normal(size=(vertices, 3))
    hull = ConvexHull(g / np.linalg.norm(g, axis=1)[:, None] * [1.0, elongation, elongation * flatness])
    lo, hi = hull.points.min(axis=0), hull.points.max(axis=0)
    x = lo + (hi - lo) * rng.random((CANDIDATES, 3))
    room = -(x @ hull.equations[:, :3].T + hull.equations[:, 3]).max(axis=1)   # distance to the nearest face
    x, room = x[room > 0], room[room > 0]
    c, r = [x[np.argmax(room)]], [room.max()]
    while len(r) < spheres:
        d = np.linalg.norm(x[:, None, :] - np.array(c)[None, :, :], axis=2)
        ok = np.all(d > r, axis=1) & np.any(d < room[:, None] + r, axis=1)   # uncovered, touching the clump
        if not ok.any():
            break
        k = np.flatnonzero(ok)[np.argmax(room[ok])]
        c.append(x[k])
        r.append(room[k])
    c, r = np.array(c), np.array(r)
    inside = np.any(np.linalg.norm(x[:, None, :] - c[None, :, :], axis=2) < r, axis=1)
    return c, r, float(np.mean(inside))


def main(argv=None):
    ap = argparse.ArgumentParser(prog='examples/angular_clumps.py', description=__doc__.split('\n\n')[0])
    ap.add_argument('out', help='the CSV file written')
    ap.add_argument('--templates', type=int, default=10, help='templates (default 10)')
    ap.add_argument('--spheres', type=int, default=20, help='spheres a template, 2 to 200 (default 20)')
    ap.add_argument('--elongation', type=float, default=0.7, help='I/L of the stretched hull, in (0, 1] (default 0.7)')
    ap.add_argument('--flatness', type=float, default=0.6, help='S/I of the stretched hull, in (0, 1] (default 0.6)')
    ap.add_argument('--vertices', type=int, default=14, help='points of each hull, at least 4 (default 14)')
    ap.add_argument('--seed', type=int, default=1, help='the random seed (default 1)')
    a = ap.parse_args(argv)
    for name, ok, allowed in (('templates', a.templates >= 1, 'at least 1'),
                              ('spheres', 2 <= a.spheres <= 200, 'from 2 to 200'),
                              ('elongation', 0 < a.elongation <= 1, 'in (0, 1]'),
                              ('flatness', 0 < a.flatness <= 1, 'in (0, 1]'),
                              ('vertices', a.vertices >= 4, 'at least 4')):
        if not ok:
            ap.error('--%s %s: expected %s' % (name, getattr(a, name), allowed))
    rng = np.random.default_rng(a.seed)
    rows = []
    for k in range(a.templates):
        c, r, filled = template(rng, a.elongation, a.flatness, a.vertices, a.spheres)
        rows += [(k, *ci, ri) for ci, ri in zip(c.tolist(), r.tolist())]
        print('template %d: %d spheres, %.0f %% of its hull filled' % (k, len(r), 100 * filled))
    with open(a.out, 'w') as fh:
        fh.write('template,x,y,z,r\n' + ''.join('%d,%r,%r,%r,%r\n' % row for row in rows))
    print('wrote %s' % a.out)
    return 0


if __name__ == '__main__':
    sys.exit(main())
