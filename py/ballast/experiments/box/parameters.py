"""Parameters of the box test (docs/box.md), declared once: the library (``BoxTest(**kw)``), the command
line (``--name value``) and study tables use these names, units, ranges and defaults. The grains, their
contact law and every crushing, abrasion, strength, fatigue and time-step option are the oedometer's
declarations (the same ballast, the same engines); the box's own are its geometry, the bed's
preparation, the sleeper and the load. Needs no YADE."""
import hashlib
import json
import math
import os

from ...params import (CYCLE_JUMP, INT32_MAX, NUMBER_NONNEGATIVE, NUMBER_POSITIVE, Param, Parameters, anyText, between,
                       boolean, checkCycleJump, checkDensityStep, flag, intBetween, nonNegative, positive, positiveInt, text)
from ..oedometer.parameters import PARAMS as OEDOMETER, checkRolling
from ..cycleparams import PARAMS as CYCLE_OUTPUTS
from .loadhistory import LoadHistory, LoadHistoryError

OWNER = 'BoxTest'
_PHI = 'a number in [0, pi/2)'
MAX_STEPS = 1e9            # [steps] a run of more is days of CPU (the oedometer's bound)
MIN_STEPS_PER_CYCLE = 100  # [steps] a cycle resolved by fewer steps is not a load cycle

PARAMS = dict({
    'seed': Param(1, '-', 'realization: grain sizes and positions, fragment orientations', intBetween(0, INT32_MAX),
                  'an integer in [0, 2^31 - 1]'),
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
    'steelFriction': OEDOMETER['steelFriction'].withDefault(0.0, 'friction angle of the steel walls and floor of the box'),
    # the sleeper
    'sleeperWidth': Param(0.25, 'm', 'width of the sleeper section along the track (x)', positive, NUMBER_POSITIVE),
    'sleeperHeight': Param(0.2, 'm', 'height of the sleeper section', positive, NUMBER_POSITIVE),
    'sleeperGap': Param(0.01, 'm', 'clearance between each end of the sleeper and the box\'s side walls: the sleeper '
                        'spans boxWidth - 2 sleeperGap', positive, NUMBER_POSITIVE),
    'sleeperMass': Param(35.0, 'kg', 'mass of the sleeper section (a 2.5 m concrete sleeper of about 285 kg, per 0.3 m)',
                         positive, NUMBER_POSITIVE),
    'sleeperFriction': Param(0.5, 'rad', 'friction angle between the sleeper and the grains', between(0, math.pi / 2),
                             _PHI),
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
    'rollingFriction': OEDOMETER['rollingFriction'].withDefault(0.3, OEDOMETER['rollingFriction'].doc.replace(
        "0: none, the paper's spheres", "0: none, the paper's spheres (which let the sleeper punch in); 0.3 by default "
        "here")),
    'continueFrom': Param('', 'path', 'a state a box test saved (state-end or state-cycle<N>.yade.gz): go on from it '
                          'for `cycles` more cycles, into this run\'s folder (a long run in slices; the physics must be '
                          'the saved run\'s: a difference is refused, naming the parameter)', anyText, 'a path', text),
    'resume': Param(False, '-', 'go on with the run killed in <results>/<runId> (run.json "running") from the last state '
                    'it saved (saveEvery), in its folder, to the end it was going to; with no such run, start afresh '
                    '(docs/box.md, "A killed run goes on")', boolean, '0 or 1', flag),
}, **{k: OEDOMETER[k] for k in (
    'dMin', 'dMax', 'young', 'poisson', 'friction', 'density', 'steelYoungRatio', 'steelPoisson', 'steelDensity', 'law',
    'rollingStiffness',
    'prepYoung', 'prepDamping', 'depFriction', 'damping', 'dtSafety', 'timeStep', 'densityStep',
    'crush', 'ft0', 'm', 'pattern', 'rMin', 'criterion', 'weibullModulus', 'keep', 'growTime', 'maxPerCheck', 'fatigue',
    'fatigueExponent', 'fatigueEndurance', 'fatigueHysteresis', 'Tc', 'abrasion', 'strength', 'gamma',
    'abrasionPeriod', 'lostAsFines', 'results', 'runId', 'progress')}, **CYCLE_JUMP, **CYCLE_OUTPUTS)


# What decides a bed: these parameters and the version of its preparation (bump it whenever bed.build changes:
# stored beds of older versions are then not reused).
BED_KEYS = ('seed', 'boxLength', 'boxWidth', 'bedDepth', 'layers', 'solidFraction', 'layerPressure', 'steelFriction',
            'dMin', 'dMax', 'young', 'poisson', 'friction', 'density', 'steelYoungRatio', 'steelPoisson', 'steelDensity',
            'prepYoung', 'prepDamping', 'depFriction', 'law', 'rollingFriction', 'rollingStiffness')
BED_VERSION = 1


def bedKey(p):
    """(the values that decide the bed, the file name it is stored under)."""
    d = dict({k: p[k] for k in BED_KEYS}, version=BED_VERSION)
    h = hashlib.sha1(json.dumps(d, sort_keys=True).encode()).hexdigest()[:10]
    return d, 'bed-seed%d-%s.json' % (p['seed'], h)


class BoxParameters(Parameters):
    """The box test's checked parameters (frozen) and what follows from them."""

    OWNER, PARAMS = OWNER, PARAMS
    STARTED_FROM = ('continueFrom',)

    def history(self):
        """The load cycle (LoadHistory): the CSV of loadFile, else the sine."""
        if self['loadFile']:
            return LoadHistory.fromCsv(self['loadFile'])
        return LoadHistory.sine(self['seatLoad'], self['peakLoad'], self['f'])

    def startTimeStep(self):
        """The paper's step [s] at the start: dtSafety r sqrt(rho / E) of the smallest grain (eq. 5)."""
        return self['dtSafety'] * self['dMin'] / 2 * math.sqrt(self['density'] / self['young'])

    def loadingTimeStep(self):
        return self['densityStep'] or self.startTimeStep()

    def scaledPWaveStep(self):
        """The own P-wave step [s] density scaling gives every grain (0: off)."""
        return self['densityStep'] / self['dtSafety']

    def crushPeriod(self):
        return {'virtPeriod': self['Tc']} if self['Tc'] > 0 else {'iterPeriod': 1}

    def sleeperLength(self):
        return self['boxWidth'] - 2 * self['sleeperGap']

    def geometry(self):
        """What the zones of the breakage map need (zones.zoneOf)."""
        return {k: self[k] for k in ('boxLength', 'boxWidth', 'sleeperWidth', 'dMax')}

    def crossCheck(self):
        """Checks between parameters; each error names the parameter at fault."""
        p, bad = self, self.bad
        if p['dMin'] >= p['dMax']:
            bad('dMin', 'must be smaller than dMax = %g' % p['dMax'])
        checkRolling(bad, p)
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
        if p['cribDepth'] > p['sleeperHeight']:
            bad('cribDepth', 'higher than the sleeper, sleeperHeight = %g m' % p['sleeperHeight'])
        if p['sleeperGap'] * 2 >= p['boxWidth']:
            bad('sleeperGap', 'leaves no sleeper in a box of width %g m' % p['boxWidth'])
        if not p['loadFile'] and p['seatLoad'] >= p['peakLoad']:
            bad('seatLoad', 'must be smaller than peakLoad = %g N' % p['peakLoad'])
        if p['resume'] and not p['runId']:
            bad('resume', 'give runId: the run that goes on is the one in <results>/<runId>')
        if p['continueFrom'] and not os.path.isfile(p['continueFrom']):
            bad('continueFrom', 'no such state file')
        if p['loadFile']:
            if not os.path.isfile(p['loadFile']):
                bad('loadFile', 'no such file')
            try:
                self.history()
            except LoadHistoryError as e:
                bad('loadFile', str(e))
        if p['rMin'] > p['dMax'] / 2:
            bad('rMin', 'larger than the largest grain radius dMax/2 = %g' % (p['dMax'] / 2))
        if p['prepYoung'] > p['young']:
            bad('prepYoung', 'must not exceed young = %g' % p['young'])
        checkDensityStep(bad, p['densityStep'], self.startTimeStep(), p['timeStep'])
        T, dt = self.history().period, self.loadingTimeStep()
        if T / dt < MIN_STEPS_PER_CYCLE:
            bad('f' if not p['loadFile'] else 'loadFile', 'a cycle of %.3g s spans %.3g time steps of %.3g s, fewer than '
                '%d' % (T, T / dt, dt, MIN_STEPS_PER_CYCLE))
        checkCycleJump(bad, p)
        if p['cycles'] * T / dt > MAX_STEPS and not p['jump']:   # jumping: the cycles simulated are not known
            bad('cycles', '%d cycles of %.3g s take %.3g time steps of %.3g s, more than %.0e' % (
                p['cycles'], T, p['cycles'] * T / dt, dt, MAX_STEPS))
        if p['Tc'] > T:
            bad('Tc', 'longer than the load cycle (%g s): a cycle could pass without a crushing check' % T)
        if p['abrasionPeriod'] * dt > T:
            bad('abrasionPeriod', '%d steps of %.3g s are longer than the load cycle (%g s)' % (p['abrasionPeriod'], dt, T))


def check(values, text=False):
    """All parameters checked, as :class:`BoxParameters`."""
    return BoxParameters.check(values, text)
