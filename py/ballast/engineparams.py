"""The engines' declarations: every parameter of BallastCrushEngine (:data:`CRUSH`), BallastAbrasionEngine
(:data:`ABRASION`) and of YADE's PeriodicEngine they both are (:data:`PERIODIC`), each a :class:`ballast.params.Param`
declared once. The ranges of the C++ core's parameters are the core's own (:func:`ballast.params.coreRange`).
Experiments take these declarations with their own defaults (``ballast.experiments.parameters``).

Needs no YADE: the study runner reads the declarations in plain ``/usr/bin/python3``.
"""
from . import _ballast
from .params import (INT32_MAX, INT64_MAX, NUMBER_NONNEGATIVE, Param, anyText, between, boolean, choice, coreRange, flag,
                     intBetween, nonNegative, oneOf, pattern, positiveInt, text, unitInterval)

# what both engines take
COMMON = {
    'rMin': Param(0.0, 'm', 'grains with a radius below rMin never degrade (fragments included)', *coreRange('rMin')),
    'mask': Param(0, '-', 'groupMask selecting the checked grains (dynamic spheres); 0 = all', intBetween(0, INT32_MAX),
                  'an integer in [0, 2^31 - 1] (a YADE groupMask)'),
    'adjustDt': Param(True, '-', 'after grains shrink, scale O.dt by the drop of utils.PWaveTimeStep() '
                      '(eq. 5: dt_cr ~ r sqrt(rho/E)); with a time stepper active, until its next update',
                      boolean, '0 or 1', flag),
    'scaledPWaveStep': Param(0.0, 's', 'density scaling: every grain the engine creates, shrinks or grows gets the '
                             "YADE State.densityScaling that makes its own P-wave step r sqrt(rho/E) this long (needs "
                             'NewtonIntegrator.densityScaling); O.dt is then not scaled (adjustDt has no effect); '
                             '0 = no density scaling', nonNegative, NUMBER_NONNEGATIVE),
}

# PyRunner's (YADE PeriodicEngine's) own settings, checked as the engines' parameters are: a negative or
# NaN period switches a PeriodicEngine off without a word
PERIODIC = {
    'iterPeriod': Param(0, 'steps', 'check every iterPeriod steps (0 = not by steps)', intBetween(0, INT64_MAX),
                        'an integer in [0, 2^63 - 1]'),
    'virtPeriod': Param(0.0, 's', 'check every virtPeriod of simulated time (the paper\'s T_c; 0 = not by time)',
                        nonNegative, NUMBER_NONNEGATIVE),
    'realPeriod': Param(0.0, 's', 'check every realPeriod of wall-clock time (0 = not by wall time)', nonNegative,
                        NUMBER_NONNEGATIVE),
    'nDo': Param(-1, '-', 'number of checks to run (-1 = no limit)', intBetween(-1, INT64_MAX),
                 'an integer in [-1, 2^63 - 1]'),
    'initRun': Param(False, '-', 'also check at the first step', boolean, '0 or 1', flag),
    'dead': Param(False, '-', 'switched off', boolean, '0 or 1', flag),
    'label': Param('', '-', 'name of the engine in the yade namespace', anyText, 'a name'),
    'firstIterRun': Param(0, 'steps', 'first step a check may run at', intBetween(0, INT64_MAX),
                          'an integer in [0, 2^63 - 1]'),
    'ompThreads': Param(-1, '-', 'OpenMP threads of the engine (-1 = YADE\'s)', intBetween(-1, 1024),
                        'an integer in [-1, 1024]'),
}

CRUSH = dict({
    'ft0': Param(None, 'Pa m^m', 'reference strength f_t0 of eq. 4, f_t = ft0 / r^m', *coreRange('ft0')),
    'm': Param(1.0, '-', 'size-effect exponent of eq. 4 (the paper: 1; 3 / m is the Weibull modulus of the size '
               'effect, 1 at m = 3)', *coreRange('m')),
    'pattern': Param(6, '-', 'fragment layout (Fig. 1): 4 (tetrahedral), 6 (octahedral), 14, or planar4 '
                     '(four in a plane, the paper\'s 70 % loss)', pattern, "4, 6, 14, 'tetra4', 'planar4', "
                     "'octa6' or 'fill14'"),
    'seed': Param(0, '-', 'seed of the random orientation of fragments (reproducible)', *coreRange('seed')),
    # beyond the paper (docs/strength.md): which stress crushes a grain, and scattered strengths
    'criterion': Param('vonMises', '-', "the stress compared with f_t: 'vonMises' (eq. 2, the paper), "
                       "'maxContactForce' (the largest normal contact force over d^2, de Bono & McDowell 2016) or "
                       "'majorPrincipal' (the largest principal compressive stress of eq. 3)",
                       choice(*_ballast.criterionNames()), oneOf(_ballast.criterionNames()), text),
    'weibullModulus': Param(0.0, '-', 'Weibull modulus k of the grains\' strengths: each grain\'s f_t is ft0 / r^m '
                            'times (-ln U)^(1/k), U uniform from (seed, body id), so eq. 4 is the characteristic '
                            'strength at every size; 0: every grain exactly ft0 / r^m (the paper)',
                            *coreRange('weibullModulus')),
    'keep': Param('none', '-', "what a replacement keeps besides the fragments' own volume: 'none' (the paper: "
                  "the mass of the lost volume is lost), 'mass' (the fragments' mass and inertia are scaled up "
                  "so that the parent's mass and momentum are kept), 'volume' (the fragments grow in place back "
                  "to the parent's volume over growTime)", choice('none', 'mass', 'volume'),
                  "'none', 'mass' or 'volume'", text),
    'growTime': Param(0.01, 's', "keep='volume': simulated time over which the fragments grow back to the parent's "
                      "volume, a step at every check (0: at the next check at once, which throws neighbours out)",
                      nonNegative, NUMBER_NONNEGATIVE),
    'maxPerCheck': Param(0, '-', 'crush at most this many grains per check, the most overloaded first (the '
                         'stress over the strength); the others wait for the next check if still over it. 0: every '
                         'grain over its strength at once (the paper)', intBetween(0, INT64_MAX),
                         'an integer in [0, 2^63 - 1]'),
    # fatigue, beyond the paper (docs/fatigue.md): Basquin-Miner damage D on the peaks of s = sigma_e / f_t
    'fatigue': Param(False, '-', 'fatigue: each peak s_p of a grain\'s stress ratio s = sigma_e / f_t takes '
                     '(1 - s_p) s_p^b off its strength (D) and it crushes when s > 1 - D, after s_p^-b equal peaks '
                     '(docs/fatigue.md); fragments start undamaged',
                     boolean, '0 or 1', flag),
    'fatigueExponent': Param(30.0, '-', 'Basquin exponent b: a constant peak s_p >= fatigueEndurance crushes a '
                             'grain after N_f = s_p^-b peaks', *coreRange('fatigueExponent')),
    'fatigueEndurance': Param(0.5, '-', 'endurance ratio: peaks of s below it do no damage',
                              *coreRange('fatigueEndurance')),
    'fatigueHysteresis': Param(0.05, '-', 'a peak of s ends when s falls this much below it, and the next rise '
                               'starts when s climbs this much above its minimum', *coreRange('fatigueHysteresis')),
}, **COMMON)

ABRASION = dict({
    'strength': Param(None, 'Pa', 'contact pressure that abrades a grain (eq. 6 compares the maximum Hertz '
                      'pressure p0 of eq. 7 with it; kept apart from ft0, which is in Pa m)', *coreRange('strength')),
    'gamma': Param(0.9, '-', 'radius reduction factor: r_new = gamma r_old (an abrasion removes a surface layer, '
                   'at most half the radius)', between(0.5, 1), 'a number in [0.5, 1)'),
    'prefilter': Param(True, '-', 'read only the contacts of grains whose bound on p0 exceeds the strength (same '
                       'decisions). Hertz-Mindlin contacts: a fabric-stress bound (ballast.abrasionBound) and one from '
                       'the largest overlap ratio; linear contacts (FrictPhys): eq. 7 is 3 kn / (2 pi R), a constant '
                       '(harvest.linearBound). It stays off for other contact laws, and once a full read finds a '
                       'bound broken', boolean, '0 or 1', flag),
    'verifyPeriod': Param(50, '-', 'with the prefilter, every verifyPeriod-th check reads all contacts anyway '
                          'and checks the bound against them', positiveInt, 'an integer >= 1'),
    'maxCandidates': Param(0.5, '-', 'with the prefilter, when more than this fraction of the grains are '
                           'candidates all contacts are read in one pass instead (reading grain by grain costs '
                           'about 1.6 times more per grain)', unitInterval, 'a number in [0, 1]'),
}, **COMMON)
