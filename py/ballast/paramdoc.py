"""docs/parameters.md, generated from the declarations (``python3 -m ballast.paramdoc > docs/parameters.md``):
every parameter of the engines, the oedometer and the studies with its unit, allowed range and default,
and the bounds the oedometer checks between parameters. tests/python/test_paramdoc.py keeps the page in
step with the code. Needs no YADE."""
from .oedometer import parameters as oedometer
from .params import ABRASION, CRUSH, PERIODIC
from .study.options import OPTIONS


def _cell(text):
    return str(text).replace('|', '\\|').replace('\n', ' ')


def table(params):
    rows = ['| parameter | unit | allowed | default | meaning |', '|---|---|---|---|---|']
    for name, p in params.items():
        default = 'required' if p.default is None else '`%r`' % (p.default,)
        rows.append('| `%s` | %s | %s | %s | %s |' % (name, _cell(p.unit), _cell(p.allowed), default, _cell(p.doc)))
    return '\n'.join(rows)


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
        '## The oedometer (`Oedometer(...)`, `--name value`, table columns)', table(oedometer.PARAMS),
        '## Bounds between the oedometer\'s parameters',
        '\n'.join([
            '* `dMin` < `dMax` < `diameter` / 2, `dMax` < `height`, `rMin` <= `dMax` / 2, `Fmin` < `Fmax`, '
            '`prepYoung` <= `young`.',
            '* The run must end: `cycles` / `f` / dt <= %.0e time steps, dt = `dtSafety` x (`dMin` / 2) '
            'sqrt(`density` / `young`) (YADE\'s PWaveTimeStep of the smallest grain at the start).'
            % oedometer.MAX_LOADING_STEPS,
            '* A cycle spans at least %d time steps: 1 / `f` >= %d dt.' % (oedometer.MIN_STEPS_PER_CYCLE,
                                                                         oedometer.MIN_STEPS_PER_CYCLE),
            '* `Fmax` carried by one steel contact of the smallest grain overlaps it by at most %g of its '
            'radius (linear law: u = F / kn, kn = 2 E r Es r / (E r + Es r); Hertz: u = (F / kno)^(2/3), '
            'kno = 4/3 E* sqrt(r / 2)).' % oedometer.MAX_OVERLAP_RATIO,
            '* `results` and the packing store (`packingDir`, default `<results>/packings`) are created and '
            'written to before the preparation.']),
        '## Study options (`scripts/study.py`)', table(OPTIONS),
    ]) + '\n'


if __name__ == '__main__':
    print(page(), end='')
