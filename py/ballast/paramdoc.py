"""docs/parameters.md, generated from the declarations (``python3 -m ballast.paramdoc > docs/parameters.md``):
every parameter of the engines, of every experiment (ballast.experiments) and of the studies with its unit,
allowed range and default, and the bounds each experiment checks between its parameters. tests/python/test_paramdoc.py keeps the page in
step with the code. Needs no YADE."""
from . import experiments
from .engineparams import ABRASION, CRUSH, PERIODIC
from .study.options import OPTIONS


def _cell(text):
    return str(text).replace('|', '\\|').replace('\n', ' ')


def table(params):
    rows = ['| parameter | unit | allowed | default | meaning |', '|---|---|---|---|---|']
    for name, p in params.items():
        default = 'required' if p.default is None else '`%r`' % (p.default,)
        rows.append('| `%s` | %s | %s | %s | %s |' % (name, _cell(p.unit), _cell(p.allowed), default, _cell(p.doc)))
    return '\n'.join(rows)


def experimentSections():
    """A section per experiment, found by its folder: its parameters and the bounds it checks between them."""
    out = []
    for name in experiments.names():
        d = experiments.declaration(name)
        out += ['## %s' % d.title, table(d.params)]
        if d.bounds:
            out += ['## Bounds between the %s\'s parameters' % d.title.split(' (')[0].replace('The ', ''),
                    '\n'.join('* ' + b for b in d.bounds)]
    return out


def page():
    return '\n\n'.join([
        '# Parameters and their bounds',
        'Generated from the declarations by `python3 -m ballast.paramdoc` (do not edit by hand; '
        'tests/python/test_paramdoc.py fails when it is out of date). Every value is checked where it is '
        'declared: when an engine or an experiment is built, on every later set, and for the command line '
        'and the study tables before any work (exit status 2 and one line naming the parameter, the value '
        'and what is allowed).',
        '## BallastCrushEngine', table(CRUSH),
        '## BallastAbrasionEngine', table(ABRASION),
        '## Periodic settings of both engines (YADE\'s PeriodicEngine)',
        'Without any period an engine checks every step; periods that are all 0 are refused (the engine '
        'would never check).',
        table(PERIODIC),
        *experimentSections(),
        '## Study options (`scripts/study.py`)', table(OPTIONS),
    ]) + '\n'


if __name__ == '__main__':
    print(page(), end='')
