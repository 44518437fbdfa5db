"""Grading of ballast and breakage indices (issue 12): the percentage passing each sieve by mass, and
Marsal's, Hardin's and Indraratna's breakage indices between two gradings. Plain NumPy: no YADE.

A grain passes a square-mesh sieve of aperture a when its sieve diameter d <= a: a sphere's diameter,
in general the grain kind's (ballast.grainkinds: GrainKind.sieveDiameters, 2 r_eq; the experiments read
it with experiments.grains.sieve()). Sieves (SIEVES_MM): the railway ballast sieves of EN 13450 (22.4,
31.5, 40, 50, 63, 80 mm; 0.5 mm for fine particles and 0.063 mm for fines) and the ISO 565 R20 sizes
between them down to the smallest fragment (1, 2, 4, 8, 11.2, 16 mm). Mass lost by a replacement (the
volume the fragments do not fill) can be counted as fines that pass the finest sieve, as a sieve
analysis of a real sample would see the dust.
docs/grading.md gives the definitions and references.
"""
import numpy as np

SIEVES_MM = (0.063, 0.5, 1.0, 2.0, 4.0, 8.0, 11.2, 16.0, 22.4, 31.5, 40.0, 50.0, 63.0, 80.0)
HARDIN_D0_MM = 0.074  # [mm] Hardin's lower limit of breakage potential (the No. 200 sieve)
BBI_FINEST_MM = 0.075  # [mm] where our boundary of maximum breakage reaches 0 % passing (the 75 um sieve)
ROUNDING = 1e-10  # [%] a shortfall from 100 % passing this small is the rounding of a sum of masses


def passing(diameters, masses, sieves=SIEVES_MM, fines=0.0):
    """Percentage passing each sieve by mass [%]: sieve diameters [m] and masses [kg] of the grains, sieve
    apertures [mm], fines [kg] of dust counted as passing every sieve."""
    d = np.asarray(diameters, dtype=float) * 1e3
    m = np.asarray(masses, dtype=float)
    total = float(np.sum(m)) + fines
    if total <= 0:
        raise ValueError('passing: no mass to grade (total %r kg)' % total)
    order = np.argsort(d, kind='stable')
    below = np.concatenate([[0.0], np.cumsum(m[order])])[np.searchsorted(d[order], sieves, side='right')]
    P = 100.0 * (below + fines) / total
    P[np.asarray(sieves) >= (d.max() if len(d) else 0.0)] = 100.0  # everything passes: exactly 100, not 100 - 1e-14
    return P


def retained(P):
    """Percentage by mass in each sieve interval, from the pan (below the finest sieve) to above the
    coarsest: len(P) + 1 values summing to 100."""
    P = np.asarray(P, dtype=float)
    return np.diff(np.concatenate([[0.0], P, [100.0]]))


def marsal(before, after):
    """Marsal's breakage index B_g [%] (Marsal 1967): the sum of the positive decreases of the
    percentage retained in each sieve interval, from before to after (percentages passing, one sieve
    series)."""
    return float(np.sum(np.maximum(retained(before) - retained(after), 0.0)))


def breakagePotential(P, sieves=SIEVES_MM, d0=HARDIN_D0_MM):
    """Hardin's breakage potential B_p (Hardin 1985): the integral over the mass of log10(D / d0) for
    grains above d0, i.e. the area between 100 % passing and the grading curve (fraction passing
    against log10 of the size, linear between sieves) from d0 to the first sieve that passes
    everything."""
    x = np.log10(np.asarray(sieves, dtype=float))
    f = np.asarray(P, dtype=float) / 100.0
    top = _topIndex(P, sieves, 'breakagePotential')
    x0 = np.log10(d0)
    grid = np.concatenate([[x0], x[(x > x0) & (np.arange(len(x)) <= top)]])
    g = 1.0 - np.interp(grid, x, f, left=f[0])     # the fraction retained above each size
    if x0 >= x[top]:
        return 0.0
    return float(np.trapz(g, grid))


def hardin(before, after, sieves=SIEVES_MM):
    """Hardin's relative breakage B_r = (B_p(before) - B_p(after)) / B_p(before) [-]."""
    bp = breakagePotential(before, sieves)
    return (bp - breakagePotential(after, sieves)) / bp if bp > 0 else 0.0


def _topIndex(P, sieves, who):
    """Index of the first sieve that passes all of a grading (to ROUNDING); the coarsest must."""
    P = np.asarray(P, dtype=float)
    if P[-1] < 100.0 - ROUNDING:
        raise ValueError('%s: %.3g %% is retained on the coarsest sieve (%g mm); add a coarser sieve'
                         % (who, 100 - P[-1], sieves[-1]))
    return int(np.argmax(P >= 100.0 - ROUNDING))


def topSize(P, sieves=SIEVES_MM):
    """The smallest sieve that passes 100 % of a grading [mm]."""
    return float(sieves[_topIndex(P, sieves, 'topSize')])


def bbi(before, after, sieves=SIEVES_MM, finest=BBI_FINEST_MM, top=None):
    """Indraratna's ballast breakage index BBI = A / (A + B) [-] (Indraratna, Lackenby & Christie 2005):
    on the grading chart (percentage passing against log10 of the size), A is the area between the
    grading after and the grading before, B the area between the boundary of maximum breakage and the
    grading after. The reference draws that boundary by hand ("arbitrary"); ours is the straight line
    from 0 % passing at `finest` [mm] to 100 % at `top` [mm] (default: the top size of the grading
    before), both curves linear in log10(size) between the sieves, areas over [finest, top]. 0 without
    breakage, 1 when the grading after lies on the boundary. Both gradings are taken at most up to the
    boundary: what passes above it is dust finer than the boundary allows (the lost volume counted as
    fines, below 0.075 mm), maximum breakage already, so BBI stays in [0, 1]; summary.json reports that
    dust apart (dustPercent)."""
    top = topSize(before, sieves) if top is None else float(top)
    if not 0 < finest < top:
        raise ValueError('bbi: the boundary needs 0 < finest < top, got finest = %r mm, top = %r mm' % (finest, top))
    xs = np.log10(np.asarray(sieves, dtype=float))
    x0, x1 = np.log10(finest), np.log10(top)
    x = np.concatenate([[x0], xs[(xs > x0) & (xs < x1)], [x1]])
    boundary = 100.0 * (x - x0) / (x1 - x0)
    b = np.minimum(np.interp(x, xs, np.asarray(before, dtype=float)), boundary)
    a = np.maximum(np.minimum(np.interp(x, xs, np.asarray(after, dtype=float)), boundary), b)
    A = float(np.trapz(a - b, x))
    AB = float(np.trapz(boundary - b, x))  # A + B
    return A / AB if AB > 0 else 0.0
