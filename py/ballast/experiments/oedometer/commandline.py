"""``yade scripts/oedometer.py``: the parameters from the command line (``--name value``) and from a
yade-batch table row (a column per name), every one checked before any work, then one realization."""
import argparse
import os
import re
import sys

from ...params import ParamError
from ...study.options import StudyError
from ...study.table import tableRow
from .declaration import DECLARATION
from .parameters import PARAMS, check

PROG = 'yade scripts/oedometer.py'


def _metavar(p):
    if p.unit == 'path':
        return 'PATH'
    return 'V' if p.unit == '-' else p.unit.upper().replace(' ', '').replace('^', '')


def parser():
    ap = argparse.ArgumentParser(prog=PROG, allow_abbrev=False, formatter_class=argparse.RawDescriptionHelpFormatter,
                                 description='One realization of the oedometric test of Dubina & Elias (sections 4-5). '
                                 'Every parameter can also be a yade-batch table column of the same name. '
                                 'See docs/oedometer.md.')
    for name, p in PARAMS.items():
        ap.add_argument('--' + name, default=None, metavar=_metavar(p),
                        help=('%s [%s] (%s; default %r)' % (p.doc, p.unit, p.allowed, p.default)).replace('%', '%%'))
    return ap


def tableValues():
    """The row of the yade-batch table (YADE_BATCH=table:line) as raw cells, read by the study's table reader
    (ballast.study.table.tableRow: every column a parameter, every cell readable, named otherwise); YADE's
    readParamsFromTable then sets O.tags (description, d.id) as under yade-batch."""
    from yade import utils
    if not utils.runningInBatch():
        return {}
    tableFile, line = os.environ['YADE_BATCH'].split(':')[:2]
    cells = tableRow(tableFile, int(line), DECLARATION)
    utils.readParamsFromTable(noTableOk=True, **{k: p.default for k, p in PARAMS.items()})
    return cells


_NUMBER = re.compile(r'^-(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$|^-(inf|nan)$', re.IGNORECASE)


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


def readParams(argv):
    """defaults <- yade-batch table row <- command line, all checked. argparse exits with status 2
    on names it does not know (no abbreviations)."""
    values = tableValues()
    values.update({k: v for k, v in vars(parser().parse_args(joinNegativeValues(argv))).items() if v is not None})
    return check(values, text=True)


def main(argv=None):
    """The command line: exit status 2 and a message naming the parameter on a bad value."""
    from yade import utils
    try:
        params = readParams(sys.argv[1:] if argv is None else argv)
        from .experiment import Oedometer
        run = Oedometer(parameters=params)  # checked once, by readParams
        run.checkOutputs()
    except ParamError as e:
        sys.stderr.write('oedometer.py: bad parameter %s: %s\n' % (e.name, e))
        sys.exit(2)
    except StudyError as e:  # a yade-batch table YADE would misread
        sys.stderr.write('oedometer.py: bad table: %s\n' % e)
        sys.exit(2)
    summary = run.run()
    utils.waitIfBatch()
    return run, summary
