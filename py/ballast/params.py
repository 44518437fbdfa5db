"""Declared parameters of the ballast engines: each parameter is declared once, with its unit,
default, allowed range and doc string, and validated in one place, the setter."""
import math
import numbers

from . import _ballast


class Param:
    """One engine parameter: default (None = required), unit, doc, check(value) -> value or raise."""

    def __init__(self, default, unit, doc, check, allowed):
        self.default, self.unit, self.doc, self.check, self.allowed = default, unit, doc, check, allowed

    def docline(self, name):
        req = 'required' if self.default is None else 'default %r' % (self.default,)
        return '%s: %s [%s] (%s; %s)' % (name, self.doc, self.unit, self.allowed, req)


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


def intNonNegative(v):
    if isinstance(v, bool) or not isinstance(v, numbers.Integral) or v < 0:
        raise ValueError
    return int(v)


def positiveInt(v):
    if isinstance(v, bool) or not isinstance(v, numbers.Integral) or v < 1:
        raise ValueError
    return int(v)


def anyInt(v):
    if isinstance(v, bool) or not isinstance(v, numbers.Integral):
        raise ValueError
    return int(v)


def boolean(v):
    if not isinstance(v, bool):
        raise ValueError
    return v


def pattern(v):
    if isinstance(v, bool) or not isinstance(v, (numbers.Integral, str)):
        raise ValueError
    _ballast.patternName(int(v) if isinstance(v, numbers.Integral) else v)  # raises on unknown layouts
    return int(v) if isinstance(v, numbers.Integral) else v


def validate(owner, table, name, value):
    """Checked value of parameter `name`, or a ValueError naming the engine, parameter, value and range."""
    p = table[name]
    try:
        return p.check(value)
    except (TypeError, ValueError):
        raise ValueError('%s: %s = %r is not allowed: expected %s [%s]' % (owner, name, value, p.allowed, p.unit)) from None


def docTable(table):
    return '\n'.join('    ' + p.docline(n) for n, p in table.items())
