"""Parameters of the oedometric test (sections 4-5), declared once: the library (``Oedometer(**kw)``),
the command line (``--name value``) and the yade-batch / study tables (a column per name) all use
these names, units, ranges and defaults. The engine parameters (ft0, m, pattern, rMin, strength,
gamma) are the engines' own declarations (:mod:`ballast.params`) with the experiment's defaults.

Needs no YADE: the study runner reads it in plain Python.
"""
import hashlib
import json
import math
import re

from ... import _ballast
from ...geometry import frictPhysStiffness
from ...params import (ABRASION, CRUSH, CYCLE_JUMP, DENSITY_STEP, INT32_MAX, NUMBER_NONNEGATIVE, NUMBER_POSITIVE, Param, ParamError,
                       Parameters, TIME_STEP, anyText, between, boolean, checkDensityStep, choice, flag, intAtLeast, intBetween,
                       literal, nonNegative, positive, positiveInt, text, checkCycleJump)
from ..cycleparams import PARAMS as CYCLE_OUTPUTS
from .loadcurve import halfLoadTime, peakTime

OWNER = 'Oedometer'
_PHI = 'a number in [0, pi/2)'

PARAMS = {
    # realization and geometry (section 4, Fig. 3)
    'seed': Param(1, '-', 'realization: grain sizes and positions, fragment orientations (YADE\'s makeCloud takes '
                  'a C int)', intBetween(0, INT32_MAX), 'an integer in [0, 2^31 - 1]'),
    'diameter': Param(0.300, 'm', 'inner diameter of the steel cylinder', positive, NUMBER_POSITIVE),
    'height': Param(0.150, 'm', 'height of the cylinder; the grains fill it after deposition', positive, NUMBER_POSITIVE),
    'dMin': Param(0.0205, 'm', 'smallest grain diameter (diameters uniform in [dMin, dMax])', positive, NUMBER_POSITIVE),
    'dMax': Param(0.0445, 'm', 'largest grain diameter', positive, NUMBER_POSITIVE),
    'segments': Param(48, '-', 'facets around the cylinder (the flat inner faces are at diameter/2)', intAtLeast(12),
                      'an integer >= 12'),
    # materials (section 4)
    'young': Param(3e11, 'Pa', "ballast Young's modulus", positive, NUMBER_POSITIVE),
    'poisson': Param(0.3, '-', 'ballast Poisson ratio', between(0, 0.5), 'a number in [0, 0.5)'),
    'friction': Param(0.8, 'rad', 'ballast friction angle', between(0, math.pi / 2), _PHI),
    'density': Param(2600., 'kg/m^3', 'ballast density', positive, NUMBER_POSITIVE),
    'steelYoungRatio': Param(10., '-', "steel Young's modulus over the ballast's", positive, NUMBER_POSITIVE),
    'steelPoisson': Param(0.25, '-', 'steel Poisson ratio', between(0, 0.5), 'a number in [0, 0.5)'),
    'steelFriction': Param(0.0, 'rad', 'steel friction angle (cylinder and plate)', between(0, math.pi / 2), _PHI),
    'steelDensity': Param(7850., 'kg/m^3', 'steel density', positive, NUMBER_POSITIVE),
    'law': Param('linear', '-', "contact law: 'linear' (YADE's default FrictPhys + CundallStrack, as the paper's "
                 "FrictMat inputs and eq. 5 suggest) or 'hertz' (Hertz-Mindlin)", choice('linear', 'hertz'),
                 "'linear' or 'hertz'", text),
    'rollingFriction': Param(0.0, '-', 'rolling resistance of the grains: the rolling moment between two grains is '
                             'limited to rollingFriction min(R1, R2) Fn (YADE\'s CohFrictMat etaRoll; a stand-in for the '
                             'interlocking of angular grains); 0: none, the paper\'s spheres; linear law only',
                             between(0, 1, closedHi=True), 'a number in [0, 1]'),
    'rollingStiffness': Param(2.0, '-', 'with rollingFriction: the rolling stiffness kr = rollingStiffness ks R1 R2 '
                              '(YADE\'s alphaKr, its default)', positive, NUMBER_POSITIVE),
    # preparation: deposition and vibration
    'prepYoung': Param(3e8, 'Pa', "ballast Young's modulus while depositing and vibrating (time scaling; steel keeps "
                       "steelYoungRatio); restored to young before loading", positive, NUMBER_POSITIVE),
    'prepDamping': Param(0.4, '-', 'local damping while preparing', between(0, 1), 'a number in [0, 1)'),
    'fill': Param(0.562, '-', 'solid volume of the grains over the volume of the cylinder (pi diameter^2 height / 4): '
                  'the dense sample fills the cylinder to about its height at 0.562', between(0.1, 0.74),
                  'a number in [0.1, 0.74)'),
    'depFriction': Param(0.0, 'rad', 'grain friction angle while depositing and pressing (frictionless grains pack '
                         'densely); friction is restored to `friction` before the plate is lifted', between(0, math.pi / 2),
                         _PHI),
    'depTime': Param(0.0, 's', 'deposition time before the press (0: the free-fall time of the cloud\'s top)',
                     nonNegative, NUMBER_NONNEGATIVE),
    'pressForce': Param(8000.0, 'N', 'force pressing the frictionless grains through a plate (besides its weight) until '
                        'they rest (0: no press)', nonNegative, NUMBER_NONNEGATIVE),
    'seatForce': Param(100.0, 'N', 'force on the press plate (besides its weight) once friction is restored, before it '
                       'is lifted', nonNegative, NUMBER_NONNEGATIVE),
    'vibAcc': Param(50., 'm/s^2', 'amplitude of the horizontal acceleration of the cylinder after the deposition',
                    nonNegative, NUMBER_NONNEGATIVE),
    'vibFreq': Param(20., 'Hz', 'frequency of the vibration', positive, NUMBER_POSITIVE),
    'vibTime': Param(0.0, 's', 'duration of the vibration (rounded up to whole periods; 0 = none: the press packs '
                     'densely enough)', nonNegative, NUMBER_NONNEGATIVE),
    'reusePacking': Param(True, '-', 'load the stored packing of this seed and packing parameters if there is one',
                          boolean, '0 or 1', flag),
    'packingDir': Param('', 'path', 'where packings are stored (default <results>/packings)', anyText, 'a path', text),
    # loading (eq. 8)
    'f': Param(8.0, 'Hz', 'loading frequency of eq. 8 (the paper: 0.25 to 8 Hz, almost no effect)', positive,
               NUMBER_POSITIVE),
    'Fmax': Param(1.5e6, 'N', 'peak force of eq. 8', positive, NUMBER_POSITIVE),
    'cycles': Param(1, '-', 'load cycles of one load() (each of period 1/f)', positiveInt, 'an integer >= 1'),
    'stopAt': Param(0.0, '-', 'stop the first load() early, at stopAt load periods and 1.5 crushing periods (or time '
                    'steps, Tc = 0) more, so that the crushing check after it has run (0.25: eq. 8 at Fmax/2, the '
                    'half-load sweep; 0.5: the applied peak, what Fig. 5 reads; 0: run the cycles)', between(0, 1),
                    'a number in [0, 1)'),
    'stopQuiet': Param(0.0, '-', 'also stop load() once, after the peak of eq. 8, the applied load has fallen below '
                       'stopQuiet Fmax and no grain has crushed for quietTime (0: never)', between(0, 1),
                       'a number in [0, 1)'),
    'quietTime': Param(0.005, 's', 'stopQuiet: how long no grain may have crushed [s of loading time]', nonNegative,
                       NUMBER_NONNEGATIVE),
    'Fmin': Param(0.0, 'N', 'lower force of the cycles after the first half-cycle (eq. 8 rises from 0 to Fmax; the '
                  'force then cycles between Fmax and Fmin, as a track between its seating load and a peak)',
                  nonNegative, NUMBER_NONNEGATIVE),
    'loadMode': Param('plate', '-', "'plate': eq. 8 applied to a steel plate free along the axis; 'servo': a kinematic "
                      "plate whose speed follows the force error (at most vMax); 'displacement': the plate moves at "
                      "plateSpeed until the grains carry Fmax", choice('plate', 'servo', 'displacement'),
                      "'plate', 'servo' or 'displacement'", text),
    'plateThickness': Param(0.02, 'm', 'thickness of the steel plate; its mass is steelDensity pi (diameter/2)^2 '
                            'plateThickness', positive, NUMBER_POSITIVE),
    'vMax': Param(5.0, 'm/s', "servo mode: fastest plate speed of the force control (the press's limit)", positive,
                  NUMBER_POSITIVE),
    'plateSpeed': Param(0.05, 'm/s', 'displacement mode: the plate speed', positive, NUMBER_POSITIVE),
    'damping': Param(0.2, '-', 'local (Cundall) damping while loading', between(0, 1), 'a number in [0, 1)'),
    'dtSafety': Param(0.8, '-', 'time step = dtSafety * PWaveTimeStep() (eq. 5; conservative for Hertz contacts); '
                      'with timeStep stiffness the stepper\'s safety factor', between(1e-9, 1, closedHi=True),
                      'a number in (0, 1]'),
    'timeStep': TIME_STEP,
    'densityStep': DENSITY_STEP.withDefault(0.0, DENSITY_STEP.doc + '; the plate from the stiffness of its contacts; '
                                            'with timeStep pwave'),
    # crushing (section 2) and abrasion (section 3): the engines' declarations
    'crush': Param(True, '-', 'BallastCrushEngine on', boolean, '0 or 1', flag),
    'ft0': CRUSH['ft0'].withDefault(3.1e6),  # calibrated: docs/oedometer.md, "Choice of the defaults"
    'm': CRUSH['m'],
    'pattern': CRUSH['pattern'],
    'rMin': CRUSH['rMin'].withDefault(0.010),
    'criterion': CRUSH['criterion'],
    'weibullModulus': CRUSH['weibullModulus'],
    'keep': CRUSH['keep'],
    'growTime': CRUSH['growTime'],
    'maxPerCheck': CRUSH['maxPerCheck'],
    'fatigue': CRUSH['fatigue'],
    'fatigueExponent': CRUSH['fatigueExponent'],
    'fatigueEndurance': CRUSH['fatigueEndurance'],
    'fatigueHysteresis': CRUSH['fatigueHysteresis'],
    'Tc': Param(1e-4, 's', 'crushing period T_c: the crushing condition is checked every Tc (0 = every step)',
                nonNegative, NUMBER_NONNEGATIVE),
    'abrasion': Param(True, '-', 'BallastAbrasionEngine on', boolean, '0 or 1', flag),
    # under the linear law eq. 7 is 3 kn / (2 pi R) = 3 E / pi = 2.86e11 Pa at every grain contact whatever the
    # load (harvest.linearBound): a strength below it abrades every grain in contact at every check
    'strength': ABRASION['strength'].withDefault(3e11),
    'gamma': ABRASION['gamma'],
    'abrasionPeriod': Param(100, 'steps', 'the abrasion condition is checked every abrasionPeriod steps', positiveInt,
                            'an integer >= 1'),
    # outputs
    'lostAsFines': Param(True, '-', 'count the mass a replacement or an abrasion loses as fines passing every sieve in '
                         'psd.csv and the breakage indices (as a sieve analysis sees the dust); 0: only the spheres',
                         boolean, '0 or 1', flag),
    'results': Param('results', 'path', 'results root; this run writes <results>/<run id>/', anyText, 'a path', text),
    'runId': Param('', '-', "run id (default O.tags['d.id']); an existing directory gets a suffix, never overwritten",
                   anyText, 'a name', text),
    'samples': Param(5000, '-', 'rows of fd.csv per loading cycle', intAtLeast(10), 'an integer >= 10'),
    'progress': Param(10.0, 's', 'wall-clock seconds between progress lines', positive, NUMBER_POSITIVE),
    'timing': Param(False, '-', 'time every engine while loading (O.timingEnabled) and write timing.txt', boolean,
                    '0 or 1', flag),
    **CYCLE_JUMP,
    **CYCLE_OUTPUTS,
}

# What decides a packing: these parameters and the version of the preparation. Bump the version
# whenever the preparation changes: stored packings of older versions are then not reused.
PACKING_KEYS = ('seed', 'diameter', 'height', 'dMin', 'dMax', 'segments', 'young', 'poisson', 'friction', 'density',
                'steelYoungRatio', 'steelPoisson', 'steelFriction', 'steelDensity', 'prepYoung', 'prepDamping', 'fill',
                'depFriction', 'depTime', 'pressForce', 'seatForce', 'plateThickness', 'vibAcc', 'vibFreq', 'vibTime',
                'law')
PACKING_VERSION = 4
ROLLING_KEYS = ('rollingFriction', 'rollingStiffness')


# A run must end and stay in the range where rigid-sphere DEM holds: these bounds are checked before any work.
MAX_LOADING_STEPS = 1e9     # [steps] cycles / f / dt at the start; 1e9 steps are days of CPU (3e5 at 8 Hz, 1 cycle)
MIN_STEPS_PER_CYCLE = 100   # [steps] a cycle resolved by fewer time steps is not a load cycle
MAX_OVERLAP_RATIO = 0.25    # [-] overlap / radius of the smallest grain if Fmax went through one of its steel contacts


# Text (a command line, a table cell) is read in the spellings --help gives: a flag is 0 or 1; a number is
# decimal (1e6, 0.5, 16); Python's other literal forms (0x10, 0o7, 0b1, 1_000, 1j) are refused.
_PYTHON_ONLY_NUMBER = re.compile(r'^[-+]?(0[xXoObB]|\d[\d.]*_|.*\d[jJ]$)')


def readText(name, value):
    """A text value as the declaration of `name` reads it, in the documented spellings only (ParamError)."""
    if not isinstance(value, str) or name not in PARAMS:
        return value
    p, t = PARAMS[name], value.strip().strip('\'"')
    if p.parse is flag and t not in ('0', '1'):
        raise ParamError(name, '%s: %s = %r is not allowed: expected 0 or 1' % (OWNER, name, value))
    if p.parse is literal and _PYTHON_ONLY_NUMBER.match(value.strip()):
        raise ParamError(name, '%s: %s = %r is not allowed: expected %s [%s], written in decimal (hexadecimal, octal, '
                         'binary, complex and 1_000 forms are refused)' % (OWNER, name, value, p.allowed, p.unit))
    return value


def checkRolling(bad, p):
    """Rolling resistance is YADE's moment law on the linear contact: with law 'linear' only."""
    if p['rollingFriction'] > 0 and p['law'] != 'linear':
        bad('rollingFriction', "needs law = 'linear' (YADE's moment law on the linear contact), got law = %r" % p['law'])


class OedometerParameters(Parameters):
    """The oedometer's checked parameters (frozen) and what follows from them."""

    OWNER, PARAMS = OWNER, PARAMS

    @classmethod
    def check(cls, values, text=False):
        if text and not isinstance(values, cls):
            values = {k: readText(k, v) for k, v in dict(values).items()}
        return super().check(values, text)

    @property
    def T(self):
        """The load period 1/f [s]."""
        return 1.0 / self['f']

    def peakTime(self):
        """Loading time [s] of eq. 8's peak, T/2."""
        return peakTime(self['f'])

    def halfLoadTime(self):
        """Loading time [s] at which eq. 8 first passes Fmax/2, T/4."""
        return halfLoadTime(self['f'])

    def crushPeriod(self):
        """The crushing engine's YADE period: {'virtPeriod': Tc}, or {'iterPeriod': 1} for Tc = 0 (every step)."""
        return {'virtPeriod': self['Tc']} if self['Tc'] > 0 else {'iterPeriod': 1}

    def startTimeStep(self):
        """The loading time step [s] at the start: dtSafety times YADE's PWaveTimeStep (eq. 5) of the
        smallest grain, r sqrt(rho / E)."""
        return self['dtSafety'] * self['dMin'] / 2 * math.sqrt(self['density'] / self['young'])

    def loadingTimeStep(self):
        """The loading time step [s] at the start: densityStep with density scaling, else startTimeStep()."""
        return self['densityStep'] or self.startTimeStep()

    def scaledPWaveStep(self):
        """The own P-wave step [s] density scaling gives every grain, densityStep / dtSafety (0: off)."""
        return self['densityStep'] / self['dtSafety']

    def singleContactOverlap(self, force):
        """Overlap [m] of the smallest grain (r = dMin/2) carrying `force` [N] through one contact with steel,
        with YADE's stiffness of that contact: linear kn = 2 E r Es r / (E r + Es r), Hertz F = kno u^1.5 with
        kno = 4/3 E* sqrt(r / 2) (YADE takes R = r/2 against a wall)."""
        r, E, Es = self['dMin'] / 2, self['young'], self['young'] * self['steelYoungRatio']
        if self['law'] == 'linear':
            return force / frictPhysStiffness(E, self['poisson'], r, Es, self['steelPoisson'], r)[0]
        Estar = _ballast.contactModulus(E, self['poisson'], Es, self['steelPoisson'])
        return (force / (4.0 / 3.0 * Estar * math.sqrt(r / 2))) ** (2.0 / 3.0)

    def crossCheck(self):
        """Checks between parameters; each error names the parameter at fault."""
        p, bad = self, self.bad
        dt = self.loadingTimeStep()
        checkDensityStep(bad, p['densityStep'], self.startTimeStep(), p['timeStep'])
        checkCycleJump(bad, p)
        steps = p['cycles'] / p['f'] / dt
        if steps > MAX_LOADING_STEPS and not p['jump']:   # jumping: the cycles simulated are not known
            bad('f', '%d cycles at %g Hz take %.3g time steps of %.3g s (the loading time step), '
                     'more than the %.0e a run may take: raise f or lower cycles' % (p['cycles'], p['f'], steps, dt,
                                                                                      MAX_LOADING_STEPS))
        if 1 / p['f'] / dt < MIN_STEPS_PER_CYCLE:
            bad('f', 'a cycle of %.3g s spans %.3g time steps of %.3g s, fewer than %d' % (
                1 / p['f'], 1 / p['f'] / dt, dt, MIN_STEPS_PER_CYCLE))
        u = self.singleContactOverlap(p['Fmax'])
        if u > MAX_OVERLAP_RATIO * p['dMin'] / 2:
            bad('Fmax', 'through one steel contact of the smallest grain it would overlap it by %.3g m, %.3g of its '
                        'radius (%s law), more than %g: outside rigid-sphere DEM' % (u, u / (p['dMin'] / 2), p['law'],
                                                                                     MAX_OVERLAP_RATIO))
        if p['dMin'] >= p['dMax']:
            bad('dMin', 'must be smaller than dMax = %g' % p['dMax'])
        checkRolling(bad, p)
        if p['dMax'] >= p['diameter'] / 2:
            bad('dMax', 'must be smaller than diameter/2 = %g' % (p['diameter'] / 2))
        if p['dMax'] >= p['height']:
            bad('dMax', 'must be smaller than height = %g' % p['height'])
        if p['rMin'] > p['dMax'] / 2:
            bad('rMin', 'larger than the largest grain radius dMax/2 = %g' % (p['dMax'] / 2))
        if p['Fmin'] >= p['Fmax']:
            bad('Fmin', 'must be smaller than Fmax = %g' % p['Fmax'])
        if p['prepYoung'] > p['young']:
            bad('prepYoung', 'must not exceed young = %g' % p['young'])
        # periods: a crushing check in every load cycle
        T = 1 / p['f']
        if p['Tc'] > T:
            bad('Tc', 'longer than the load cycle 1/f = %g s: a cycle could pass without a crushing check (Tc <= 1/f; '
                      '0 = every step)' % T)
        if p['abrasionPeriod'] * dt > T:
            bad('abrasionPeriod', '%d steps of %.3g s are longer than the load cycle 1/f = %g s (at most %d steps)' % (
                p['abrasionPeriod'], dt, T, int(T / dt)))


def check(values, text=False):
    """All parameters checked, as :class:`OedometerParameters` (see Parameters.check)."""
    return OedometerParameters.check(values, text)


def packingKey(p):
    """(the values that decide the packing, the file name it is stored under)."""
    d = {k: p[k] for k in PACKING_KEYS}
    for k in ROLLING_KEYS:   # in the key only when on: the stored packings of the paper's spheres keep their names
        if p['rollingFriction'] > 0:
            d[k] = p[k]
    d['version'] = PACKING_VERSION
    h = hashlib.sha1(json.dumps(d, sort_keys=True).encode()).hexdigest()[:10]
    return d, 'packing-seed%d-%s.json' % (p['seed'], h)
