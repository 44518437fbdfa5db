"""Tables a study writes: a grid of parameter values (``scripts/study.py grid``), refused like a table to
run. Reading tables is :mod:`ballast.tables`, below experiments and studies."""
import itertools
import re

from ..tables import Table
from .options import StudyError, experimentDeclaration


def gridValues(spec):
    """NAME=V1,V2,... or NAME=A:B (the integers A to B): (NAME, [cell text])."""
    m = re.fullmatch(r'([A-Za-z_]\w*!?)=(.+)', spec)
    if not m:
        raise StudyError('grid: %r is not NAME=V1,V2,... or NAME=A:B' % spec)
    name, vals = m.group(1), m.group(2)
    r = re.fullmatch(r'(-?\d+):(-?\d+)', vals)
    if r:
        a, b = int(r.group(1)), int(r.group(2))
        if b < a:
            raise StudyError('grid: %s: empty range %s' % (name, vals))
        return name, [str(v) for v in range(a, b + 1)]
    out = [v.strip() for v in vals.split(',')]
    if any(not v or re.search(r'\s', v) for v in out):
        raise StudyError('grid: %s: empty value or blank inside a value in %r' % (name, vals))
    return name, out


def gridTable(axes, fixed=(), comments=(), command='', declaration=None):
    """The text of a table with every combination of the values of `axes` (NAME=VALUES, the first
    varies slowest) and the `fixed` columns (NAME=V); refused like a table to run (Table.check with
    `declaration`) if a row is bad."""
    axes = [gridValues(s) for s in axes]
    fixed = [gridValues(s) for s in fixed]
    for name, vals in fixed:
        if len(vals) != 1:
            raise StudyError('--fixed: %s takes one value, got %s' % (name, ','.join(vals)))
    names = [n for n, _ in axes + fixed]
    rows = [list(c) + [v[0] for _, v in fixed] for c in itertools.product(*[v for _, v in axes])]
    widths = [max(len(x) for x in [n] + [r[i] for r in rows]) for i, n in enumerate(names)]
    text = ''.join('# %s\n' % c for c in comments) + ('# written by: %s\n' % command if command else '')
    for r in [names] + rows:
        text += ' '.join(x.ljust(w) for x, w in zip(r, widths)).rstrip() + '\n'
    Table('grid', text).check(experimentDeclaration(declaration))  # what it writes must run
    return text, len(rows)
