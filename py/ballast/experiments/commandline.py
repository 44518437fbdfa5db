"""What every experiment's command line shares: a ``--name value`` option per declared parameter (in full,
each once), negative numbers as values, argparse's errors in one line naming the option and what is
allowed, the yade-batch row read by the table reader (ballast.tables), and everything checked once by the
experiment's Parameters (text=True: numbers in decimal, flags 0 or 1, as ballast.params reads all text)
before any work. A refusal is one line on stderr and exit status 2."""
import argparse
import difflib
import os
import re
import sys

from ..params import ParamError

_NUMBER = re.compile(r'^-(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$|^-(inf|nan)$', re.IGNORECASE)


def metavar(p):
    if p.unit == 'path':
        return 'PATH'
    return 'V' if p.unit == '-' else p.unit.upper().replace(' ', '').replace('^', '')


class OneLineParser(argparse.ArgumentParser):
    """argparse whose errors are one line naming the option and what is allowed (not the usage), exit 2.
    script: the name the errors start with; params: the declarations the messages quote."""

    def __init__(self, script, params, **kw):
        argparse.ArgumentParser.__init__(self, allow_abbrev=False, **kw)
        self.script, self.params = script, params

    def error(self, message):
        self.refuse(explain(message, self.params))

    def refuse(self, words):
        """The one line of a refusal on stderr, then exit status 2."""
        sys.stderr.write('%s: %s\n' % (self.script, words))
        sys.exit(2)


def explain(message, params):
    """argparse's message in the words of the parameters."""
    m = re.match(r'unrecognized arguments: (\S+)', message)
    if m:
        name = m.group(1).split('=')[0]
        lower = {k.lower(): k for k in params}
        close = [lower[k] for k in difflib.get_close_matches(name.lstrip('-').lower(), list(lower), n=3, cutoff=0.5)]
        return 'unknown option %s: the options are the parameters of --help (names in full)%s' % (
            name, '; did you mean %s?' % ', '.join('--' + c for c in close) if close else '')
    m = re.match(r'argument --(\w+): expected one argument', message)
    if m and m.group(1) in params:
        p = params[m.group(1)]
        return 'option --%s needs a value: %s [%s]' % (m.group(1), p.allowed, p.unit)
    return message


class Once(argparse.Action):
    """An option given once: a second --f is refused (argparse would keep the last silently)."""

    def __call__(self, parser, namespace, values, option_string=None):
        if getattr(namespace, self.dest) is not None:
            parser.error('option %s given twice (%s and %s): give it once' % (option_string, getattr(namespace, self.dest),
                                                                             values))
        setattr(namespace, self.dest, values)


def addParameters(ap, params):
    """An option --name per parameter, given at most once, its help from the declaration."""
    for name, p in params.items():
        ap.add_argument('--' + name, default=None, metavar=metavar(p), action=Once,
                        help=('%s [%s] (%s; default %r)' % (p.doc, p.unit, p.allowed, p.default)).replace('%', '%%'))
    return ap


def joinNegativeValues(argv):
    """`--Fmax -1e6` as `--Fmax=-1e6`: argparse takes '-1e6' for an option, and the value then reaches
    the parameter's check, which names what is allowed."""
    out, i = [], 0
    while i < len(argv):
        a = argv[i]
        if a.startswith('--') and '=' not in a and i + 1 < len(argv) and _NUMBER.match(argv[i + 1]):
            out.append('%s=%s' % (a, argv[i + 1]))
            i += 2
        else:
            out.append(a)
            i += 1
    return out


def tableValues(declaration):
    """Under yade-batch (YADE_BATCH=table:line): the row's raw cells (ballast.tables.tableRow: every
    column a parameter, every cell readable, named otherwise), then YADE's readParamsFromTable sets O.tags
    (description, d.id) as yade-batch does. Else {}."""
    if 'YADE_BATCH' not in os.environ:   # YADE's utils.runningInBatch(), without YADE: a command line reads without it
        return {}
    from ..tables import tableRow
    tableFile, line = os.environ['YADE_BATCH'].split(':')[:2]
    cells = tableRow(tableFile, int(line), declaration)   # a bad column or cell is named before YADE is asked
    from yade import utils
    utils.readParamsFromTable(noTableOk=True, **{k: p.default for k, p in declaration.params.items()})
    return cells


def parse(ap, argv):
    """The options given, as {dest: text} (None for those not given)."""
    return vars(ap.parse_args(joinNegativeValues(argv)))


def readParams(ap, argv, declaration):
    """defaults <- yade-batch row <- command line, checked once by the declaration (text=True). A bad value,
    option or table: one line naming it on stderr, exit status 2 (ap: a OneLineParser)."""
    from ..tables import TableError
    try:
        values = tableValues(declaration)
        values.update({k: v for k, v in parse(ap, argv).items() if v is not None and k in declaration.params})
        return declaration.check(values, text=True)
    except ParamError as e:
        ap.refuse('bad parameter %s: %s' % (e.name, e))
    except TableError as e:  # a yade-batch table YADE would misread
        ap.refuse('bad table: %s' % e)


def experiment(ap, argv, declaration, experimentClass):
    """The experiment of a command line: its parameters read and checked (readParams), built by
    experimentClass() (a callable giving the class: its module needs YADE) and its outputs checked writable,
    before any work. A bad value: one line naming the parameter, exit status 2."""
    params = readParams(ap, argv, declaration)
    try:
        exp = experimentClass()(parameters=params)   # checked once, by readParams
        exp.checkOutputs()
    except ParamError as e:
        ap.refuse('bad parameter %s: %s' % (e.name, e))
    return exp


def run(ap, exp):
    """exp.run(), with what it finds wrong in its input before any work (a state to go on from that is damaged, of
    another version or of another physics) refused in one line, exit status 2, as a bad parameter is. Returns the
    summary."""
    from ..runtime import StateFormatError
    from .rundir import StateFileError
    try:
        return exp.run()
    except (StateFileError, StateFormatError) as e:
        ap.refuse('bad state: %s' % e)
    except ParamError as e:
        ap.refuse('bad parameter %s: %s' % (e.name, e))


class Script:
    """The command line of an experiment whose script is one run (the box test, the triaxial test):
    ``yade -n -x scripts/<script> [--name value ...]``, every parameter by name (or a yade-batch row), checked before
    any work. experimentClass: 'module:Class', imported when the run starts (the module needs YADE)."""

    def __init__(self, declaration, script, description, experimentClass):
        self.declaration, self.script, self.description = declaration, script, description
        self.experimentClass = experimentClass
        self.prog = 'yade -n -x scripts/' + script

    def parser(self):
        ap = OneLineParser(self.script, self.declaration.params, prog=self.prog, description=self.description)
        return addParameters(ap, self.declaration.params)

    def readParams(self, argv):
        """defaults <- yade-batch table row <- command line, all checked (readParams)."""
        return readParams(self.parser(), argv, self.declaration)

    def main(self, argv=None):
        import importlib
        from yade import utils
        argv = sys.argv[1:] if argv is None else argv
        module, name = self.experimentClass.split(':')
        ap = self.parser()
        run(ap, experiment(ap, argv, self.declaration, lambda: getattr(importlib.import_module(module), name)))
        utils.waitIfBatch()
        return 0
