"""Parameters of the single-particle crushing test, declared once (the library, the command line and
study tables use these names). The materials, the contact law and the crushing model are the
declarations every experiment shares (:mod:`ballast.experiments.parameters`: the same grains, the same
steel); the test's own are the sample of grains, the platens' speed and when a grain counts as not
crushed. Needs no YADE."""
from ...params import Param, between, intBetween, numberList, positive
from ..parameters import (CONTACT, DENSITY_STEP, ENGINES, GRAIN, GRAINS, INTEGRATION, RUN, SEED, STEEL, TIME_STEP,
                          ExperimentParameters, take)
from .closedform import crushingForce

DIAMETERS = (1e-3, 0.3)   # [m] the sizes of ballast grains (EN 13450: 22.4-63 mm) and of the fragments they give
OWNER = 'SingleParticle'

PARAMS = {
    'seed': SEED.withDefault(1, 'the sample: grain sizes, Weibull strengths, fragment orientations'),
    'n': Param(30, '-', 'grains crushed, each between its own pair of platens', intBetween(1, 10000),
               'an integer in [1, 10000]'),
    'diameters': Param((), 'm', 'the grains\' diameters (then n is their number); empty: n diameters uniform in '
                       '[dMin, dMax]', numberList(positive), 'a list of numbers > 0, e.g. [0.025, 0.04]'),
    'classes': Param(3, '-', 'size classes of equal width in [dMin, dMax] that the Weibull statistics are given '
                     'for (1: one class)', intBetween(1, 50), 'an integer in [1, 50]'),
    'speed': Param(0.01, 'm/s', 'closing speed of each pair of platens (the top one moves, the bottom one is fixed); '
                   'quasi-static when the grain\'s inertia is a small share of the load (inertiaRatioMax in '
                   'summary.json)', positive, 'a number > 0'),
    'maxStrain': Param(0.01, '-', 'a grain not crushed when its platens have closed by this fraction of its diameter '
                       'is reported as not crushed', between(1e-4, 0.5), 'a number in [1e-4, 0.5)'),
    'Tc': ENGINES['Tc'].withDefault(0.0, 'crushing period T_c: the criterion is checked every Tc (0 = every step, the '
                                    'default here: the force at the crush is then resolved to one step)'),
    'ft0': ENGINES['ft0'],
    'rMin': ENGINES['rMin'].withDefault(0.0, 'grains smaller than rMin never crush (0: every grain of the test can)'),
    'timeStep': TIME_STEP,
    'densityStep': DENSITY_STEP.withDefault(0.0, DENSITY_STEP.doc + '; the platens move at a set speed (not scaled); '
                                            'inertiaRatioMax says what the heavier grain costs'),
    **GRAINS,
    **GRAIN,
    **STEEL,
    **take(CONTACT, 'law'),
    **take(INTEGRATION, 'damping', 'dtSafety'),
    **take(ENGINES, 'm', 'pattern', 'criterion', 'weibullModulus'),
    **RUN,
}


class SingleParticleParameters(ExperimentParameters):
    """The test's checked parameters (frozen) and what follows from them."""

    OWNER, PARAMS = OWNER, PARAMS
    POLYHEDRA = True   # grain 'polyhedron' too (docs/grains.md, "Polyhedra")

    def grainCount(self):
        return len(self['diameters']) or self['n']

    def smallestDiameter(self):
        """The smallest of the diameters given, else dMin."""
        return min(self['diameters']) if self['diameters'] else self['dMin']

    def expectedForce(self, d, height=None):
        """The closed-form force [N] that crushes a grain of diameter d [m] (volume-equivalent) and height [m] between
        the platens (None: a sphere's) of characteristic strength (closedform.crushingForce)."""
        return crushingForce(self['criterion'], d / 2, self['ft0'], self['m'], height)

    def crossCheck(self):
        p, bad = self, self.bad
        self.checkSizes()
        self.checkGrain()
        if p['diameters'] and p['n'] != PARAMS['n'].default and p['n'] != len(p['diameters']):
            bad('n', 'given with %d diameters: give one or the other' % len(p['diameters']))
        lo, hi = DIAMETERS
        odd = [d for d in p['diameters'] if not lo <= d <= hi]
        if odd:
            bad('diameters', '%g m is outside %g-%g m, the sizes of ballast grains and their fragments (diameters are '
                             'in metres: 30 mm is 0.03)' % (odd[0], lo, hi))
        # the platens of one grain close by maxStrain d at speed: at least 100 steps (a loading, not a blow), and the
        # largest grain at the step of the smallest at most 1e8
        self.checkDensityStep()
        dt = self.loadingTimeStep()
        steps = p['maxStrain'] * self.smallestDiameter() / p['speed'] / dt
        if steps < 100:
            bad('speed', 'closes the smallest grain by maxStrain in %.3g time steps of %.3g s, fewer than 100: not '
                         'a quasi-static test' % (steps, dt))
        largest = max(p['diameters']) if p['diameters'] else p['dMax']
        most = p['maxStrain'] * largest / p['speed'] / dt
        if most > 1e8:
            bad('speed', 'takes %.3g time steps of %.3g s (the smallest grain\'s step) to close the largest grain by '
                         'maxStrain, more than 1e8' % (most, dt))


def check(values, text=False):
    """All parameters checked, as :class:`SingleParticleParameters`."""
    return SingleParticleParameters.check(values, text)
