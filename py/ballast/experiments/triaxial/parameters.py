"""Parameters of the cyclic triaxial test (docs/triaxial.md), declared once: the library (``TriaxialTest(**kw)``), the
command line (``--name value``) and study tables use these names, units, ranges and defaults. The grains, their
contact law and every crushing, abrasion, strength, fatigue, time-step and cycle-jumping option are the declarations
every experiment shares (:mod:`ballast.experiments.parameters`); the test's own are the specimen, its preparation,
the membrane and the stresses. Needs no YADE."""
import functools
import math
import os

from ...params import NUMBER_NONNEGATIVE, NUMBER_POSITIVE, Param, anyText, between, boolean, choice, flag, intBetween, \
    nonNegative, positive, positiveInt, text
from ..parameters import (CONTACT, CONTINUE_FROM, CYCLE_JUMP, CYCLE_OUTPUTS, ENGINES, GRAIN, GRAINS, INTEGRATION,
                          PREPARATION, QUASI_STATIC, RUN, SEED, STEEL, ExperimentParameters, grainKey, storeName, take)
from ..loadhistory import LoadHistory
from .strains import CurveError, readReference

OWNER = 'TriaxialTest'

PARAMS = {
    'seed': SEED,
    # the specimen (the Wollongong group's large-scale cell: Indraratna, Ionescu and Christie 1998; Sun, Indraratna
    # and Nimbalkar 2016): 300 mm across, 600 mm high
    'diameter': Param(0.3, 'm', 'specimen diameter (the mould\'s inner diameter)', positive, NUMBER_POSITIVE),
    'height': Param(0.6, 'm', 'specimen height (the mould is filled to it)', positive, NUMBER_POSITIVE),
    'segments': Param(48, '-', 'facets around the preparation mould', intBetween(12, 720), 'an integer in [12, 720]'),
    'layers': Param(4, '-', 'layers the specimen is placed and compacted in (the laboratory compacts in layers)',
                    intBetween(1, 40), 'an integer in [1, 40]'),
    'solidFraction': Param(0.6, '-', 'solid volume of the grains of a layer over the layer\'s share of the mould: '
                           'with layerPressure, what sets the specimen\'s porosity (reported as porosity)',
                           between(0.3, 0.74), 'a number in [0.3, 0.74)'),
    'layerPressure': Param(1e5, 'Pa', 'pressure on each layer through a plate until it rests (with compaction '
                           '\'height\', or until it reaches the layer\'s mark)', positive, NUMBER_POSITIVE),
    'compaction': Param('pressure', '-', "how each layer is compacted: 'pressure' (pressed at layerPressure until it "
                        "rests: the porosity follows from the grains, denser than 1 - solidFraction without friction) "
                        "or 'height' (pressed so, but stopped and held at its share of the specimen's height, as a "
                        "laboratory compacts layers to marks on the mould, Ladd 1978: the porosity is 1 - "
                        "solidFraction where the grains, deposited with depFriction, lie looser than that and "
                        "layerPressure packs them to it; the porosity reached is reported)", choice('pressure', 'height'),
                        "'pressure' or 'height'", text),
    'reuseSpecimen': Param(True, '-', 'load the stored specimen of this seed and specimen parameters if there is '
                           'one, else, with depFriction 0, its stored layers if a specimen that differs in young or '
                           'friction only left them (docs/triaxial.md, "Set-up")', boolean, '0 or 1', flag),
    'specimenDir': Param('', 'path', 'where specimens are stored (default <results>/specimens)', anyText, 'a path',
                         text),
    'platenMass': Param(20.0, 'kg', 'mass of the top platen and the loading ram it moves with', positive,
                        NUMBER_POSITIVE),
    # the membrane (docs/triaxial.md, "The membrane")
    'membraneCell': Param(0.0, 'm', 'size of the membrane\'s cells (0: dMin / 2)', nonNegative, NUMBER_NONNEGATIVE),
    'membraneDepth': Param(0.0, 'm', 'how far into a gap between outer grains the membrane follows (0: dMin / 4)',
                           nonNegative, NUMBER_NONNEGATIVE),
    'membranePeriod': Param(10, 'steps', 'steps between updates of the membrane\'s load and the axial load',
                            intBetween(1, 10000), 'an integer in [1, 10000]'),
    # the stresses (Sun, Indraratna and Nimbalkar 2016: p' = 60 kPa, q_max = 230 kPa, 5 Hz; q_min is not in the data
    # given: a choice, docs/triaxial.md)
    'confining': Param(60e3, 'Pa', 'effective confining pressure p\' (the cell pressure, drained)', positive,
                       NUMBER_POSITIVE),
    'qMin': Param(45e3, 'Pa', 'smallest deviator stress of a cycle (a choice: not given with the measured curve)',
                  nonNegative, NUMBER_NONNEGATIVE),
    'qMax': Param(230e3, 'Pa', 'largest deviator stress of a cycle', positive, NUMBER_POSITIVE),
    'f': Param(5.0, 'Hz', 'loading frequency of the sine', positive, NUMBER_POSITIVE),
    'loadFile': Param('', 'path', 'a deviator history instead of the sine: a CSV with columns t [s] and q [Pa], one '
                      'cycle from t = 0, ending at the deviator it starts at (its first q seats the specimen, as '
                      'qMin does)', anyText, 'a path', text),
    'cycles': Param(10, '-', 'load cycles of one load()', positiveInt, 'an integer >= 1'),
    'failureStrain': Param(0.2, '-', 'axial strain at which cycling stops: the specimen failed (a laboratory stops a '
                           'cyclic test once the specimen fails; summary.json says so, with the cycle)',
                           between(0.001, 0.5), 'a number in [0.001, 0.5)'),
    # the monotonic drained compression (docs/triaxial.md, "Monotonic compression")
    'monotonic': Param(False, '-', 'instead of cycles, a drained monotonic compression: the top platen driven down at '
                       'strainRate under p\' until maxAxialStrain', boolean, '0 or 1', flag),
    'strainRate': Param(0.05, '1/s', 'axial strain rate of the monotonic compression (the platen\'s speed over the '
                        'consolidated height; quasi-static while the inertial number, reported, stays below 1e-3)',
                        between(1e-4, 10.0), 'a number in [1e-4, 10)'),
    'maxAxialStrain': Param(0.15, '-', 'axial strain at which the monotonic compression ends', between(0.005, 0.5),
                            'a number in [0.005, 0.5)'),
    'samples': Param(50, '-', 'rows of samples.csv per cycle (the strains and the stress path)', intBetween(20, 100000),
                     'an integer in [20, 100000]'),
    'reference': Param('', 'path', 'measured curves drawn over the simulated ones in strains.png: CSV files with a header '
                       'N,axial_strain or N,volumetric_strain (strains as fractions), separated by commas', anyText,
                       'paths', text),
    'consolidationTime': Param(0.5, 's', 'longest isotropic consolidation (it ends earlier once the platen rests)',
                               positive, NUMBER_POSITIVE),
    'rollingFriction': CONTACT['rollingFriction'].withDefault(0.3, CONTACT['rollingFriction'].doc.replace(
        "0: none, the paper's spheres", "0: none, the paper's spheres (which roll apart under a deviator); 0.3 by "
        "default here, as in the box test")),
    **GRAINS,
    **GRAIN,
    **take(STEEL, 'steelYoungRatio', 'steelPoisson', 'steelFriction', 'steelDensity'),
    **take(CONTACT, 'law', 'rollingStiffness'),
    **PREPARATION,
    **INTEGRATION,
    **ENGINES,
    **RUN,
    **CYCLE_JUMP,
    **CYCLE_OUTPUTS,
    'continueFrom': CONTINUE_FROM,
    **QUASI_STATIC,
}

@functools.lru_cache(maxsize=8)
def _history(path, mtime):
    """loadFile's history, read once per file and version (the deviator is asked for every membranePeriod steps)."""
    return LoadHistory.fromCsv(path, LoadHistory.DEVIATOR)


# What decides a specimen: these parameters and the version of its preparation (bump it whenever specimen.build
# changes: stored specimens of older versions are then not reused).
SPECIMEN_KEYS = ('seed', 'diameter', 'height', 'segments', 'layers', 'solidFraction', 'layerPressure', 'steelFriction',
                 'dMin', 'dMax', 'young', 'poisson', 'friction', 'density', 'steelYoungRatio', 'steelPoisson',
                 'steelDensity', 'prepYoung', 'prepDamping', 'depFriction', 'law', 'rollingFriction', 'rollingStiffness')
SPECIMEN_VERSION = 1


# what the layers decide before friction and the true modulus are given them (the frictionless, soft deposition and
# pressing read prepYoung and depFriction): specimens that differ only in these share their layers (layersKey)
FINISH_KEYS = ('young', 'friction')


def specimenKey(p, keys=SPECIMEN_KEYS, prefix='specimen'):
    """(the values that decide the specimen, the file name it is stored under)."""
    d = dict({k: p[k] for k in keys}, version=SPECIMEN_VERSION, **grainKey(p))   # sphere ones keep their names
    if p['compaction'] != 'pressure':   # only then: the specimens stored before the option keep their names
        d['compaction'] = p['compaction']
    return d, storeName(prefix, p['seed'], d)


def layersKey(p):
    """(the values that decide the specimen's layers as deposited and pressed, before friction and the true modulus;
    the file name they are stored under)."""
    return specimenKey(p, tuple(k for k in SPECIMEN_KEYS if k not in FINISH_KEYS), 'layers')


class TriaxialParameters(ExperimentParameters):
    """The triaxial test's checked parameters (frozen) and what follows from them."""

    OWNER, PARAMS = OWNER, PARAMS
    STARTED_FROM = ('continueFrom',)

    def history(self):
        """The deviator's cycle from loadFile (LoadHistory, read once a process), None for the sine."""
        return _history(self['loadFile'], os.path.getmtime(self['loadFile'])) if self['loadFile'] else None

    def period(self):
        h = self.history()
        return h.period if h else 1.0 / self['f']

    def seatDeviator(self):
        """The deviator at each cycle's start and end [Pa]: qMin, or the history's first; 0 before a monotonic
        compression (it starts from the isotropic state)."""
        if self['monotonic']:
            return 0.0
        h = self.history()
        return h.seat if h else self['qMin']

    def peakDeviator(self):
        """The largest deviator of a cycle [Pa]: qMax, or the history's."""
        h = self.history()
        return h.peak if h else self['qMax']

    def deviator(self, t):
        """The deviator stress [Pa] at loading time t [s]: the sine from qMin up to qMax and back, a cycle from t = 0
        (q = qMin at each cycle's start and end), or loadFile's history interpolated linearly, cycle after cycle."""
        h = self.history()
        if h:
            return float(h.at(t))
        return self['qMin'] + (self['qMax'] - self['qMin']) * 0.5 * (1 - math.cos(2 * math.pi * self['f'] * t))

    def cell(self):
        """The membrane's cell size [m] (membraneCell, or dMin / 2)."""
        return self['membraneCell'] or self['dMin'] / 2

    def depth(self):
        """How far into a gap the membrane follows [m] (membraneDepth, or dMin / 4)."""
        return self['membraneDepth'] or self['dMin'] / 4

    def references(self):
        """The measured curves of `reference`: [(kind, N, strain)] (strains.readReference)."""
        return [readReference(f.strip()) for f in self['reference'].split(',') if f.strip()]

    def crossCheck(self):
        """Checks between parameters; each error names the parameter at fault."""
        p, bad = self, self.bad
        self.checkGrain()
        self.checkSizes()
        self.checkBed()
        if p['diameter'] < 4 * p['dMax']:
            bad('diameter', 'must hold at least 4 of the largest grains across, 4 dMax = %g m' % (4 * p['dMax']))
        if p['height'] < 2 * p['diameter'] / 3 or p['height'] > 3 * p['diameter']:
            bad('height', '%g m: a triaxial specimen is 2/3 to 3 times as high as it is wide (diameter %g m)' % (
                p['height'], p['diameter']))
        if p['height'] / p['layers'] < p['dMax']:
            bad('layers', 'layers of %.3g m are thinner than the largest grain dMax = %g m' % (
                p['height'] / p['layers'], p['dMax']))
        self.checkGrainCount(math.pi * p['diameter'] ** 2 / 4 * p['height'], 'diameter')
        if p['qMin'] >= p['qMax']:
            bad('qMin', 'must be smaller than qMax = %g Pa' % p['qMax'])
        if p['loadFile']:
            self.checkLoadFile(('qMin', 'qMax', 'f'), 'deviator')
        if p['monotonic']:
            for k in ('loadFile', 'quasiStatic', 'jump', 'continueFrom'):
                if p[k]:
                    bad(k, 'is for load cycles, not a monotonic compression (monotonic 1): %s' % (
                        'give densityStep or timeStep stiffness for fewer steps' if k == 'quasiStatic' else
                        'leave it out'))
        self.checkStress('loadFile' if p['loadFile'] else 'qMax' if p['qMax'] >= p['confining'] else 'confining',
                         p['confining'] + self.peakDeviator(), "the specimen's ends at the peak (confining + qMax)")
        if p['membraneCell'] > p['dMax']:
            bad('membraneCell', '%g m is larger than the largest grain, dMax = %g m: the membrane would not see the '
                'grains it rests on' % (p['membraneCell'], p['dMax']))
        if p['membraneCell'] and p['membraneCell'] < p['dMin'] / 20:
            bad('membraneCell', '%g m is under dMin / 20 = %g m: cells far finer than the grains cost without use' % (
                p['membraneCell'], p['dMin'] / 20))
        if p['continueFrom'] and not os.path.isfile(p['continueFrom']):
            bad('continueFrom', 'no such state file')
        try:
            self.references()
        except CurveError as e:
            bad('reference', str(e))
        self.checkDensityStep()
        self.checkCycleJump()
        self.checkCycles(self.period(), 'f', 'cycles')


def check(values, text=False):
    """All parameters checked, as :class:`TriaxialParameters`."""
    return TriaxialParameters.check(values, text)
