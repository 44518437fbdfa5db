"""The grains of the current scene as arrays, and how far they are from rest: what every experiment
reads of its sample. What a grain is comes from the scene's grain kind (ballast.grainkinds): walls,
facets, platens, sleepers and a membrane's nodes are never grains. A loop over the bodies: at phase
ends, per chunk and at the end only."""
import math

import numpy as np
from yade import O, utils

from .. import grainkinds


def kind():
    """The current scene's grain kind (ballast.grainkinds.current())."""
    return grainkinds.current()


def bodies():
    """The grains (yade Bodies), O.bodies order, dynamic or not."""
    return kind().bodies()


def spheres():
    """The grains (yade Bodies): the name of the time when a grain was always a sphere; see bodies()."""
    return bodies()


def erase(ids):
    """The grains ids taken out of the scene, a clump with its members (YADE's erase leaves them free)."""
    for i in ids:
        O.bodies.erase(i, O.bodies[i].isClump)


def arrays():
    """(centres [m], equivalent radii [m], masses [kg]) of the grains, O.bodies order."""
    k = kind()
    ids = k.ids()
    if not len(ids):
        return np.zeros((0, 3)), np.zeros(0), np.zeros(0)
    return k.centres(ids), k.radii(ids), k.masses(ids)


def bounds():
    """(lo, hi), each (n, 3) [m]: the box each grain fills, O.bodies order (the kind's: a sphere's centre -+ its
    radius, a clump's members', a polyhedron's vertices'), where a plate or a sleeper is seated."""
    k = kind()
    return k.bounds(k.ids())


def top():
    """The height of the grains' highest point [m] (bounds), where a plate is seated."""
    return float(np.max(bounds()[1][:, 2]))


def volumes():
    """Volumes [m^3] of the grains, O.bodies order."""
    k = kind()
    return k.volumes(k.ids())


def sieve():
    """(diameters [m] a sieve sees, masses [kg]) of the grains: what ballast.grading.passing takes."""
    k = kind()
    ids = k.ids()
    return k.sieveDiameters(ids), k.masses(ids)


def vtk():
    """(centres [m], radii [m] to draw, ids) of the grains for a VTK file."""
    k = kind()
    ids = k.ids()
    return k.centres(ids), k.vtkRadii(ids), ids


def unbalanced():
    """YADE's unbalanced force [-] (1 where it is not defined)."""
    u = utils.unbalancedForce()
    return u if math.isfinite(u) else 1.0


def vRms():
    """Root mean square grain speed [m/s], sqrt(2 Ek / mass): the grains rest when it is small."""
    m = arrays()[2]
    return math.sqrt(2 * utils.kineticEnergy() / max(np.sum(m), 1e-300))


def restInfo():
    """One progress-line word on rest: unbalanced force and v_rms."""
    return 'unbalanced %.3g  v_rms %.2g m/s' % (unbalanced(), vRms())
