"""Density scaling that survives crushing (docs/performance.md, "Density scaling"): YADE's
State.densityScaling of a body set so that its own P-wave step r sqrt(rho / E) (eq. 5 for that body)
reaches a target, by the C++ core (pkg/DensityScaling.hpp); NewtonIntegrator.densityScaling must be on
for it to act. The engines call it for the grains they create, shrink or grow; the experiment for every
grain at the start. A loop over the given bodies only: a few per crush, all grains once."""
import numpy as np
from yade import O

from . import _ballast
from .geometry import sphereVolume


def scaleDensities(ids, ownStep):
    """Set densityScaling of the spheres `ids` for an own P-wave step ownStep [s] (0: nothing to do); each
    body's density is its mass over its volume (keep='mass' fragments are denser)."""
    if ownStep <= 0 or len(ids) == 0:
        return
    bodies = [O.bodies[int(i)] for i in ids]
    r = np.array([b.shape.radius for b in bodies])
    rho = np.array([b.state.mass for b in bodies]) / sphereVolume(r)
    young = np.array([b.material.young for b in bodies])
    for b, s in zip(bodies, _ballast.densityScaling(_ballast.pWaveStep(r, rho, young), ownStep)):
        b.state.densityScaling = float(s)


def scaledDensity(radii, density, young, ownStep):
    """The grains' density as their inertia sees it [kg/m^3]: density over the mass-weighted mean of
    their densityScaling for an own step ownStep [s] (0: density itself), from the radii [m] alone."""
    if ownStep <= 0 or len(radii) == 0:
        return density
    s = _ballast.densityScaling(_ballast.pWaveStep(radii, density, young), ownStep)
    w = np.asarray(radii) ** 3
    return density * float(np.sum(w / s) / np.sum(w))
