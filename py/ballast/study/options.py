"""What the user gives the study runner: its options with a unit and a range, declared once (the
command line, ``scripts/study.py run``, and the library, :class:`Study` and the executors, check
them here), and the error for bad input."""
import argparse
import re

from ..tables import TableError
from ..params import NUMBER_POSITIVE, Param, ParamError, anyInt, positive, positiveInt, text, validate

OWNER = 'study'


# Bad input, found before any run starts; the message names the argument (or the table line and column), the
# value and what is allowed. The command lines exit with status 2 on it. One class with the table reader's
# (ballast.tables, a floor below): a study's and a table's errors are caught alike.
StudyError = TableError


# what a study runs when none is named, and what made the study folders older than study.json's 'experiment'
DEFAULT_EXPERIMENT = 'oedometer'


def experimentDeclaration(experiment=None):
    """The declaration (ballast.experiments.Declaration) of `experiment`: a name, a Declaration, or None
    for DEFAULT_EXPERIMENT. StudyError naming the experiments there are."""
    from ..experiments import Declaration, declaration
    if isinstance(experiment, Declaration):
        return experiment
    try:
        return declaration(experiment or DEFAULT_EXPERIMENT)
    except ValueError as e:
        raise StudyError('--experiment: %s' % e) from None


def lineList(v):
    """yade-batch's --lines: '2,3-5,8' (or line numbers) -> the sorted line numbers."""
    if isinstance(v, str):
        spans = [re.fullmatch(r'\s*(\d+)\s*(?:-\s*(\d+)\s*)?', part) for part in v.split(',')]
        if not all(spans):
            raise ValueError
        v = [n for m in spans for n in range(int(m.group(1)), int(m.group(2) or m.group(1)) + 1)]
    return sorted(set(positiveInt(n) for n in v))


def niceness(v):
    v = anyInt(v)
    if not -20 <= v <= 19:
        raise ValueError
    return v


OPTIONS = {
    'lines': Param(None, 'line', "only these lines of the table, in yade-batch's format (default: every row)", lineList,
                   'a list like 2,3-5,8', text),
    'jobs': Param(None, 'runs', 'local: runs at the same time, one core each (default: the cores of this machine)',
                  positiveInt, 'an integer >= 1'),
    'timeout': Param(None, 's', 'kill a run after this wall time: a failed run (default: no limit)', positive,
                     NUMBER_POSITIVE),
    'nice': Param(10, '-', "nice value of the runs, as yade-batch's", niceness, 'an integer from -20 to 19'),
    'progress': Param(60.0, 's', 'wall time between progress lines', positive, NUMBER_POSITIVE),
    'connectTimeout': Param(20.0, 's', 'dask: how long to wait for the scheduler', positive, NUMBER_POSITIVE),
}


def flag(name):
    """The command-line flag of an option: connectTimeout -> --connect-timeout."""
    return '--' + re.sub('[A-Z]', lambda m: '-' + m.group().lower(), name)


def optionValue(name, value, text=False):
    """value (a Python value, or with text=True the text of the command line) checked against its
    declaration; None stays None (not given). A bad value raises StudyError naming the flag."""
    if value is None:
        return None
    try:
        return validate(OWNER, OPTIONS, name, value, text)
    except ParamError as e:
        raise StudyError('%s: %s' % (flag(name), e)) from None


SHORT = {'jobs': '-j', 'lines': '-l'}  # short flags on the command line


def argument(name):
    """argparse keywords for option `name`: help with unit, range and default, checked on parsing."""
    p = OPTIONS[name]

    def parse(text):
        try:
            return optionValue(name, text, text=True)
        except StudyError as e:
            raise argparse.ArgumentTypeError(str(e)) from None
    return {'type': parse, 'default': p.default, 'metavar': 'N' if p.unit == '-' else p.unit.upper(),
            'help': '%s [%s] (%s%s)' % (p.doc, p.unit, p.allowed, '' if p.default is None else '; default %g' % p.default)}


def addArguments(parser, *names):
    """The options `names` on an argparse parser, as flag() names them (and SHORT)."""
    for name in names:
        parser.add_argument(flag(name), *[SHORT[name]] if name in SHORT else [], **argument(name))


def measuredCurve(text):
    """An argparse type for --curve COLUMN=PATH: a column of cycles.csv and the measured curve it is held against."""
    column, sep, path = text.partition('=')
    if not sep or not column or not path:
        raise argparse.ArgumentTypeError('%r; allowed: COLUMN=PATH, a column of cycles.csv and a measured curve' % text)
    return column, path


def cycleNumber(text):
    """An argparse type for a cycle number of cycles.csv (--at N ...): an integer from 1."""
    if not text.isdigit() or int(text) < 1:
        raise argparse.ArgumentTypeError('%r; allowed: a cycle number from 1' % text)
    return int(text)
