"""Member spheres of a ballast-like clump from shape descriptors (issue 47, item 1); no YADE.

Descriptors, as the flakiness and elongation of aggregate grains are read (EN 933-3/4 style axis ratios):
elongation e = I/L (intermediate over long axis), flatness f = S/I (short over intermediate), both in
(0, 1]. A clump of n spheres is built in its own frame, long axis x, intermediate y, short z, with
half-extents (L, I, S) = (1, e, e f) before scaling:

* a core sphere of radius S at the origin and four tips of radius t = rho S (rho the roundness, default 1) at
  (+-(L - t), 0, 0), (0, +-(I - t), 0), so the member cloud's extents are exactly 2L, 2I, 2S (the descriptors
  hold exactly for any n), and where a tip does not reach the core the bridges of its arm
  (:func:`ballast.clumpcross.crossMembers`);
* the other spheres, radius uniform in [0.6, 1] rho S, centres uniform in the box |x| <= L - r, |y| <= I - r,
  |z| <= S - r and kept only where they overlap a sphere already placed (numpy Generator(seed): the same
  seed gives the same clump);
* all scaled so the union's volume-equivalent radius is r_eq: (3 V_union / (4 pi))^(1/3) = r_eq.

The union volume of overlapping spheres is estimated by Monte Carlo over the bounding box with a fixed
seed (:func:`unionVolume`): with N points and a hit fraction p, its relative standard error is
sqrt((1 - p)/(p N)); the default N = 400 000 gives about 0.1 % on V, 0.04 % on r_eq. The returned
volume is the estimate scaled with the clump (V r_eq^3 / r_eq0^3 = 4/3 pi r_eq^3 exactly by construction).

Defaults (choices, stated as such): e = 0.7, f = 0.6, rho = 1, n = 8: a moderately elongated and flat grain. No
published measurement of railway ballast's axis ratios was found in the sources searched; the descriptor
definitions (Ei = b/a, Fi = c/b, a >= b >= c) are those of e.g. the SHPSG shape generator
(github.com/budizhao/SHPSG). Replace the defaults with measured ones when they are at hand.

Templates can also come from a CSV file (:func:`ballast.templatefile.readTemplates`, the experiments'
``clumpFile``), each put in its principal frame at r_eq = 1 (:func:`principalTemplate`), for shapes the descriptors
do not give.
"""
import math

import numpy as np

from ..clumpcross import ELONGATION, FLATNESS, ROUNDNESS, crossMembers
from ..grainparams import CLUMP_SHAPE, MAX_SPHERES, MIN_SPHERES

# the defaults are the experiments' declarations (ballast.grainparams), declared once
N_SPHERES = CLUMP_SHAPE['clumpSpheres'].default
SAMPLES = 400000
SHELL_SAMPLES = 20000   # shellOutside: about 1 % on a worn member's loss for p > 0.3
_RADIUS_SPREAD = 0.6      # extra members' radii in [0.6, 1] rho S
_TRIES = 10000            # candidate centres per extra member before giving up


def _check(name, value, ok, allowed):
    if not ok:
        raise ValueError('%s: expected %s, got %r' % (name, allowed, value))


def unionVolume(centres, radii, samples=SAMPLES, seed=0):
    """(V [m^3], its standard error [m^3]) of the union of spheres (centres (n, 3), radii (n,)) by Monte
    Carlo: N uniform points in the bounding box, V = V_box p, s.e. = V_box sqrt(p (1 - p) / N)."""
    vbox, hits, _ = _sample(centres, radii, None, samples, seed)
    p = hits / samples
    return vbox * p, vbox * math.sqrt(p * (1 - p) / samples)


def pieceShares(centres, radii, piece, samples=SAMPLES, seed=0):
    """The share of each piece of a split clump in the clump's union volume [-], an array of max(piece) + 1 (piece:
    the piece of each sphere, 0 ... k-1), from the same Monte Carlo points as :func:`unionVolume`'s (same box, seed
    and count). The union is partitioned: a point inside members of several pieces (their overlap, cut by a plane)
    goes to the piece of the member it lies deepest in (largest r - |x - c|, the side of the lens's radical plane
    for equal spheres), so the shares sum to 1 exactly and the pieces' volumes, V times their shares, to V."""
    piece = np.asarray(piece, dtype=np.int64).reshape(-1)
    _check('piece', piece, len(piece) == len(np.asarray(centres).reshape(-1, 3)) and len(piece) > 0
           and piece.min() >= 0, 'one piece index >= 0 per sphere')
    _, hits, each = _sample(centres, radii, piece, samples, seed)
    return each / hits


def containers(centres, radii):
    """For each sphere, the index of the sphere that holds it whole (r_i - |c_i - c_j| >= r_j; of several, the one
    with the largest margin; of two equal spheres at one place, the first), -1 where none does. A sphere held whole
    adds nothing to the union: it belongs with its holder wherever a plane cuts."""
    c = np.asarray(centres, dtype=float).reshape(-1, 3)
    r = np.asarray(radii, dtype=float).reshape(-1)
    n = len(r)
    margin = r[:, None] - np.linalg.norm(c[:, None, :] - c[None, :, :], axis=2) - r[None, :]   # [holder, held]
    idx = np.arange(n)
    bigger = (r[:, None] > r[None, :]) | ((r[:, None] == r[None, :]) & (idx[:, None] < idx[None, :]))
    margin = np.where((margin >= 0) & bigger, margin, -np.inf)
    holder = np.argmax(margin, axis=0)
    out = np.where(np.isfinite(margin[holder, idx]), holder, -1)
    for _ in range(n):   # a holder held itself (a tie of margins): up to the one nothing holds
        up = np.where(out >= 0, out[np.maximum(out, 0)], -1)
        if not np.any(up >= 0):
            break
        out = np.where(up >= 0, up, out)
    return out


def crossPairs(centres, radii, piece):
    """(k, 2) indices (i < j) of the spheres that overlap (|c_i - c_j| < r_i + r_j) and lie in different pieces. Taken
    over every member of a split clump with its final pieces: a member held whole by another, or moved by absorbEmpty,
    is cut without the planes' own pairs, and an overlap of it with another piece left as an ordinary contact would
    be a spring pressed by up to its whole radius (issue 47: the clump box's explosion)."""
    c = np.asarray(centres, dtype=float).reshape(-1, 3)
    r = np.asarray(radii, dtype=float).reshape(-1)
    piece = np.asarray(piece, dtype=np.int64).reshape(-1)
    d = np.linalg.norm(c[:, None, :] - c[None, :, :], axis=2)
    i, j = np.nonzero(np.triu((d < r[:, None] + r[None, :]) & (piece[:, None] != piece[None, :]), 1))
    return np.stack([i, j], axis=1)


def absorbEmpty(centres, radii, piece, shares):
    """(piece, shares) with every piece of no share of the volume (its members lie wholly deeper in other pieces'
    members, e.g. a small member inside the core: pieceShares gives it no point) absorbed: each of its members
    joins the piece of the member of a piece with volume it lies deepest in (largest r_i - |x_j - c_i|); pieces
    renumbered 0 ... k-1 in their order, shares of those kept. A piece of no volume would be a grain of no mass."""
    piece = np.asarray(piece, dtype=np.int64).reshape(-1).copy()
    shares = np.asarray(shares, dtype=float).reshape(-1)
    keep = shares > 0
    if keep.all():
        return piece, shares
    c = np.asarray(centres, dtype=float).reshape(-1, 3)
    r = np.asarray(radii, dtype=float).reshape(-1)
    hosts = np.flatnonzero(keep[piece])
    for j in np.flatnonzero(~keep[piece]):
        depth = r[hosts] - np.linalg.norm(c[hosts] - c[j], axis=1)
        piece[j] = piece[hosts[int(np.argmax(depth))]]
    new = np.cumsum(keep) - 1   # old piece -> new index (for the kept ones)
    return new[piece], shares[keep]


def shellOutside(centre, r, rNew, centres, radii, samples=SHELL_SAMPLES, seed=0):
    """(V [m^3], its standard error [m^3]) of the part of the shell rNew <= |x - centre| <= r outside every sphere
    (centres (n, 3), radii (n,); n may be 0): what the union of that sphere and those loses when the sphere shrinks
    from r to rNew about its centre (issue 47, item 3). Monte Carlo on N points uniform in the shell (direction
    uniform, radius by the inverse of the shell's cumulative volume): with a fraction p outside, V = V_shell p and
    s.e. = V_shell sqrt(p (1 - p) / N), V_shell = 4/3 pi (r^3 - rNew^3). Sampling the shell alone, not the union's
    box, gives the loss, a small difference of two unions, to its own relative error."""
    x0 = np.asarray(centre, dtype=float).reshape(-1)
    _check('centre', centre, x0.shape == (3,) and np.all(np.isfinite(x0)), 'a finite point (x, y, z) [m]')
    _check('r', r, np.isscalar(r) and math.isfinite(r) and r > 0, 'a finite radius > 0 [m]')
    _check('rNew', rNew, np.isscalar(rNew) and math.isfinite(rNew) and 0 < rNew <= r, 'a radius in (0, r = %r] [m]' % r)
    c = np.asarray(centres, dtype=float).reshape(-1, 3)
    rr = np.asarray(radii, dtype=float).reshape(-1)
    _check('radii', radii, len(rr) == len(c) and np.all(rr > 0) and np.all(np.isfinite(rr)),
           'as many positive finite radii as centres (%d)' % len(c))
    _check('samples', samples, int(samples) == samples and samples >= 1000, 'an integer >= 1000')
    vShell = 4.0 / 3.0 * math.pi * (r ** 3 - rNew ** 3)
    rng = np.random.default_rng(seed)
    out, done, chunk = 0, 0, 50000
    while done < samples:
        m = min(chunk, samples - done)
        u = rng.standard_normal((m, 3))
        u /= np.linalg.norm(u, axis=1)[:, None]
        p = x0 + u * ((rNew ** 3 + (r ** 3 - rNew ** 3) * rng.random(m)) ** (1.0 / 3.0))[:, None]
        inside = np.zeros(m, dtype=bool)
        for ci, ri in zip(c, rr):
            inside |= np.einsum('ij,ij->i', p - ci, p - ci) <= ri * ri
        out += m - int(inside.sum())
        done += m
    q = out / samples
    return vShell * q, vShell * math.sqrt(q * (1 - q) / samples)


def _sample(centres, radii, piece, samples, seed):
    """(V_box [m^3], points inside the union, points of each piece (one piece without pieces)): a point inside the
    union belongs to the piece of the member it lies deepest in."""
    c = np.asarray(centres, dtype=float).reshape(-1, 3)
    r = np.asarray(radii, dtype=float).reshape(-1)
    _check('radii', radii, len(r) == len(c) and len(r) > 0 and np.all(r > 0) and np.all(np.isfinite(r)),
           'as many positive finite radii as centres (%d)' % len(c))
    _check('samples', samples, int(samples) == samples and samples >= 1000, 'an integer >= 1000')
    k = 1 if piece is None else int(piece.max()) + 1
    piece = np.zeros(len(c), dtype=np.int64) if piece is None else piece
    lo, hi = (c - r[:, None]).min(axis=0), (c + r[:, None]).max(axis=0)
    rng = np.random.default_rng(seed)
    hits, each, done, chunk = 0, np.zeros(k, dtype=np.int64), 0, 50000
    while done < samples:
        m = min(chunk, samples - done)
        p = lo + (hi - lo) * rng.random((m, 3))
        d2 = np.stack([np.einsum('ij,ij->i', p - ci, p - ci) for ci in c])   # (n, m) squared distances
        inside = (d2 <= (r * r)[:, None]).any(axis=0)
        hits += int(inside.sum())
        deepest = np.argmax(r[:, None] - np.sqrt(d2[:, inside]), axis=0)
        each += np.bincount(piece[deepest], minlength=k)
        done += m
    return float(np.prod(hi - lo)), hits, each


def _overlapsAny(x, r, centres, radii):
    d = np.linalg.norm(np.asarray(centres) - x, axis=1)
    return bool(np.any(d < np.asarray(radii) + r))


def clumpMembers(rEq, elongation=ELONGATION, flatness=FLATNESS, n=N_SPHERES, seed=0, samples=SAMPLES,
                 roundness=ROUNDNESS):
    """Members of a clump in its own frame (long axis x, short z), scaled to the equivalent radius rEq [m].
    Returns (centres (n, 3) [m] relative to the union's bounding-box centre, radii (n,) [m], V [m^3] the
    union's volume 4/3 pi rEq^3, its Monte Carlo standard error [m^3]). See the module doc."""
    _check('rEq', rEq, np.isscalar(rEq) and math.isfinite(rEq) and rEq > 0, 'a finite radius > 0 [m]')
    for name, v in (('elongation', elongation), ('flatness', flatness), ('roundness', roundness)):
        _check(name, v, np.isscalar(v) and math.isfinite(v) and 0 < v <= 1, 'a ratio in (0, 1]')
    _check('n', n, isinstance(n, (int, np.integer)) and not isinstance(n, bool) and MIN_SPHERES <= n <= MAX_SPHERES,
           'an integer number of spheres in [%d, %d]' % (MIN_SPHERES, MAX_SPHERES))
    L = 1.0
    I = elongation * L
    S = flatness * I
    c, r = crossMembers(elongation, flatness, roundness)
    if len(r) > n:
        raise ValueError('n: %d spheres cannot hold the core, the four tips and the %d bridges of elongation %r, '
                         'flatness %r, roundness %r; expected n >= %d' % (n, len(r) - 5, elongation, flatness,
                                                                          roundness, len(r)))
    c, r = [tuple(x) for x in c.tolist()], r.tolist()
    rng = np.random.default_rng(seed)
    while len(c) < n:
        for _ in range(_TRIES):
            ri = S * (_RADIUS_SPREAD + (1 - _RADIUS_SPREAD) * rng.random()) * roundness
            x = (rng.random(3) * 2 - 1) * np.array([L - ri, I - ri, S - ri])
            if _overlapsAny(x, ri, c, r):
                c.append(tuple(x))
                r.append(ri)
                break
        else:  # pragma: no cover - a box of positive size always holds overlapping candidates
            raise RuntimeError('clumpMembers: no overlapping member found in %d tries' % _TRIES)
    c, r = np.array(c), np.array(r)
    v0, err0 = unionVolume(c, r, samples=samples, seed=seed)
    s = rEq / (3.0 * v0 / (4.0 * math.pi)) ** (1.0 / 3.0)
    return c * s, r * s, v0 * s ** 3, err0 * s ** 3


def principalExtents(centres, radii):
    """Extents [m] of the member cloud along x, y, z of the clump's frame: max(c + r) - min(c - r)."""
    c = np.asarray(centres, dtype=float)
    r = np.asarray(radii, dtype=float)[:, None]
    return (c + r).max(axis=0) - (c - r).min(axis=0)


def principalTemplate(centres, radii, samples=SAMPLES, seed=0):
    """A template as clumpMembers builds them: turned to its principal axes (the largest second moment of its spheres'
    volumes about their centroid along x, the smallest along z, so a grain laid flat lies on its flat side), centred
    on its spheres' bounding box and scaled so the union's volume-equivalent radius is 1. Returns (centres (n, 3),
    radii (n,), V, its Monte Carlo standard error) as clumpMembers (V = 4/3 pi by construction)."""
    c = np.asarray(centres, dtype=float).reshape(-1, 3)
    r = np.asarray(radii, dtype=float).reshape(-1)
    w = r ** 3
    d = c - (w[:, None] * c).sum(axis=0) / w.sum()
    # each sphere's own second moment is r^2/5 about any axis through its centre
    M = np.einsum('i,ij,ik->jk', w, d, d) + np.eye(3) * float(np.sum(w * r ** 2)) / 5
    axes = np.linalg.eigh(M)[1][:, ::-1]   # columns: the largest moment first
    if np.linalg.det(axes) < 0:
        axes[:, 2] = -axes[:, 2]   # a rotation, not a mirror image
    c = d @ axes
    c -= ((c - r[:, None]).min(axis=0) + (c + r[:, None]).max(axis=0)) / 2
    v0, err0 = unionVolume(c, r, samples=samples, seed=seed)
    s = (4.0 * math.pi / (3.0 * v0)) ** (1.0 / 3.0)
    return c * s, r * s, v0 * s ** 3, err0 * s ** 3
