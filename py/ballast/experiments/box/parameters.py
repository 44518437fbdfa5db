"""Parameters of the box test (docs/box.md), declared once: the library (``BoxTest(**kw)``), the command
line (``--name value``) and study tables use these names, units, ranges and defaults. The grains, their
contact law and every crushing, abrasion, strength, fatigue and time-step option are the declarations every
experiment shares (:mod:`ballast.experiments.parameters`: the same ballast, the same engines); the box's own
are its geometry, the bed's preparation, the sleeper and the load. Needs no YADE."""
import math
import os

from ...params import NUMBER_NONNEGATIVE, NUMBER_POSITIVE, Param, anyText, between, boolean, flag, intBetween, nonNegative, \
    positive, positiveInt, text
from ..parameters import (CONTACT, CONTINUE_FROM, CYCLE_JUMP, ENGINES, GRAIN, GRAINS, INTEGRATION, PHI, PREPARATION,
                          RESUME, RUN, SEED, STEEL, CYCLE_OUTPUTS, QUASI_STATIC, ExperimentParameters, grainKey,
                          storeName, take)
from ..loadhistory import LoadHistory

OWNER = 'BoxTest'

PARAMS = {
    'seed': SEED,
    # the box and the bed (choices: docs/box.md, "Set-up")
    'boxLength': Param(0.7, 'm', 'inner length of the box along the track (x); the sleeper sits in its middle',
                       positive, NUMBER_POSITIVE),
    'boxWidth': Param(0.3, 'm', 'inner width of the box (y), along the sleeper', positive, NUMBER_POSITIVE),
    'bedDepth': Param(0.3, 'm', 'depth of ballast under the sleeper (the bed is built to this height)', positive,
                      NUMBER_POSITIVE),
    'layers': Param(3, '-', 'layers the bed is placed and compacted in', intBetween(1, 20), 'an integer in [1, 20]'),
    'solidFraction': Param(0.6, '-', 'solid volume of the grains of a layer over the layer\'s share of the box '
                           '(boxLength boxWidth bedDepth / layers)', between(0.3, 0.74), 'a number in [0.3, 0.74)'),
    'layerPressure': Param(1e5, 'Pa', 'pressure on each frictionless layer through a plate until it rests (the '
                           'oedometer\'s press: 8 kN on its 0.3 m cylinder, 113 kPa)', positive, NUMBER_POSITIVE),
    'reuseBed': Param(True, '-', 'load the stored bed of this seed and bed parameters if there is one (the study '
                      'builds each bed once)', boolean, '0 or 1', flag),
    'bedDir': Param('', 'path', 'where beds are stored (default <results>/beds)', anyText, 'a path', text),
    'steelFriction': STEEL['steelFriction'].withDefault(0.0, 'friction angle of the steel walls and floor of the box'),
    # the sleeper
    'sleeperWidth': Param(0.25, 'm', 'width of the sleeper section along the track (x)', positive, NUMBER_POSITIVE),
    'sleeperHeight': Param(0.2, 'm', 'height of the sleeper section', positive, NUMBER_POSITIVE),
    'sleeperGap': Param(0.01, 'm', 'clearance between each end of the sleeper and the box\'s side walls: the sleeper '
                        'spans boxWidth - 2 sleeperGap', positive, NUMBER_POSITIVE),
    'sleeperMass': Param(35.0, 'kg', 'mass of the sleeper section (a 2.5 m concrete sleeper of about 285 kg, per 0.3 m)',
                         positive, NUMBER_POSITIVE),
    'sleeperFriction': Param(0.5, 'rad', 'friction angle between the sleeper and the grains', between(0, math.pi / 2),
                             PHI),
    'cribDepth': Param(0.0, 'm', 'crib ballast: grains tipped beside the sleeper up to this height above its underside '
                       '(at most sleeperHeight; 0: none, the sleeper sits on the bed\'s surface)', nonNegative,
                       NUMBER_NONNEGATIVE),
    'tilt': Param(True, '-', 'the sleeper may tilt about the box\'s width axis (y) as well as settle; 0: settles only',
                  boolean, '0 or 1', flag),
    # the load
    'seatLoad': Param(3e3, 'N', 'seating load: the load between the train\'s passes, where the permanent settlement '
                      'is read', positive, NUMBER_POSITIVE),
    'peakLoad': Param(40e3, 'N', 'peak load of a cycle (a sine from seatLoad up to peakLoad and back)', positive,
                      NUMBER_POSITIVE),
    'f': Param(3.0, 'Hz', 'loading frequency of the sine', positive, NUMBER_POSITIVE),
    'loadFile': Param('', 'path', 'a load history instead of the sine: a CSV with columns t [s] and F [N], one cycle '
                      'from t = 0, ending at the load it starts at (docs/box.md, "Load")', anyText, 'a path', text),
    'cycles': Param(10, '-', 'load cycles of one load()', positiveInt, 'an integer >= 1'),
    'samples': Param(100, '-', 'rows of samples.csv per cycle (the settlement, the load and the work per cycle are '
                     'read from them)', intBetween(20, 100000), 'an integer in [20, 100000]'),
    # the paper's spheres roll freely: under a sleeper they roll aside and it punches into the bed (docs/box.md)
    'rollingFriction': CONTACT['rollingFriction'].withDefault(0.3, CONTACT['rollingFriction'].doc.replace(
        "0: none, the paper's spheres", "0: none, the paper's spheres (which let the sleeper punch in); 0.3 by default "
        "here")),
    'continueFrom': CONTINUE_FROM,
    'resume': RESUME,
    **GRAINS,
    **GRAIN,
    **take(STEEL, 'steelYoungRatio', 'steelPoisson', 'steelDensity'),
    **take(CONTACT, 'law', 'rollingStiffness'),
    **PREPARATION,
    **INTEGRATION,
    **ENGINES,
    **RUN,
    **CYCLE_JUMP,
    **CYCLE_OUTPUTS,
    **QUASI_STATIC,
}

# What decides a bed: these parameters and the version of its preparation (bump it whenever bed.build changes:
# stored beds of older versions are then not reused).
BED_KEYS = ('seed', 'boxLength', 'boxWidth', 'bedDepth', 'layers', 'solidFraction', 'layerPressure', 'steelFriction',
            'dMin', 'dMax', 'young', 'poisson', 'friction', 'density', 'steelYoungRatio', 'steelPoisson', 'steelDensity',
            'prepYoung', 'prepDamping', 'depFriction', 'law', 'rollingFriction', 'rollingStiffness')
BED_VERSION = 1


def bedKey(p):
    """(the values that decide the bed, the file name it is stored under)."""
    d = dict({k: p[k] for k in BED_KEYS}, version=BED_VERSION, **grainKey(p))   # sphere beds keep their names
    return d, storeName('bed', p['seed'], d)


class BoxParameters(ExperimentParameters):
    """The box test's checked parameters (frozen) and what follows from them."""

    OWNER, PARAMS = OWNER, PARAMS
    STARTED_FROM = ('continueFrom',)

    def history(self):
        """The load cycle (LoadHistory): the CSV of loadFile, else the sine."""
        if self['loadFile']:
            return LoadHistory.fromCsv(self['loadFile'])
        return LoadHistory.sine(self['seatLoad'], self['peakLoad'], self['f'])

    def sleeperLength(self):
        return self['boxWidth'] - 2 * self['sleeperGap']

    def geometry(self):
        """What the zones of the breakage map need (zones.zoneOf)."""
        return {k: self[k] for k in ('boxLength', 'boxWidth', 'sleeperWidth', 'dMax')}

    def crossCheck(self):
        """Checks between parameters; each error names the parameter at fault."""
        p, bad = self, self.bad
        self.checkGrain()
        self.checkSizes()
        self.checkBed()
        if p['bedDepth'] < 2 * p['dMax']:
            bad('bedDepth', 'must hold at least two of the largest grains, 2 dMax = %g m' % (2 * p['dMax']))
        if p['bedDepth'] / p['layers'] < p['dMax']:
            bad('layers', 'layers of %.3g m are thinner than the largest grain dMax = %g m' % (
                p['bedDepth'] / p['layers'], p['dMax']))
        if p['boxWidth'] < 3 * p['dMax']:
            bad('boxWidth', 'must be at least 3 dMax = %g m' % (3 * p['dMax']))
        if p['sleeperWidth'] > p['boxLength'] - 4 * p['dMax']:
            bad('sleeperWidth', 'leaves less than 2 dMax of ballast on either side in a box of length %g m (at most %g m)'
                % (p['boxLength'], p['boxLength'] - 4 * p['dMax']))
        self.checkGrainCount(p['boxLength'] * p['boxWidth'] * p['bedDepth'], 'boxLength')
        if p['cribDepth'] > p['sleeperHeight']:
            bad('cribDepth', 'higher than the sleeper, sleeperHeight = %g m' % p['sleeperHeight'])
        if p['sleeperGap'] * 2 >= p['boxWidth']:
            bad('sleeperGap', 'leaves no sleeper in a box of width %g m' % p['boxWidth'])
        if not p['loadFile'] and p['seatLoad'] >= p['peakLoad']:
            bad('seatLoad', 'must be smaller than peakLoad = %g N' % p['peakLoad'])
        self.checkResume()
        if p['continueFrom'] and not os.path.isfile(p['continueFrom']):
            bad('continueFrom', 'no such state file')
        if p['loadFile']:
            self.checkLoadFile(('seatLoad', 'peakLoad', 'f'), 'load')
        self.checkStress('loadFile' if p['loadFile'] else 'peakLoad', self.history().peak / (
            p['sleeperWidth'] * self.sleeperLength()), "the bed under the sleeper's footprint")
        self.checkDensityStep()
        self.checkCycleJump()
        self.checkCycles(self.history().period, 'f' if not p['loadFile'] else 'loadFile', 'cycles')


def check(values, text=False):
    """All parameters checked, as :class:`BoxParameters`."""
    return BoxParameters.check(values, text)
