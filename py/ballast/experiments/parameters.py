"""What every experiment declares alike, declared once: the grains, the steel, the contact law, the
preparation, the integration (damping, time step), the engines' options, the run, cycle jumping; and
:class:`ExperimentParameters`, the base of each experiment's checked parameters, with the values derived
from them (time steps, the crushing period) and the checks between them that every experiment makes.

An experiment builds its table from these groups (``**GRAINS``, ``**take(STEEL, ...)``), in the order
its --help and docs/parameters.md list them, and may give a declaration another default or doc with
``.withDefault(...)``; its own parameters it declares in its folder. Needs no YADE: the study runner
reads it in plain Python.
"""
import json
import math
import os

from ..engineparams import ABRASION, CRUSH
from ..grainparams import CLUMP_SHAPE
from ..runfiles import sha1
from ..params import (INT32_MAX, NUMBER_NONNEGATIVE, NUMBER_POSITIVE, Param, Parameters, anyText, between, boolean, choice,
                      coreRange, flag, intBetween, nonNegative, positive, positiveInt, text)

PHI = 'a number in [0, pi/2)'   # the allowed range of a friction angle, in words

# A run must end and resolve its cycles: bounds every cyclic experiment checks before any work.
MAX_LOADING_STEPS = 1e9     # [steps] cycles / f / dt at the start; 1e9 steps are days of CPU (3e5 at 8 Hz, 1 cycle)
MIN_STEPS_PER_CYCLE = 100   # [steps] a cycle resolved by fewer time steps is not a load cycle
MAX_GRAINS = 1e6            # [grains] a sample YADE can step on one core (1 s of CPU a step at 1 us a grain-step)
MAX_OVERLAP_RATIO = 0.25   # [-] the largest overlap / radius a loading may give the smallest grain (checkStress)


def take(group, *names):
    """The declarations `names` of a group, in that order (an experiment keeps the order of its table)."""
    return {n: group[n] for n in names}


SEED = Param(1, '-', 'realization: grain sizes and positions, fragment orientations', intBetween(0, INT32_MAX),
             'an integer in [0, 2^31 - 1]')

# the grains (section 4)
GRAINS = {
    'dMin': Param(0.0205, 'm', 'smallest grain diameter (diameters uniform in [dMin, dMax])', positive, NUMBER_POSITIVE),
    'dMax': Param(0.0445, 'm', 'largest grain diameter', positive, NUMBER_POSITIVE),
    'young': Param(3e11, 'Pa', "ballast Young's modulus", positive, NUMBER_POSITIVE),
    'poisson': Param(0.3, '-', 'ballast Poisson ratio', between(0, 0.5), 'a number in [0, 0.5)'),
    'friction': Param(0.8, 'rad', 'ballast friction angle', between(0, math.pi / 2), PHI),
    'density': Param(2600., 'kg/m^3', 'ballast density', positive, NUMBER_POSITIVE),
}

# what a grain is (issue 47, docs/grains.md "Clumps in the experiments"): the paper's sphere or a clump of spheres
GRAIN_KIND = 'sphere'   # the default, the paper's: its samples' store keys hold no entry of GRAIN
GRAIN = {
    'grain': Param(GRAIN_KIND, '-', "what a grain is: 'sphere' (one YADE sphere, the paper's), 'clump' (a YADE clump "
                   'of overlapping spheres shaped by the clump parameters, its volume-equivalent radius the cloud\'s '
                   'radius; crushed, it splits) or \'polyhedron\' (one of YADE\'s convex polyhedra, its volumetric '
                   'contact law, crushed by YADE\'s PolyhedraSplitter: the single-particle test and the oedometer, for '
                   'comparison; docs/grains.md); the same preparation and outputs',
                   choice('sphere', 'clump', 'polyhedron'), "'sphere', 'clump' or 'polyhedron'", text),
    **CLUMP_SHAPE,
    'clumpTemplates': Param(20, '-', "with grain 'clump': clump shapes built from the seed for a sample, each grain one "
                            'of them scaled to its radius and turned at random (a shape costs about 1 s to build: its '
                            'union volume by Monte Carlo)', intBetween(1, 1000), 'an integer in [1, 1000]'),
    'clumpFile': Param('', 'path', "with grain 'clump': clump templates from a CSV file instead of the shape "
                       'parameters (columns template, x, y, z, r: a row a member sphere, any one length unit), each '
                       'turned to its principal axes and scaled to r_eq = 1, every grain one of them (docs/grains.md, '
                       '"Templates from a file")', anyText, 'a path to a CSV file, or empty', text),
}
GRAIN_SHAPE_KEYS = tuple(k for k in GRAIN if k != 'grain')
CLUMP_BUILDER_KEYS = ('clumpElongation', 'clumpFlatness', 'clumpRoundness', 'clumpSpheres', 'clumpTemplates')   # clumpFile replaces them
NEWER_KEYS = ('clumpFile', 'clumpRoundness')   # in a sample's store key only when set (grainKey)
# the measured cost of polyhedra that makes a box or a triaxial sample of them too slow (bench/bench_grains.py)
POLYHEDRON_COST = '140 us a grain-step, 363 times the spheres (bench/grains.json), about 30 h of CPU a 300-grain oedometer'



def grainKey(p):
    """What of GRAIN decides a stored sample, for its store key: nothing for the paper's spheres (their stored
    samples keep their names), else the kind and its shape parameters; a clumpFile by its content (its SHA-1) and
    clumpRoundness only when not the default (the samples stored before them keep their names)."""
    if p['grain'] == GRAIN_KIND:
        return {}
    d = {k: p[k] for k in GRAIN if k not in NEWER_KEYS}
    if p['clumpRoundness'] != GRAIN['clumpRoundness'].default:
        d['clumpRoundness'] = p['clumpRoundness']
    if p['clumpFile']:
        with open(p['clumpFile'], 'rb') as fh:
            d['clumpFile'] = sha1(fh.read())
    return d


def storeName(prefix, seed, keys):
    """The file name a prepared sample decided by `keys` (a dict of JSON values) is stored under: the same keys give
    the same name, any other keys (almost surely) another."""
    return '%s-seed%d-%s.json' % (prefix, seed, sha1(json.dumps(keys, sort_keys=True))[:10])


# the steel of the walls, plates and platens (section 4)
STEEL = {
    'steelYoungRatio': Param(10., '-', "steel Young's modulus over the ballast's", positive, NUMBER_POSITIVE),
    'steelPoisson': Param(0.25, '-', 'steel Poisson ratio', between(0, 0.5), 'a number in [0, 0.5)'),
    'steelFriction': Param(0.0, 'rad', 'steel friction angle (cylinder and plate)', between(0, math.pi / 2), PHI),
    'steelDensity': Param(7850., 'kg/m^3', 'steel density', positive, NUMBER_POSITIVE),
}

CONTACT = {
    'law': Param('linear', '-', "contact law: 'linear' (YADE's default FrictPhys + CundallStrack, as the paper's "
                 "FrictMat inputs and eq. 5 suggest) or 'hertz' (Hertz-Mindlin)", choice('linear', 'hertz'),
                 "'linear' or 'hertz'", text),
    'rollingFriction': Param(0.0, '-', 'rolling resistance of the grains: the rolling moment between two grains is '
                             'limited to rollingFriction min(R1, R2) Fn (YADE\'s CohFrictMat etaRoll; a stand-in for the '
                             'interlocking of angular grains); 0: none, the paper\'s spheres; linear law only',
                             between(0, 1, closedHi=True), 'a number in [0, 1]'),
    'rollingStiffness': Param(2.0, '-', 'with rollingFriction: the rolling stiffness kr = rollingStiffness ks R1 R2 '
                              '(YADE\'s alphaKr, its default)', positive, NUMBER_POSITIVE),
}

# a packed bed's preparation (experiments.preparation)
PREPARATION = {
    'prepYoung': Param(3e8, 'Pa', "ballast Young's modulus while depositing and vibrating (time scaling; steel keeps "
                       "steelYoungRatio); restored to young before loading", positive, NUMBER_POSITIVE),
    'prepDamping': Param(0.4, '-', 'local damping while preparing', between(0, 1), 'a number in [0, 1)'),
    'depFriction': Param(0.0, 'rad', 'grain friction angle while depositing and pressing (frictionless grains pack '
                         'densely); friction is restored to `friction` before the plate is lifted', between(0, math.pi / 2),
                         PHI),
}

# the time step options (experiments.timestep)
TIME_STEP = Param('pwave', '-', "the time step: 'pwave' (dtSafety x YADE's PWaveTimeStep of the smallest grain, eq. 5, "
                  "scaled down after each replacement: the paper's) or 'stiffness' (YADE's GlobalStiffnessTimeStepper, "
                  "safety dtSafety, from the contacts' stiffness every 10 steps; after a replacement scaled as for "
                  "pwave until its next update)", choice('pwave', 'stiffness'), "'pwave' or 'stiffness'", text)
DENSITY_STEP = Param(0.0, 's', "density scaling: the loading's time step; every grain, fragments included, gets "
                     "YADE's State.densityScaling so that its own P-wave step r sqrt(rho/E) (r: a sphere's radius, a "
                     "clump's smallest member) reaches densityStep / "
                     "dtSafety (never made lighter); other moving bodies as the experiment says; 0 = off (the "
                     "paper's). At least the paper's step", nonNegative, NUMBER_NONNEGATIVE)

# while loading: the integrator's damping and time step
INTEGRATION = {
    'damping': Param(0.2, '-', 'local (Cundall) damping while loading', between(0, 1), 'a number in [0, 1)'),
    'dtSafety': Param(0.8, '-', 'time step = dtSafety * PWaveTimeStep() (eq. 5; conservative for Hertz contacts); '
                      'with timeStep stiffness the stepper\'s safety factor', between(1e-9, 1, closedHi=True),
                      'a number in (0, 1]'),
    'timeStep': TIME_STEP,
    'densityStep': DENSITY_STEP.withDefault(0.0, DENSITY_STEP.doc + '; the plate from the stiffness of its contacts; '
                                            'with timeStep pwave'),
}

# the quasi-static option of the cyclic experiments (experiments.quasistatic, docs/performance.md)
QS_START_FACTOR = 4.0   # [-] its first cycle's step over the paper's, by default
QUASI_STATIC = {
    'quasiStatic': Param(0.0, '-', 'the quasi-static option: density scaling whose step is chosen cycle by cycle so '
                         'that the bed\'s largest inertial number in a cycle stays below this bound and the load\'s '
                         'period over the bed\'s response time above quasiStaticRatio (the first cycle at '
                         'quasiStaticStart times the paper\'s step; a cycle that breaks a bound is marked in cycles.csv '
                         'and the next runs at the paper\'s step; docs/performance.md); 1e-3 is the quasi-static regime '
                         '(GDR MiDi 2004); 0 = off', between(0, 0.1, closedHi=True), 'a number in [0, 0.1]'),
    'quasiStaticStart': Param(QS_START_FACTOR, '-', 'with quasiStatic: the first cycle\'s step over the paper\'s; 1 runs '
                              'the first loading, where the bed rearranges most, at the paper\'s step, and the option '
                              'grows the step from the second cycle on', between(1, 16, closedHi=True),
                              'a number in [1, 16]'),
    'quasiStaticRatio': Param(10.0, '-', 'with quasiStatic: the smallest ratio of the load\'s period to the bed\'s '
                              'slowest response time a cycle may have', between(1, 1e6, closedHi=True),
                              'a number in [1, 1e6]'),
}

# crushing (section 2) and abrasion (section 3): the engines' declarations with the experiments' defaults
ENGINES = {
    'crush': Param(True, '-', 'BallastCrushEngine on', boolean, '0 or 1', flag),
    'ft0': CRUSH['ft0'].withDefault(3.1e6),  # calibrated: docs/oedometer.md, "Choice of the defaults"
    **take(CRUSH, 'm', 'pattern'),
    'rMin': CRUSH['rMin'].withDefault(0.010),
    **take(CRUSH, 'criterion', 'weibullModulus', 'keep', 'growTime', 'maxPerCheck', 'fatigue', 'fatigueExponent',
           'fatigueEndurance', 'fatigueHysteresis'),
    'Tc': Param(1e-4, 's', 'crushing period T_c: the crushing condition is checked every Tc (0 = every step)',
                nonNegative, NUMBER_NONNEGATIVE),
    'abrasion': Param(True, '-', 'BallastAbrasionEngine on', boolean, '0 or 1', flag),
    # under the linear law eq. 7 is 3 kn / (2 pi R) = 3 E / pi = 2.86e11 Pa at every grain contact whatever the
    # load (harvest.linearBound): a strength below it abrades every grain in contact at every check
    'strength': ABRASION['strength'].withDefault(3e11),
    'gamma': ABRASION['gamma'],
    'abrasionPeriod': Param(100, 'steps', 'the abrasion condition is checked every abrasionPeriod steps', positiveInt,
                            'an integer >= 1'),
    # what the grading counts of the mass the engines remove
    'lostAsFines': Param(True, '-', 'count the mass a replacement or an abrasion loses as fines passing every sieve in '
                         'psd.csv and the breakage indices (as a sieve analysis sees the dust); 0: only the spheres',
                         boolean, '0 or 1', flag),
}

# where a run writes and how it reports
RUN = {
    'results': Param('results', 'path', 'results root; this run writes <results>/<run id>/', anyText, 'a path', text),
    'runId': Param('', '-', "run id (default O.tags['d.id']); an existing directory gets a suffix, never overwritten",
                   anyText, 'a name', text),
    'progress': Param(10.0, 's', 'wall-clock seconds between progress lines', positive, NUMBER_POSITIVE),
}

# cycle jumping, beyond the paper (docs/cycles.md; the law is the C++ core's pkg/CycleJump.hpp): an option of every
# cyclic experiment
CYCLE_JUMP = {
    'jump': Param(False, '-', 'cycle jumping: once each grain\'s fatigue damage grows steadily over the last jumpWindow '
                  'simulated cycles, advance it over many cycles at once, never over a crush (the cycle a grain fails in '
                  'is simulated), then simulate again; the settlement of the jumped cycles is extrapolated from a law '
                  'fitted to the simulated ones, not simulated (docs/cycles.md). Needs fatigue',
                  boolean, '0 or 1', flag),
    'jumpWindow': Param(10, 'cycles', 'simulated cycles without a crush or an abrasion whose damage gives each grain\'s '
                        'rate per cycle; the rates of its two halves tell how steady it is', *coreRange('jumpWindow')),
    'jumpSteady': Param(0.2, '-', 'a grain whose rate differs between the window\'s halves by |b - a| limits a jump to '
                        'jumpSteady jumpMaxDamage / |b - a| cycles (the damage it extrapolates is that uncertain)',
                        *coreRange('jumpSteady')),
    'jumpMaxDamage': Param(0.05, '-', 'no grain\'s damage D may grow by more than this in one jump',
                           *coreRange('jumpMaxDamage')),
    'jumpMargin': Param(1, 'cycles', 'simulated cycles left between the end of a jump and the cycle in which the first '
                        'grain is predicted to fail (at its largest stress ratio of the window)', *coreRange('jumpMargin')),
    'jumpGrowth': Param(1.0, '-', 'a jump takes the cycle count N to at most (1 + jumpGrowth) N: cycles are simulated '
                        'again in every stretch of log N, where the bed may change (1: at most doubling)',
                        *coreRange('jumpGrowth')),
    'jumpDriftNoise': Param(2.0, '-', 'a grain below the endurance ratio whose peaks rise between the window\'s halves '
                            'drifts towards damage; the rise counts beyond this many standard errors of it (from the '
                            'peaks\' scatter within the halves; 0: the whole rise)', *coreRange('jumpDriftNoise')),
    'jumpDriftDamage': Param(0.0, '-', 'a grain below the endurance ratio whose peaks drift up limits a jump to the '
                             'cycles in which it would collect at most this damage unseen (a bound on the fatigue law '
                             'summed along the drift); 0: its peaks may not reach the endurance ratio, the validated '
                             'rule (longer jumps in a bed still evolving are less conservative: docs/cycles.md)',
                             *coreRange('jumpDriftDamage')),
    'jumpAfter': Param(0, 'cycles', 'no jump before this cycle: the cycles a bed needs to shake down, simulated',
                       intBetween(0, 10 ** 9), 'an integer in [0, 10^9]'),
    'jumpStates': Param('all', '-', "the states saved around each jump (state-jump<K>-before/after.yade.gz, each the "
                        "size of a state): 'all' keeps every jump's pair, 'last' only the latest jump's (the pair before "
                        "is removed once the new one is written, its names blanked in jumps.csv)", choice('all', 'last'),
                        "'all' or 'last'", text),
}


# the outputs of the cyclic piece (experiments.cyclic), the same unit and meaning in every experiment: load cycles
# (the oedometer's were seconds of loading until 2026-12; a refusal says so)
CYCLES_ALLOWED = NUMBER_NONNEGATIVE + ' of load cycles, in every experiment (the oedometer\'s were seconds before 2026-12)'
SAVE_EVERY = Param(0.0, 'cycles', 'besides the states at the start and the end, save the state every saveEvery load '
                   'cycles: a whole number after the cycle closes (state-cycle<N>.yade.gz, N the cycles done: reopen '
                   'or continueFrom goes on from it), a fraction within cycles (0.25: four states a cycle, '
                   'state-iter<step>.yade.gz); 0 = only those two', nonNegative, CYCLES_ALLOWED)
VTK = Param(0.0, 'cycles', 'a VTK frame (the grains with their state, the contact force network, the walls) every vtk '
            'load cycles from the start of loading and one at its end, listed in a .pvd for ParaView (0.1: ten frames '
            'a cycle; 0 = none)', nonNegative, CYCLES_ALLOWED)
CYCLE_OUTPUTS = {'saveEvery': SAVE_EVERY, 'vtk': VTK}
# a long run of a cyclic experiment in slices (experiments.cyclic.Cyclic.goOn): its check is the experiment's
CONTINUE_FROM = Param('', 'path', 'a state a run of this experiment saved (state-end or state-cycle<N>.yade.gz): go on '
                      'from it for `cycles` more cycles, into this run\'s folder (a long run in slices; the physics '
                      'must be the saved run\'s: a difference is refused, naming the parameter)', anyText, 'a path', text)

# a killed run taken on in its own folder (Experiment.resumeKilled); an experiment that declares it says so in its
# declaration's sets, and a study then keeps a killed row's folder to hand back
RESUME = Param(False, '-', 'go on with the run killed in <results>/<runId> (run.json "running") from the last state it '
               'saved (every saveEvery cycles, and one as loading starts), in its folder, to the end it was going to; '
               'with no such run, start afresh (docs/box.md, "A killed run goes on")', boolean, '0 or 1', flag)


class ExperimentParameters(Parameters):
    """An experiment's checked parameters (the GRAINS, INTEGRATION and crushing ones at least): the time steps
    and the crushing period derived from them, and the checks between them that every experiment makes, each
    called by the experiment's crossCheck where it applies."""

    def smallestDiameter(self):
        """The smallest grain's diameter [m] at the start (dMin; an experiment given its diameters says so)."""
        return self['dMin']

    def startTimeStep(self):
        """The paper's loading time step [s] at the start: dtSafety times YADE's PWaveTimeStep (eq. 5) of the
        smallest grain, r sqrt(rho / E)."""
        return self['dtSafety'] * self.smallestDiameter() / 2 * math.sqrt(self['density'] / self['young'])

    def loadingTimeStep(self):
        """The loading time step [s] at the start: densityStep with density scaling, the quasi-static option's first
        step (quasiStaticStart times the paper's), else startTimeStep()."""
        if self.get('quasiStatic', 0) > 0:
            return self['quasiStaticStart'] * self.startTimeStep()
        return self['densityStep'] or self.startTimeStep()

    def scaledPWaveStep(self):
        """The own P-wave step [s] density scaling gives every grain, densityStep / dtSafety (0: off)."""
        return self['densityStep'] / self['dtSafety']

    def crushPeriod(self):
        """The crushing engine's YADE period: {'virtPeriod': Tc}, or {'iterPeriod': 1} for Tc = 0 (every step)."""
        return {'virtPeriod': self['Tc']} if self['Tc'] > 0 else {'iterPeriod': 1}

    # ---------------------------------------------------------------- checks between parameters
    def checkSizes(self):
        if self['dMin'] >= self['dMax']:
            self.bad('dMin', 'must be smaller than dMax = %g' % self['dMax'])

    # grain 'polyhedron' (docs/grains.md, "Polyhedra"): which experiments take it, and the options YADE's polyhedra and
    # their PolyhedraSplitter have no counterpart for, with the one value each may take
    POLYHEDRA = False   # an experiment that takes grain 'polyhedron' says so
    POLYHEDRA_REFUSED = "YADE's polyhedra cost %s (docs/grains.md, \"Polyhedra\")" % POLYHEDRON_COST
    POLYHEDRON_ONLY = (
        ('m', 1.0, "PolyhedraSplitter's size law is ft0 / r_eq"),
        ('criterion', 'vonMises', 'PolyhedraSplitter compares the von Mises stress'),
        ('weibullModulus', 0.0, 'PolyhedraSplitter gives every grain the same strength'),
        ('fatigue', False, 'PolyhedraSplitter has no fatigue damage'),
        ('maxPerCheck', 0, 'PolyhedraSplitter splits every grain over its strength at once'),
        ('keep', 'none', "PolyhedraSplitter's pieces are its own"),
        ('pattern', 6, 'PolyhedraSplitter cuts a grain into four pieces by two planes, not into Fig. 1\'s spheres'),
        ('abrasion', False, 'polyhedra are not abraded (eq. 7 is for spheres); give abrasion 0'),
        ('law', 'linear', "polyhedra touch by YADE's volumetric law"),
        ('rollingFriction', 0.0, "YADE's volumetric law has no rolling resistance"),
        ('timeStep', 'pwave', 'the stiffness stepper reads the spheres\' laws'),
        ('densityStep', 0.0, 'density scaling reads the spheres\' P-wave steps'),
        ('quasiStatic', 0.0, 'density scaling reads the spheres\' P-wave steps'),
    )

    def checkGrain(self):
        """The clump parameters only with grain 'clump' (elsewhere a value set would be lost), and enough spheres for
        the core, tips and bridges of its shape (clumpshapes.crossMembers); grain 'polyhedron' only where the
        experiment takes it, without the options YADE's polyhedra have no counterpart for."""
        if self['grain'] == 'polyhedron':
            if not self.POLYHEDRA:
                self.bad('grain', 'polyhedra are offered in the single-particle test and the oedometer only: %s; use '
                                  'sphere or clump' % self.POLYHEDRA_REFUSED)
            for k, allowed, why in self.POLYHEDRON_ONLY:
                if k in self.PARAMS and self[k] != allowed:
                    self.bad(k, "with grain = 'polyhedron' only %r: %s" % (allowed, why))
        if self['grain'] != 'clump':
            self.refuseUnlessDefault(GRAIN_SHAPE_KEYS,
                                     "is used only with grain = 'clump' (got grain = %r)" % self['grain'])
        elif self['clumpFile']:
            self.refuseUnlessDefault(CLUMP_BUILDER_KEYS, 'the templates of clumpFile = %r replace it (leave it out, or '
                                                         'leave clumpFile out)' % self['clumpFile'])
            self.checkClumpFile()
        else:
            from ..clumpcross import crossMembers
            need = len(crossMembers(self['clumpElongation'], self['clumpFlatness'], self['clumpRoundness'])[1])
            if self['clumpSpheres'] < need:
                self.bad('clumpSpheres', 'cannot hold the core, the four tips and the %d bridges of their arms at '
                         'clumpElongation = %g, clumpFlatness = %g, clumpRoundness = %g: give at least %d' % (
                             need - 5, self['clumpElongation'], self['clumpFlatness'], self['clumpRoundness'], need))

    def checkClumpFile(self):
        """clumpFile there and its templates readable (clumpshapes.readTemplates names the line of a fault)."""
        from ..templatefile import readTemplates
        if not os.path.isfile(self['clumpFile']):
            self.bad('clumpFile', 'no such file')
        try:
            readTemplates(self['clumpFile'])
        except ValueError as e:
            self.bad('clumpFile', str(e))

    def refuseUnlessDefault(self, keys, why):
        """Each parameter of `keys` the experiment declares left at its default, else refused with `why`: a value
        set where nothing reads it would be lost without a word."""
        for k in keys:
            if k in self.PARAMS and self[k] != self.PARAMS[k].default:
                self.bad(k, why)

    def checkBed(self):
        """A bed prepared soft and crushed down to rMin: rMin <= dMax/2, prepYoung <= young, rolling resistance
        with the linear law."""
        if self['rMin'] > self['dMax'] / 2:
            self.bad('rMin', 'larger than the largest grain radius dMax/2 = %g' % (self['dMax'] / 2))
        if self['prepYoung'] > self['young']:
            self.bad('prepYoung', 'must not exceed young = %g' % self['young'])
        self.checkRolling()

    def checkRolling(self):
        """Rolling resistance is YADE's moment law on the linear contact: with law 'linear' only."""
        if self['rollingFriction'] > 0 and self['law'] != 'linear':
            self.bad('rollingFriction', "needs law = 'linear' (YADE's moment law on the linear contact), got law = %r"
                     % self['law'])

    def checkResume(self):
        """resume names the run that goes on by its folder: runId must be given."""
        if self.get('resume') and not self['runId']:
            self.bad('resume', 'give runId: the run that goes on is the one in <results>/<runId>')

    def checkGrainCount(self, volume, name):
        """A sample of `volume` [m^3] at its layers' solidFraction holds at most MAX_GRAINS grains of [dMin, dMax]
        (else the parameter `name`, which sets the volume, is named), before any preparation."""
        from ..geometry import meanCubedDiameterVolume
        n = self['solidFraction'] * volume / meanCubedDiameterVolume(self['dMin'], self['dMax'])
        if n > MAX_GRAINS:
            self.bad(name, 'a sample of %.3g m^3 holds about %.2g grains of %g-%g m, more than the %.0e a run may take' % (
                volume, n, self['dMin'], self['dMax'], MAX_GRAINS))

    def checkLoadFile(self, replaced, noun):
        """With loadFile: the options the history replaces (`replaced`, the loads and the frequency of the sine) left
        at their defaults, the file there and its history readable (self.history(): LoadHistoryError names the line).
        `noun` names what the history gives (load, deviator)."""
        from .loadhistory import LoadHistoryError
        p = self
        for k in replaced:   # the history gives the loads and the period: a value set is lost
            if p[k] != self.PARAMS[k].default:
                self.bad(k, 'is not used with loadFile = %r: the %s history gives the %ss and the period (leave %s '
                            'out, or leave loadFile out for the sine)' % (p['loadFile'], noun, noun, k))
        if not os.path.isfile(p['loadFile']):
            self.bad('loadFile', 'no such file')
        try:
            self.history()
        except LoadHistoryError as e:
            self.bad('loadFile', str(e))

    def checkStress(self, name, stress, what):
        """A mean stress `stress` [Pa] the loading puts on the sample (`what` says where; the parameter `name` sets
        it) that a rigid-sphere DEM can carry: the smallest grain, carrying stress dMin^2 through a contact with a
        grain like itself (the linear law, kn = E r), overlaps it by at most MAX_OVERLAP_RATIO of its radius (the
        oedometer's bound on Fmax through one steel contact). Beyond it the grains interpenetrate and nothing the run
        reports is physics (a peak load of 1e12 N once sank a sleeper 1 m into the floor)."""
        from ..geometry import frictPhysStiffness
        r = self['dMin'] / 2
        kn = frictPhysStiffness(self['young'], self['poisson'], r, self['young'], self['poisson'], r)[0]
        u = stress * self['dMin'] ** 2 / kn
        if u > MAX_OVERLAP_RATIO * r:
            most = MAX_OVERLAP_RATIO * r * kn / self['dMin'] ** 2
            self.bad(name, 'puts a mean stress of %.3g Pa on %s: the smallest grain would overlap its neighbour by %.3g '
                           'of its radius, more than %g (rigid-sphere DEM); at most %.3g Pa with young = %g Pa' % (
                               stress, what, u / r, MAX_OVERLAP_RATIO, most, self['young']))

    def checkDensityStep(self):
        """densityStep 0, or at least the paper's step (startTimeStep) with timeStep pwave; the quasi-static option
        chooses the step itself: with neither."""
        step, paper, timeStep = self['densityStep'], self.startTimeStep(), self['timeStep']
        if self.get('quasiStatic', 0) == 0:
            self.refuseUnlessDefault(['quasiStaticStart'], 'is used only with quasiStatic > 0 (got quasiStatic = 0)')
        if self.get('quasiStatic', 0) > 0 and (step > 0 or timeStep != 'pwave'):
            self.bad('quasiStatic', "chooses the density step itself: give densityStep 0 and timeStep 'pwave' (got %g s, "
                                    '%r)' % (step, timeStep))
        if step > 0 and timeStep != 'pwave':
            self.bad('densityStep', "%g s with timeStep = %r: density scaling sets the step itself; give timeStep "
                                    "'pwave' or densityStep 0" % (step, timeStep))
        if 0 < step < paper:
            self.bad('densityStep', "%g s is below the paper's step %.3g s (dtSafety PWaveTimeStep of the smallest "
                                    'grain): nothing would be scaled; give 0 (off) or at least %.3g s' % (step, paper, paper))

    def checkCycleJump(self):
        """Jumping needs the fatigue damage it advances."""
        if self['jump'] and not (self['fatigue'] and self['crush']):
            self.bad('jump', 'cycle jumping advances fatigue damage: it needs fatigue = 1 and crush = 1')

    def checkCycles(self, period, perCycle, overall):
        """A run of `cycles` load cycles of `period` [s] at the loading time step: each cycle at least
        MIN_STEPS_PER_CYCLE steps (else the parameter `perCycle` is named), the run at most MAX_LOADING_STEPS
        (`overall`; with jumping the cycles simulated are not known), a crushing check and an abrasion check in
        every cycle."""
        dt, cycles = self.loadingTimeStep(), self['cycles']
        if period / dt < MIN_STEPS_PER_CYCLE:
            self.bad(perCycle, 'a cycle of %.3g s spans %.3g time steps of %.3g s, fewer than %d' % (
                period, period / dt, dt, MIN_STEPS_PER_CYCLE))
        if cycles * period / dt > MAX_LOADING_STEPS and not self['jump']:
            self.bad(overall, '%d cycles of %.3g s take %.3g time steps of %.3g s (the loading time step), more than '
                              'the %.0e a run may take' % (cycles, period, cycles * period / dt, dt, MAX_LOADING_STEPS))
        if self['Tc'] > period:
            self.bad('Tc', 'longer than the load cycle, %g s: a cycle could pass without a crushing check (Tc at most '
                           'the cycle; 0 = every step)' % period)
        if self['abrasionPeriod'] * dt > period:
            self.bad('abrasionPeriod', '%d steps of %.3g s are longer than the load cycle, %g s (at most %d steps)' % (
                self['abrasionPeriod'], dt, period, int(period / dt)))
