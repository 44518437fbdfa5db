"""Parameters of the oedometric test (sections 4-5), declared once: the library (``Oedometer(**kw)``),
the command line (``--name value``) and the yade-batch / study tables (a column per name) all use
these names, units, ranges and defaults. The engine parameters (ft0, m, pattern, rMin, strength,
gamma) are the engines' own declarations (:mod:`ballast.engineparams`) with the experiment's defaults, and
the grains, the steel, the contact law, the time step and the run are those every experiment shares
(:mod:`ballast.experiments.parameters`).

Needs no YADE: the study runner reads it in plain Python.
"""
import math

from ... import _ballast
from ...geometry import frictPhysStiffness
from ...params import NUMBER_NONNEGATIVE, NUMBER_POSITIVE, Param, anyText, between, boolean, choice, flag, intAtLeast, \
    nonNegative, positive, positiveInt, text
from ..parameters import (CONTACT, CYCLE_JUMP, ENGINES, GRAIN, GRAINS, INTEGRATION, PREPARATION, RESUME, RUN, SEED, STEEL,
                          CYCLE_OUTPUTS, MAX_OVERLAP_RATIO, QUASI_STATIC, ExperimentParameters, grainKey, storeName, take)
from .loadcurve import halfLoadTime, peakTime

OWNER = 'Oedometer'

PARAMS = {
    # realization and geometry (section 4, Fig. 3)
    'seed': SEED.withDefault(1, SEED.doc + " (YADE's makeCloud takes a C int)"),
    'diameter': Param(0.300, 'm', 'inner diameter of the steel cylinder', positive, NUMBER_POSITIVE),
    'height': Param(0.150, 'm', 'height of the cylinder; the grains fill it after deposition', positive, NUMBER_POSITIVE),
    **take(GRAINS, 'dMin', 'dMax'),
    'segments': Param(48, '-', 'facets around the cylinder (the flat inner faces are at diameter/2)', intAtLeast(12),
                      'an integer >= 12'),
    # materials (section 4)
    **take(GRAINS, 'young', 'poisson', 'friction', 'density'),
    **GRAIN,
    **STEEL,
    **CONTACT,
    # preparation: deposition and vibration
    **take(PREPARATION, 'prepYoung', 'prepDamping'),
    'fill': Param(0.562, '-', 'solid volume of the grains over the volume of the cylinder (pi diameter^2 height / 4): '
                  'the dense sample fills the cylinder to about its height at 0.562', between(0.1, 0.74),
                  'a number in [0.1, 0.74)'),
    **take(PREPARATION, 'depFriction'),
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
    **INTEGRATION,
    # crushing (section 2) and abrasion (section 3): the engines' declarations; what the grading counts
    **ENGINES,
    # outputs
    **take(RUN, 'results', 'runId'),
    'samples': Param(5000, '-', 'rows of fd.csv per loading cycle', intAtLeast(10), 'an integer >= 10'),
    **take(RUN, 'progress'),
    'timing': Param(False, '-', 'time every engine while loading (O.timingEnabled) and write timing.txt', boolean,
                    '0 or 1', flag),
    'resume': RESUME,
    **CYCLE_JUMP,
    **CYCLE_OUTPUTS,
    **QUASI_STATIC,
}

# What decides a packing: these parameters and the version of the preparation. Bump the version
# whenever the preparation changes: stored packings of older versions are then not reused.
PACKING_KEYS = ('seed', 'diameter', 'height', 'dMin', 'dMax', 'segments', 'young', 'poisson', 'friction', 'density',
                'steelYoungRatio', 'steelPoisson', 'steelFriction', 'steelDensity', 'prepYoung', 'prepDamping', 'fill',
                'depFriction', 'depTime', 'pressForce', 'seatForce', 'plateThickness', 'vibAcc', 'vibFreq', 'vibTime',
                'law')
PACKING_VERSION = 4
ROLLING_KEYS = ('rollingFriction', 'rollingStiffness')


# A run must stay in the range where rigid-sphere DEM holds: checked before any work (the bounds of every cyclic
# experiment are ExperimentParameters.checkCycles').


class OedometerParameters(ExperimentParameters):
    """The oedometer's checked parameters (frozen) and what follows from them."""

    OWNER, PARAMS = OWNER, PARAMS
    POLYHEDRA = True   # grain 'polyhedron' too (polyhedronsample, the wall plate; docs/grains.md, "Polyhedra")

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
        self.checkSizes()
        self.checkGrain()
        self.checkBed()
        self.checkDensityStep()
        self.checkCycleJump()
        self.checkResume()
        # f is named for a run too long as well: raise f or lower cycles
        self.checkCycles(self.T, 'f', 'f')
        u = self.singleContactOverlap(p['Fmax'])
        if u > MAX_OVERLAP_RATIO * p['dMin'] / 2:
            bad('Fmax', 'through one steel contact of the smallest grain it would overlap it by %.3g m, %.3g of its '
                        'radius (%s law), more than %g: outside rigid-sphere DEM' % (u, u / (p['dMin'] / 2), p['law'],
                                                                                     MAX_OVERLAP_RATIO))
        if p['dMax'] >= p['diameter'] / 2:
            bad('dMax', 'must be smaller than diameter/2 = %g' % (p['diameter'] / 2))
        if p['dMax'] >= p['height']:
            bad('dMax', 'must be smaller than height = %g' % p['height'])
        if p['Fmin'] >= p['Fmax']:
            bad('Fmin', 'must be smaller than Fmax = %g' % p['Fmax'])
        if p['grain'] == 'polyhedron':
            if p['loadMode'] == 'servo':   # its gain reads the plate contacts' kn in N/m; the volumetric law's is N/m^3
                bad('loadMode', "with grain = 'polyhedron' only 'plate' or 'displacement': the servo's gain reads the "
                                "contacts' stiffness in N/m, the volumetric law's is in N/m^3")


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
    d.update(grainKey(p))   # nothing for spheres: their stored packings keep their names
    return d, storeName('packing', p['seed'], d)
