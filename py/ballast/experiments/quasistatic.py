"""What tells a cyclic run is quasi-static (issue 45, docs/performance.md): the inertial number of the bed under
the body that loads it (a plate, a sleeper), and the ratio of the load's period to the bed's slowest response
time. Both are reported per cycle in cycles.csv (:mod:`.cyclic`) by every cyclic experiment; a time scaling
(density scaling, ``densityStep``) is quasi-static while the first stays small (GDR MiDi 2004: I < 1e-3) and
the second large.

* I = gamma_dot d sqrt(rho / p) (pkg/InertialNumber.hpp): the loading body's speed over the bed's height, the
  grains' mean diameter, their density as their inertia sees it (density scaling included) and the grains'
  force on the loading body over its area.
* t_response = 2 pi sqrt(M / K): the period of the loading body and the whole bed as one mass M (their masses as
  their inertia sees them: an upper bound of the mass that moves, so a lower bound of the ratio) on the bed's
  resilient stiffness K = (the cycle's load range) / (its resilient deformation)."""
import math

import numpy as np

from .. import _ballast, harvest
from ..densityscaling import scaledDensity

LOADED = 0.01   # [-] I is reported once the grains carry this share of the peak load (p -> 0 looks inertial)
INERTIAL_BOUND = 1e-3   # [-] the quasi-static regime's inertial number (GDR MiDi 2004): above it a run warns


def inertialNumber(p, speed, height, force, area, peak):
    """The bed's inertial number [-] under a loading body moving at `speed` [m/s] over a bed `height` [m] high,
    the grains carrying `force` [N] over `area` [m^2]; NaN while they carry less than LOADED of the `peak` load
    [N] (the seating), or without grains. p: the run's parameters (density, young, the density step)."""
    radii = harvest.grains().radii
    if not (force >= LOADED * peak and height > 0 and len(radii)):
        return math.nan
    rho = scaledDensity(radii, p['density'], p['young'], p.scaledPWaveStep())
    return float(_ballast.inertialNumber(speed / height, 2 * float(np.mean(radii)), rho, force / area))


def bedMass(p, masses):
    """The grains' mass [kg] as their inertia sees it: their masses [kg] times the density scaling's factor."""
    radii = harvest.grains().radii
    return float(np.sum(masses)) * scaledDensity(radii, p['density'], p['young'], p.scaledPWaveStep()) / p['density']


def responseRatio(period, mass, loadRange, resilient):
    """The load's period [s] over the bed's slowest response time 2 pi sqrt(mass / K) [s], K = loadRange [N] /
    resilient [m]; NaN where the cycle has no resilient deformation to measure K from."""
    if not (resilient > 0 and loadRange > 0 and mass > 0):
        return math.nan
    return period / (2 * math.pi * math.sqrt(mass * resilient / loadRange))


def cycleStats(values):
    """(largest, median) of a cycle's inertial numbers, NaN where none was defined."""
    v = np.asarray([x for x in values if x is not None and math.isfinite(x)], dtype=float)
    return (float(v.max()), float(np.median(v))) if v.size else (math.nan, math.nan)
