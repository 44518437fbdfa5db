"""Where the grains broke in the box (docs/box.md, "Where the grains broke"), from the positions of the
crushes: the zone of each (under the sleeper, beside it, at the walls), its depth below the sleeper's
underside, and the paper's "local character" of crushing as numbers. Plain NumPy: no YADE.

Zones, in this order: 'wall' within one dMax of a side or end wall; 'under' below the sleeper's
footprint (|x - x_sleeper| <= w/2); 'beside' the rest of the bed.
"""
import numpy as np

ZONES = ('under', 'beside', 'wall')
DEPTH_BANDS = 5   # [-] bands of equal depth from the sleeper's underside to the box's floor


def zoneOf(x, y, boxLength, boxWidth, sleeperWidth, dMax, xSleeper=0.0):
    """The zone name of each point (x, y) [m] (arrays), box centred on the origin."""
    x, y = np.asarray(x, float), np.asarray(y, float)
    wall = (np.abs(x) > boxLength / 2 - dMax) | (np.abs(y) > boxWidth / 2 - dMax)
    under = np.abs(x - xSleeper) <= sleeperWidth / 2
    return np.where(wall, 'wall', np.where(under, 'under', 'beside'))


def table(x, y, z, zBase, geometry):
    """Crushes by zone and depth band: a dict {'bands': [(top, bottom)] depths [m], zone: [count per band]}.
    z [m] the crushes' heights, zBase the sleeper's underside at the start [m]; geometry: boxLength, boxWidth,
    sleeperWidth, dMax (and xSleeper)."""
    zone = zoneOf(x, y, **geometry)
    depth = zBase - np.asarray(z, float)
    edges = np.linspace(0.0, zBase, DEPTH_BANDS + 1)
    band = np.clip(np.searchsorted(edges, depth, side='right') - 1, 0, DEPTH_BANDS - 1)
    out = {'bands': [(float(a), float(b)) for a, b in zip(edges[:-1], edges[1:])]}
    for name in ZONES:
        out[name] = [int(np.sum((zone == name) & (band == k))) for k in range(DEPTH_BANDS)]
    return out


def localCharacter(x, y, z, zBase, crushedOriginal, nGrains, geometry):
    """How local the crushing was: the share of the bed's nGrains grains that crushed (crushedOriginal of
    them; their fragments' crushes not counted), the share of all crushes under the sleeper, and the
    crushes' median and 90th percentile depth below its underside [m] (NaN without crushes)."""
    n = len(np.asarray(x))
    zone = zoneOf(x, y, **geometry)
    depth = zBase - np.asarray(z, float)
    return {'crushedShare': crushedOriginal / nGrains if nGrains else float('nan'),
            'underShare': float(np.mean(zone == 'under')) if n else float('nan'),
            'depthMedian': float(np.median(depth)) if n else float('nan'),
            'depth90': float(np.percentile(depth, 90)) if n else float('nan')}
