"""The skeleton every built clump grows from (issue 47, item 1): its core, four tips and, where a tip does not reach
the core, the bridges of its arm. Pure geometry, no YADE: the builder (:mod:`ballast.grainkinds.clumpshapes`) and the
parameter check (:mod:`ballast.experiments.parameters`, which runs without YADE) both read it.
"""
import numpy as np

from .grainparams import CLUMP_SHAPE

ELONGATION = CLUMP_SHAPE['clumpElongation'].default
FLATNESS = CLUMP_SHAPE['clumpFlatness'].default
ROUNDNESS = CLUMP_SHAPE['clumpRoundness'].default
OVERLAP = 0.9   # neighbouring bridges' centre distance over their radii's sum, at most


def crossMembers(elongation=ELONGATION, flatness=FLATNESS, roundness=ROUNDNESS):
    """The members every built clump starts from, at L = 1 in its own frame: (centres (k, 3), radii (k,)) of the core
    (radius S = e f, at the origin), the four tips (radius t = roundness S, at (+-(1 - t), 0, 0), (0, +-(e - t), 0))
    and, on an arm whose tip does not overlap the core, bridges: equally spaced on the arm, their radii falling
    linearly from S to t (a tapered arm), as few as make each neighbour overlap the next by a tenth of their radii'
    sum (centre distance <= OVERLAP (r_i + r_j)). No bridge at roundness 1 and e f > 1/3: the clumps built before the
    roundness."""
    S = flatness * elongation
    t = roundness * S
    c, r = [(0.0, 0.0, 0.0)], [S]
    arms = []
    for half, axis in ((1.0, 0), (elongation, 1)):
        a = half - t   # the tip's centre on its axis
        for sign in (1.0, -1.0):
            tip = [0.0, 0.0, 0.0]
            tip[axis] = sign * a
            c.append(tuple(tip))
            r.append(t)
            arms.append((axis, sign, a))
    for axis, sign, a in arms:
        if a < S + t:
            continue
        k = 1
        while a / (k + 1) > OVERLAP * (S + (t - S) * k / (k + 1) + t):   # the last pair is the thinnest
            k += 1
        for j in range(1, k + 1):
            x = [0.0, 0.0, 0.0]
            x[axis] = sign * a * j / (k + 1)
            c.append(tuple(x))
            r.append(S + (t - S) * j / (k + 1))
    return np.array(c), np.array(r)
