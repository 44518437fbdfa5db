"""The grains (spheres) of the current scene as arrays, and how far they are from rest: what every
experiment reads of its sample. A loop over the bodies: at phase ends, per chunk and at the end only."""
import math

import numpy as np
from yade import O, utils
from yade.wrapper import Sphere


def spheres():
    return [b for b in O.bodies if b is not None and isinstance(b.shape, Sphere)]


def arrays():
    """(centres [m], radii [m], masses [kg]) of the grains."""
    bs = spheres()
    if not bs:
        return np.zeros((0, 3)), np.zeros(0), np.zeros(0)
    x = np.array([[b.state.pos[0], b.state.pos[1], b.state.pos[2]] for b in bs])
    return x, np.array([b.shape.radius for b in bs]), np.array([b.state.mass for b in bs])


def unbalanced():
    """YADE's unbalanced force [-] (1 where it is not defined)."""
    u = utils.unbalancedForce()
    return u if math.isfinite(u) else 1.0


def vRms():
    """Root mean square grain speed [m/s], sqrt(2 Ek / mass): the grains rest when it is small."""
    m = arrays()[2]
    return math.sqrt(2 * utils.kineticEnergy() / max(np.sum(m), 1e-300))


def restInfo():
    return 'unbalanced %.3g  v_rms %.2g m/s' % (unbalanced(), vRms())
