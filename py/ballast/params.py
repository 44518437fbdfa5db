"""The parameter system of the package: every parameter (of the engines, the oedometer, the command
line and the study tables) is one :class:`Param`, declared once with its unit, default, allowed range
and doc, and validated in one place, :func:`validate`. Text (a command-line value, a table cell) is
turned into a value by :meth:`Param.fromText` and then validated like any Python value.

This module needs no YADE: the study runner reads the declarations in plain ``/usr/bin/python3``.
"""
import ast
from collections.abc import Mapping
import math
import numbers
import os

from . import _ballast


class ParamError(ValueError):
    """A bad parameter value; ``name`` is the parameter, the message names the owner, the value and
    what is allowed."""

    def __init__(self, name, message):
        ValueError.__init__(self, message)
        self.name = name


class Param:
    """One parameter: default (None = required), unit, doc, check(value) -> value or raise, allowed
    (the range in words), parse(text) -> value for command lines and tables."""

    def __init__(self, default, unit, doc, check, allowed, parse=None):
        self.default, self.unit, self.doc, self.check, self.allowed = default, unit, doc, check, allowed
        self.parse = parse or literal

    def withDefault(self, default, doc=None):
        """The same declaration with another default (an experiment's choice for an engine parameter)."""
        return Param(default, self.unit, doc or self.doc, self.check, self.allowed, self.parse)

    def fromText(self, text):
        return self.parse(text) if isinstance(text, str) else text

    def docline(self, name):
        req = 'required' if self.default is None else 'default %r' % (self.default,)
        return '%s: %s [%s] (%s; %s)' % (name, self.doc, self.unit, self.allowed, req)


# ---------------------------------------------------------------- text -> value
def literal(text):
    """A Python literal as YADE's table reader evaluates cells (1e6, 'planar4'); other text as is."""
    try:
        return ast.literal_eval(text.strip())
    except (ValueError, SyntaxError):
        return text.strip()


def text(text):
    """Text parameters (paths, names) are taken as they are; quotes of a table cell removed."""
    t = text.strip()
    return t[1:-1] if len(t) >= 2 and t[0] == t[-1] and t[0] in '\'"' else t


def flag(text):
    s = text.strip().strip('\'"').lower()
    return {'1': True, 'true': True, 'yes': True, 'on': True, '0': False, 'false': False, 'no': False,
            'off': False}.get(s, text)


# ---------------------------------------------------------------- checks: value -> value or raise
def _number(v):
    if isinstance(v, bool) or not isinstance(v, numbers.Real):
        raise TypeError('a number')
    v = float(v)
    if not math.isfinite(v):
        raise ValueError('finite')
    return v


def anyNumber(v):
    return _number(v)


def positive(v):
    v = _number(v)
    if v <= 0:
        raise ValueError
    return v


def nonNegative(v):
    v = _number(v)
    if v < 0:
        raise ValueError
    return v


def openUnit(v):
    v = _number(v)
    if not 0 < v < 1:
        raise ValueError
    return v


def unitInterval(v):
    v = _number(v)
    if not 0 <= v <= 1:
        raise ValueError
    return v


def between(lo, hi, closedHi=False):
    """A check for lo <= v < hi (or <= hi)."""
    def check(v):
        v = _number(v)
        if not (lo <= v <= hi if closedHi else lo <= v < hi):
            raise ValueError
        return v
    return check


def _integer(v):
    if isinstance(v, bool) or not isinstance(v, numbers.Real) or not math.isfinite(v) or v != int(v):
        raise ValueError
    return int(v)


def intBetween(lo, hi):
    """A check for an integer lo <= v <= hi (the range the code below can represent)."""
    def check(v):
        v = _integer(v)
        if not lo <= v <= hi:
            raise ValueError
        return v
    return check


INT64_MAX, INT32_MAX = 2 ** 63 - 1, 2 ** 31 - 1


def positiveInt(v):
    v = _integer(v)
    if v < 1:
        raise ValueError
    return v


def intAtLeast(lo):
    def check(v):
        v = _integer(v)
        if v < lo:
            raise ValueError
        return v
    return check


def anyInt(v):
    return _integer(v)


def numberList(each):
    """A check for a list (or tuple) of numbers, each passing `each`; gives a tuple (frozen)."""
    def check(v):
        if isinstance(v, (str, bytes)) or not hasattr(v, '__iter__'):
            raise ValueError
        return tuple(each(x) for x in v)
    return check


def boolean(v):
    if not isinstance(v, bool):
        raise ValueError
    return v


def anyText(v):
    if not isinstance(v, str):
        raise ValueError
    return v


def pattern(v):
    """A fragment layout of Fig. 1, as the C++ core names them (the one list of patterns)."""
    if isinstance(v, bool) or not isinstance(v, (numbers.Integral, str)):
        raise ValueError
    if isinstance(v, str) and v.strip().isdigit():
        v = int(v)
    _ballast.patternName(int(v) if isinstance(v, numbers.Integral) else v)  # raises on unknown layouts
    return int(v) if isinstance(v, numbers.Integral) else v


def choice(*names):
    """A check for one of the names."""
    def check(v):
        if v not in names:
            raise ValueError
        return v
    return check


def oneOf(names):
    """The names in words: "'a', 'b' or 'c'"."""
    quoted = ['%r' % (n,) for n in names]
    return ', '.join(quoted[:-1]) + ' or ' + quoted[-1] if len(quoted) > 1 else quoted[0]


def coreRange(name):
    """(check, words) of the engine parameter `name` from the C++ core's declaration of its range (the one
    source: pkg/InputCheck.hpp, exported as _ballast.parameterRanges()), so that Python refuses what C++ refuses,
    in the same words."""
    lower, upper, lowerClosed, upperClosed, integer, zeroAllowed, words = _ballast.parameterRanges()[name]

    def check(v):
        v = _integer(v) if integer else _number(v)
        above = lower <= v if lowerClosed else lower < v
        below = v <= upper if upperClosed else v < upper
        if not (above and below or zeroAllowed and v == 0):
            raise ValueError
        return v
    return check, words


def requireWritableDir(owner, name, path):
    """Creates the folder `path` of parameter `name` if needed and writes a probe file in it, so that a run
    fails before its work, not after it, when its results could not be stored. Raises ParamError."""
    probe = os.path.join(path, '.ballast-probe-%d' % os.getpid())
    try:
        os.makedirs(path, exist_ok=True)
        with open(probe, 'w') as fh:
            fh.write('probe\n')
        os.remove(probe)
    except OSError as e:
        raise ParamError(name, '%s: %s = %r is not allowed: expected a folder that can be created and written to (%s)'
                         % (owner, name, path, e.strerror or e)) from None


def validate(owner, table, name, value, text=False):
    """Checked value of parameter `name`, or a ParamError naming the owner, parameter, value and range.
    text=True: a string value is text from a command line or a table, read by the parameter's parse;
    else values are taken as Python gives them (a string where a number is due is an error)."""
    p = table[name]
    try:
        return p.check(p.fromText(value) if text else value)
    except (TypeError, ValueError, RuntimeError):
        raise ParamError(name, '%s: %s = %r is not allowed: expected %s [%s]' % (owner, name, value, p.allowed, p.unit)) \
            from None


def validateAll(owner, table, values, text=False):
    """Defaults of `table` updated with `values`, every one checked (see validate); unknown names raise first."""
    unknown = sorted(k for k in values if k not in table)
    if unknown:
        raise ParamError(unknown[0], '%s: unknown parameter(s) %s; parameters: %s' % (
            owner, ', '.join(unknown), ', '.join(table)))
    missing = [k for k, p in table.items() if p.default is None and k not in values]
    if missing:
        raise ParamError(missing[0], '%s: parameter(s) %s required: %s' % (
            owner, ', '.join(missing), '; '.join(table[k].docline(k) for k in missing)))
    return {k: validate(owner, table, k, values.get(k, p.default), text) for k, p in table.items()}


def docTable(table):
    return '\n'.join('    ' + p.docline(n) for n, p in table.items())


# ---------------------------------------------------------------- the engines' parameters
NUMBER_POSITIVE, NUMBER_NONNEGATIVE = 'a finite number > 0', 'a finite number >= 0'

COMMON = {
    'rMin': Param(0.0, 'm', 'grains with a radius below rMin never degrade (fragments included)', *coreRange('rMin')),
    'mask': Param(0, '-', 'groupMask selecting the checked grains (dynamic spheres); 0 = all', intBetween(0, INT32_MAX),
                  'an integer in [0, 2^31 - 1] (a YADE groupMask)'),
    'adjustDt': Param(True, '-', 'after grains shrink, scale O.dt by the drop of utils.PWaveTimeStep() '
                      '(eq. 5: dt_cr ~ r sqrt(rho/E)); with a time stepper active, until its next update',
                      boolean, 'True or False', flag),
    'scaledPWaveStep': Param(0.0, 's', 'density scaling: every grain the engine creates, shrinks or grows gets the '
                             "YADE State.densityScaling that makes its own P-wave step r sqrt(rho/E) this long (needs "
                             'NewtonIntegrator.densityScaling); O.dt is then not scaled (adjustDt has no effect); '
                             '0 = no density scaling', nonNegative, NUMBER_NONNEGATIVE),
}

# every experiment's time step options (ballast.experiments.timestep)
TIME_STEP = Param('pwave', '-', "the time step: 'pwave' (dtSafety x YADE's PWaveTimeStep of the smallest grain, eq. 5, "
                  "scaled down after each replacement: the paper's) or 'stiffness' (YADE's GlobalStiffnessTimeStepper, "
                  "safety dtSafety, from the contacts' stiffness every 10 steps; after a replacement scaled as for "
                  "pwave until its next update)", choice('pwave', 'stiffness'), "'pwave' or 'stiffness'", text)
DENSITY_STEP = Param(0.0, 's', "density scaling: the loading's time step; every grain, fragments included, gets "
                     "YADE's State.densityScaling so that its own P-wave step r sqrt(rho/E) reaches densityStep / "
                     "dtSafety (never made lighter); other moving bodies as the experiment says; 0 = off (the "
                     "paper's). At least the paper's step", nonNegative, NUMBER_NONNEGATIVE)


def checkDensityStep(bad, step, paperStep, timeStep):
    """The cross-check of every experiment: densityStep 0, or at least the paper's step [s] with timeStep pwave."""
    if step > 0 and timeStep != 'pwave':
        bad('densityStep', "%g s with timeStep = %r: density scaling sets the step itself; give timeStep 'pwave' or "
                           'densityStep 0' % (step, timeStep))
    if 0 < step < paperStep:
        bad('densityStep', "%g s is below the paper's step %.3g s (dtSafety PWaveTimeStep of the smallest grain): "
                           'nothing would be scaled; give 0 (off) or at least %.3g s' % (step, paperStep, paperStep))


# cycle jumping, beyond the paper (docs/cycles.md; the law is the C++ core's pkg/CycleJump.hpp): an option of every
# cyclic experiment
CYCLE_JUMP = {
    'jump': Param(False, '-', 'cycle jumping: once each grain\'s fatigue damage grows steadily over the last jumpWindow '
                  'simulated cycles, advance it over many cycles at once, never over a crush (the cycle a grain fails in '
                  'is simulated), then simulate again; the settlement of the jumped cycles is extrapolated from a law '
                  'fitted to the simulated ones, not simulated (docs/cycles.md). Needs fatigue',
                  boolean, 'True or False', flag),
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


def checkCycleJump(bad, p):
    """The cross-check of every cyclic experiment: jumping needs the fatigue damage it advances."""
    if p['jump'] and not (p['fatigue'] and p['crush']):
        bad('jump', 'cycle jumping advances fatigue damage: it needs fatigue = 1 and crush = 1')

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
    'initRun': Param(False, '-', 'also check at the first step', boolean, 'True or False', flag),
    'dead': Param(False, '-', 'switched off', boolean, 'True or False', flag),
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
                     boolean, 'True or False', flag),
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
                       'bound broken', boolean, 'True or False', flag),
    'verifyPeriod': Param(50, '-', 'with the prefilter, every verifyPeriod-th check reads all contacts anyway '
                          'and checks the bound against them', positiveInt, 'an integer >= 1'),
    'maxCandidates': Param(0.5, '-', 'with the prefilter, when more than this fraction of the grains are '
                           'candidates all contacts are read in one pass instead (reading grain by grain costs '
                           'about 1.6 times more per grain)', unitInterval, 'a number in [0, 1]'),
}, **COMMON)


# ---------------------------------------------------------------- checked parameters as one value
class Parameters(Mapping):
    """The checked parameters of an experiment: frozen (a new value is a new object, checked again), read
    as p['f'] or p.f; subclasses add the derived values (the step, the crushing period...). Built only by
    :meth:`check`, the one place the declarations are applied."""

    OWNER = 'experiment'
    PARAMS = {}
    STARTED_FROM = ()   # files a run started from (checked when given, not when a saved run is restored: moved since)

    def __init__(self, values, _checked=False):
        if not _checked:
            raise TypeError('%s: build parameters with %s.check(values)' % (self.OWNER, type(self).__name__))
        object.__setattr__(self, '_values', dict(values))

    @classmethod
    def check(cls, values, text=False):
        """The defaults updated with `values`, each checked (text=True: strings are text from a command line
        or a table), then :meth:`crossCheck`. Raises ParamError naming the parameter, the value and what is
        allowed."""
        if isinstance(values, cls):
            return values
        p = cls(validateAll(cls.OWNER, cls.PARAMS, dict(values), text), _checked=True)
        p.crossCheck()
        return p

    @classmethod
    def fromSaved(cls, values):
        """The parameters of a saved run: checked as :meth:`check` does, but its STARTED_FROM files, which were
        there when it started, are kept as they were, not looked for again (a slice's state outlives the state
        it continued from)."""
        return cls._checkedCarrying(values, {k: values[k] for k in cls.STARTED_FROM if k in values})

    @classmethod
    def _checkedCarrying(cls, values, carried):
        p = cls.check(dict(values, **{k: cls.PARAMS[k].default for k in carried}))
        return cls(dict(p._values, **carried), _checked=True) if carried else p

    def crossCheck(self):
        """Checks between parameters (subclasses); each error names the parameter at fault."""

    def bad(self, name, why):
        raise ParamError(name, '%s: %s = %r is not allowed: %s' % (self.OWNER, name, self[name], why))

    def replace(self, **changes):
        """A copy with some values changed, checked again (STARTED_FROM files only where changed)."""
        return type(self)._checkedCarrying(dict(self._values, **changes),
                                           {k: self._values[k] for k in self.STARTED_FROM if k not in changes})

    def __getitem__(self, name):
        return self._values[name]

    def __getattr__(self, name):
        try:
            return self._values[name]
        except KeyError:
            raise AttributeError('%s has no parameter %r' % (self.OWNER, name)) from None

    def __setattr__(self, name, value):
        raise AttributeError('%s: parameters are frozen; use replace(%s=...)' % (self.OWNER, name))

    def __iter__(self):
        return iter(self._values)

    def __len__(self):
        return len(self._values)

    def __repr__(self):
        return '%s(%s)' % (type(self).__name__, ', '.join('%s=%r' % kv for kv in self._values.items()))
