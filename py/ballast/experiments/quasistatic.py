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

from .. import _ballast, harvest, runtime
from ..densityscaling import scaledDensity
from .parameters import QS_START_FACTOR as START_FACTOR   # the first cycle's step over the paper's, by default

LOADED = 0.01   # [-] I is reported once the grains carry this share of the peak load (p -> 0 looks inertial)
INERTIAL_BOUND = 1e-3   # [-] the quasi-static regime's inertial number (GDR MiDi 2004): above it a run warns


def inertialNumber(p, speed, height, force, area, peak, ownStep=None):
    """The bed's inertial number [-] under a loading body moving at `speed` [m/s] over a bed `height` [m] high,
    the grains carrying `force` [N] over `area` [m^2]; NaN while they carry less than LOADED of the `peak` load
    [N] (the seating), or without grains. p: the run's parameters (density, young); ownStep [s]: the grains' own
    step under density scaling now (default the parameters')."""
    table = harvest.grains()
    radii = table.radii
    if not (force >= LOADED * peak and height > 0 and len(radii)):
        return math.nan
    own = p.scaledPWaveStep() if ownStep is None else ownStep
    rho = scaledDensity(radii, p['density'], p['young'], own, table.stepRadii())
    return float(_ballast.inertialNumber(speed / height, 2 * float(np.mean(radii)), rho, force / area))


def bedMass(p, masses, ownStep=None):
    """The grains' mass [kg] as their inertia sees it: their masses [kg] times the density scaling's factor (ownStep
    as in inertialNumber)."""
    table = harvest.grains()
    own = p.scaledPWaveStep() if ownStep is None else ownStep
    return float(np.sum(masses)) * scaledDensity(table.radii, p['density'], p['young'], own,
                                                 table.stepRadii()) / p['density']


def responseRatio(period, mass, loadRange, resilient):
    """The load's period [s] over the bed's slowest response time 2 pi sqrt(mass / K) [s], K = loadRange [N] /
    resilient [m]; NaN where the cycle has no resilient deformation to measure K from."""
    if not (resilient > 0 and loadRange > 0 and mass > 0):
        return math.nan
    return period / (2 * math.pi * math.sqrt(mass * resilient / loadRange))


def ownStep(p, choice):
    """The grains' own P-wave step [s] under density scaling now: the quasi-static option's (choice, a StepChoice),
    else densityStep / dtSafety (0: none)."""
    return choice.step / p['dtSafety'] if choice is not None else p.scaledPWaveStep()


def cycleStats(values):
    """(largest, median) of a cycle's inertial numbers, NaN where none was defined."""
    v = np.asarray([x for x in values if x is not None and math.isfinite(x)], dtype=float)
    return (float(v.max()), float(np.median(v))) if v.size else (math.nan, math.nan)


# ---------------------------------------------------------------------------- the option: quasiStatic
GROWTH = 2.0         # [-] a cycle's step at most this many times the last one's
SAFETY = 0.7         # [-] the next step aims at SAFETY of the bounds: the measures of one cycle scatter
MIN_STEPS = 1000     # [steps] a load cycle is resolved by at least this many steps


@runtime.persistent('QuasiStaticStep')
class StepChoice:
    """The quasi-static option (quasiStatic I_MAX): the density step of each load cycle chosen from the last
    cycle's measures. Density scaling by a step dt makes the grains' inertia grow as dt^2, so the inertial number
    grows as dt and the response ratio falls as 1/dt: the next step is the one that puts the last cycle's largest I
    at SAFETY I_MAX and its ratio at ratioMin / SAFETY, at most GROWTH times the last step, at most a cycle over
    MIN_STEPS (and abrasionPeriod steps within a cycle), at least the paper's step. A cycle that broke a bound is
    marked; after one that broke the inertial bound (an avalanche, a grain flying: a dynamic event the scaled inertia
    may have changed) the next runs at the paper's step; after one that broke only the ratio bound the rule above
    shrinks the step to put the ratio back at ratioMin / SAFETY (the ratio goes as 1 / dt, so the cycle's own
    measure says how far; on the default box a cycle at the paper's step costs about 40 steady ones, and as many
    again while the step grows back).
    The first cycle runs at `start` times the paper's step (quasiStaticStart): its measures give the second's."""

    def __init__(self, paper=0.0, bound=0.0, ratioMin=0.0, period=0.0, abrasionPeriod=1, start=START_FACTOR):
        self.paper, self.bound, self.ratioMin, self.period = paper, bound, ratioMin, period
        self.largest = min(period / MIN_STEPS, period / max(abrasionPeriod, 1)) if period else paper
        self.step = max(paper, min(start * paper, self.largest))
        self.met = []        # per closed cycle: 1 if it kept both bounds, 0 if it broke one
        self.loaded = {}     # {body id: its own critical step [s] or None}: the loading body's scaling

    def state(self):
        return {k: getattr(self, k) for k in ('paper', 'bound', 'ratioMin', 'period', 'largest', 'step', 'met',
                                              'loaded')}

    @classmethod
    def fromState(cls, s, ref=None):
        obj = runtime.fromAttributes(cls, s)
        obj.loaded = {int(k): v for k, v in obj.loaded.items()}   # JSON keys are text
        return obj

    def cycleClosed(self, inertialMax, ratio):
        """The closed cycle's largest inertial number and response ratio: whether it kept the bounds, and the
        next cycle's step [s]."""
        inertial = math.isfinite(inertialMax) and inertialMax > self.bound
        self.met.append(0 if inertial or (math.isfinite(ratio) and ratio < self.ratioMin) else 1)
        if inertial:
            self.step = self.paper
            return self.step
        limits = [GROWTH]
        if math.isfinite(inertialMax) and inertialMax > 0:
            limits.append(SAFETY * self.bound / inertialMax)
        if math.isfinite(ratio):
            limits.append(SAFETY * ratio / self.ratioMin)
        self.step = max(self.paper, min(self.step * min(limits), self.largest))
        return self.step
