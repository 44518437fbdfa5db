"""Density scaling that survives crushing (docs/performance.md, "Density scaling"): YADE's
State.densityScaling of a body set so that its own P-wave step r sqrt(rho / E) (eq. 5 for that body)
reaches a target, by the C++ core (pkg/DensityScaling.hpp); NewtonIntegrator.densityScaling must be on
for it to act. The engines call it for the grains they create, shrink or grow; the experiment for every
grain at the start. A loop over the given bodies only: a few per crush, all grains once. Radius, volume,
mass and modulus of a grain are its kind's (ballast.grainkinds): r is the radius of the grain's own step
(GrainKind.stepRadii: a sphere's radius, a clump's smallest member), the density its mass over its volume."""
import numpy as np
from yade import O

from . import _ballast, grainkinds


def scaleDensities(ids, ownStep):
    """Set densityScaling of the grains `ids` for an own P-wave step ownStep [s] (0: nothing to do) of
    r sqrt(rho / E), r the kind's stepRadii; each grain's density is its mass over its volume (keep='mass' fragments
    are denser)."""
    if ownStep <= 0 or len(ids) == 0:
        return
    kind, ids = grainkinds.current(), [int(i) for i in ids]
    r = kind.stepRadii(ids)
    rho = kind.masses(ids) / kind.volumes(ids)
    young = kind.moduli(ids)
    for b, s in zip((O.bodies[i] for i in ids), _ballast.densityScaling(_ballast.pWaveStep(r, rho, young), ownStep)):
        b.state.densityScaling = float(s)


def scaledDensity(radii, density, young, ownStep, stepRadii=None):
    """The grains' density as their inertia sees it [kg/m^3]: density over the mass-weighted mean of
    their densityScaling for an own step ownStep [s] (0: density itself), from the equivalent radii [m] (the masses
    weigh as r^3) and the radii of their own steps [m] (stepRadii as scaleDensities; default the radii)."""
    if ownStep <= 0 or len(radii) == 0:
        return density
    s = _ballast.densityScaling(_ballast.pWaveStep(radii if stepRadii is None else stepRadii, density, young),
                                ownStep)
    w = np.asarray(radii) ** 3
    return density * float(np.sum(w / s) / np.sum(w))
