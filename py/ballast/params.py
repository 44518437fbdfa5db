"""The parameter system of the package: every parameter (of the engines, the experiments, the command
lines and the study tables) is one :class:`Param`, declared once with its unit, default, allowed range
and doc, and validated in one place, :func:`validate`. Text (a command-line value, a table cell) is
turned into a value by :meth:`Param.fromText`, in the spellings --help gives only, and then validated
like any Python value. A checked set of them is a :class:`Parameters`.

The declarations live with what they configure: the engines' in :mod:`ballast.engineparams`, what every
experiment shares in :mod:`ballast.experiments.parameters`, each experiment's own in its folder.

This module needs no YADE: the study runner reads the declarations in plain ``/usr/bin/python3``.
"""
import ast
from collections.abc import Mapping
import io
import math
import numbers
import os
import re
import tokenize

from . import _ballast


class ParamError(ValueError):
    """A bad parameter value; ``name`` is the parameter, the message names the owner, the value and
    what is allowed."""

    def __init__(self, name, message):
        ValueError.__init__(self, message)
        self.name = name


class TextError(ValueError):
    """Text written in a spelling the parameters do not read (0x10, yes); `expected`: what is read instead,
    in words (None: the declaration's range, written in decimal)."""

    def __init__(self, expected=None):
        ValueError.__init__(self, expected)
        self.expected = expected


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
# Text (a command line, a table cell) is read in the spellings --help gives: a number in decimal (1e6, 0.5, 16),
# a flag 0 or 1. Python's other forms of a number (0x10, 0o7, 0b1, 1_000, 1j) and other words for a flag (yes,
# True) are refused: a typo must not become another value silently.
DECIMAL_ONLY = 'written in decimal (hexadecimal, octal, binary, complex and 1_000 forms are refused)'
_NOT_DECIMAL = re.compile(r'^0[xob]|_|j$', re.IGNORECASE)


def _decimal(text):
    """Whether every number in `text` is written in decimal (text that is no Python is left to the check)."""
    try:
        return not any(t.type == tokenize.NUMBER and _NOT_DECIMAL.search(t.string)
                       for t in tokenize.generate_tokens(io.StringIO(text).readline))
    except (tokenize.TokenError, SyntaxError):
        return True


def literal(text):
    """A Python literal as YADE's table reader evaluates cells (1e6, 'planar4', [0.02, 0.04]), its numbers
    in decimal only (TextError); other text as is."""
    if not _decimal(text.strip()):
        raise TextError()
    try:
        return ast.literal_eval(text.strip())
    except (ValueError, SyntaxError):
        return text.strip()


def text(text):
    """Text parameters (paths, names) are taken as they are; quotes of a table cell removed."""
    t = text.strip()
    return t[1:-1] if len(t) >= 2 and t[0] == t[-1] and t[0] in '\'"' else t


def flag(text):
    """A flag: 0 or 1 (quoted in a table cell or not); anything else is TextError."""
    s = text.strip().strip('\'"')
    if s not in ('0', '1'):
        raise TextError('0 or 1')
    return s == '1'


# ---------------------------------------------------------------- checks: value -> value or raise
def _number(v):
    if isinstance(v, bool) or not isinstance(v, numbers.Real):
        raise TypeError('a number')
    v = float(v)
    if not math.isfinite(v):
        raise ValueError('finite')
    return v


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
NUMBER_POSITIVE, NUMBER_NONNEGATIVE = 'a finite number > 0', 'a finite number >= 0'


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
    text=True: a string value is text from a command line or a table, read by the parameter's parse (in the
    documented spellings only); else values are taken as Python gives them (a string where a number is due is
    an error)."""
    p = table[name]
    try:
        return p.check(p.fromText(value) if text else value)
    except TextError as e:
        expected = e.expected or '%s [%s], %s' % (p.allowed, p.unit, DECIMAL_ONLY)
        raise ParamError(name, '%s: %s = %r is not allowed: expected %s' % (owner, name, value, expected)) from None
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
