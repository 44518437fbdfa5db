"""The experiment base's fast-step option, density scaling (docs/performance.md; the parameter is
ballast.experiments.parameters.DENSITY_STEP, checked by checkDensityStep): how a scene is switched to it and kept on it
across O.save / O.load.
The per-body factors are the C++ core's (pkg/DensityScaling.hpp, through ballast.densityscaling)."""
from yade import O
from yade.wrapper import GlobalStiffnessTimeStepper

from .. import _ballast, harvest, runtime
from ..densityscaling import scaleDensities
from .chain import engine, insertBeforeNewton, newton

GUARD, SWITCH = 'densityScalingGuard', 'densityScalingSwitch'
STIFFNESS_UPDATE = 10   # [steps] timeStep stiffness: between two updates of YADE's GlobalStiffnessTimeStepper


def enableDensityScaling():
    """NewtonIntegrator.densityScaling on. YADE 2023.02a's setter only switches it on when it finds a
    GlobalStiffnessTimeStepper among the scene's current engines (and one running with densityScaling
    aborts on the Box plate): one stays in O.engines, dead and inactive, for the setter. It then works
    inside a step too, where a new O.engines takes effect only at the next one. (Reading the flag back
    makes YADE warn when no stepper is there, so the tests read it, not the runs.)"""
    if engine(SWITCH) is None:
        O.engines = O.engines + [GlobalStiffnessTimeStepper(dead=True, active=False, label=SWITCH)]
    newton().densityScaling = True
    engine(SWITCH).densityScaling = False  # the setter switched the stepper's on too


def startDensityScaling(exp, step, ownStep, others):
    """Density scaling from now on: O.dt = step [s], Newton's densityScaling on, every grain's own P-wave
    step ownStep [s] (the engines scale the grains they change, given scaledPWaveStep = ownStep), and
    `others` {body id: own critical step [s] or None}: the other bodies Newton moves (YADE's default
    factor, -1, would turn their accelerations around; None: not scaled). Puts exp's guard first in the
    chain (see Experiment.densityGuard)."""
    O.dt = step
    enableDensityScaling()
    O.engines = [runtime.callback(exp, 'densityGuard', iterPeriod=1, dead=True, label=GUARD)] + list(O.engines)
    scaleDensities(harvest.grains().ids, ownStep)
    for bid, own in others.items():
        O.bodies[bid].state.densityScaling = 1.0 if own is None else float(_ballast.densityScaling(own, ownStep))
    engineSteps(ownStep)


def engineSteps(ownStep):
    """The crushing and abrasion engines' scaledPWaveStep [s]: the grains they create or resize get the density
    scaling of the step. Without it the quasi-static option's first cycle (its step 4 times the paper's, the engines
    built with densityStep's 0) made fragments of unscaled density: at q_max 370 kPa on the triaxial, 124 crushes
    and an explosion in cycle 1 where the paper's step crushed one grain."""
    for label in ('crush', 'abrasion'):
        e = engine(label)
        if e is not None:
            e.scaledPWaveStep = ownStep


def changeDensityStep(step, ownStep, others):
    """Density scaling on already: the step [s] from the next step on, every grain's own P-wave step ownStep [s]
    (the factors set afresh from the grains' own densities), `others` as startDensityScaling, and the engines'
    scaledPWaveStep (the grains they change later)."""
    O.dt = step
    scaleDensities(harvest.grains().ids, ownStep)
    for bid, own in others.items():
        O.bodies[int(bid)].state.densityScaling = 1.0 if own is None else float(_ballast.densityScaling(own, ownStep))
    engineSteps(ownStep)


def startStiffnessStep(safety):
    """timeStep 'stiffness': YADE's GlobalStiffnessTimeStepper with the safety factor, every STIFFNESS_UPDATE
    steps, just before NewtonIntegrator; the current O.dt until its first update."""
    insertBeforeNewton([GlobalStiffnessTimeStepper(timestepSafetyCoefficient=safety, timeStepUpdateInterval=STIFFNESS_UPDATE,
                                                   defaultDt=O.dt, label='timeStepper')])
    O.dynDt = True
