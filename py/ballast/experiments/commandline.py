"""What every experiment's command line shares: a ``--name value`` option per declared parameter (no
abbreviations), negative numbers as values, the yade-batch row read by the study's table reader, and
everything checked once by the experiment's Parameters (text=True) before any work."""
import os
import re

_NUMBER = re.compile(r'^-(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$|^-(inf|nan)$', re.IGNORECASE)


def metavar(p):
    if p.unit == 'path':
        return 'PATH'
    return 'V' if p.unit == '-' else p.unit.upper().replace(' ', '').replace('^', '')


def addParameters(ap, params):
    """An option --name per parameter, its help from the declaration (doc, unit, range, default)."""
    for name, p in params.items():
        ap.add_argument('--' + name, default=None, metavar=metavar(p),
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
    """Under yade-batch (YADE_BATCH=table:line): the row's raw cells (ballast.study.table.tableRow), then
    YADE's readParamsFromTable sets O.tags (description, d.id) as yade-batch does. Else {}."""
    from yade import utils
    if not utils.runningInBatch():
        return {}
    from ..study.table import tableRow
    tableFile, line = os.environ['YADE_BATCH'].split(':')[:2]
    cells = tableRow(tableFile, int(line), declaration)
    utils.readParamsFromTable(noTableOk=True, **{k: p.default for k, p in declaration.params.items()})
    return cells


def readParams(ap, argv, declaration):
    """defaults <- yade-batch row <- command line, checked once (ParamError names a bad one)."""
    values = tableValues(declaration)
    values.update({k: v for k, v in vars(ap.parse_args(joinNegativeValues(argv))).items()
                   if v is not None and k in declaration.params})
    return declaration.check(values, text=True)
