"""A study's tables, tests and figures, as scripts/aggregate.py writes them for any experiment, driven by its
declaration (docs/studies.md, "Aggregating"):

    runs.csv, stats.csv   the finished runs and their statistics per value (ballast.study.aggregate): the
                          declaration's results and statistics
    test.json             does the parameter change the response (the declaration's: the oedometer's displacement
                          at peak, the box's settlement)? Kruskal-Wallis across its values, with the difference of
                          two means the runs could have detected; under "blocked" the same question asked within
                          each realization (Friedman, seeds as blocks; Page's trend test), and under each key the
                          declaration's `tested` names the same within seeds for another result (the oedometer's
                          "onset" and "network") (ballast.analysis.effects)
    response.png          the response against the parameter; fd_curves.png, checks.png where the runs have an
                          F-delta curve, a per-check log (ballast.analysis.figures)

The studied parameter is the column of the table that varies besides the seed (or the one named).
Runs not finished are left out and listed.
"""
import json
import os

from ..study.aggregate import count, label, stats, writeCsv
from ..study.data import StudyData
from ..study.options import StudyError
from .effects import blockedTest, effectTest, unitOf
from .figures import plots, shown

COLUMNS = 4   # the printed table: the response and the first statistics after it, in the declaration's order


def amount(data, quantity, value):
    """'12.3 mm': a value [declared unit] of a result in the unit it is printed in."""
    unit, k = shown(unitOf(data, quantity))
    return '%.3g%s' % (value * k, '' if unit == '-' else ' ' + unit)


def columns(data):
    """The results of the printed table: the response, then the declaration's statistics some run has, COLUMNS in
    all."""
    first = [data.response] if data.response else []
    return (first + [k for k in data.declaration.statistics if k not in first and
                     any(r.summary.get(k) is not None for r in data.runs)])[:COLUMNS]


def tests(data):
    """test.json of `data` (StudyData): effectTest of the response, with blocked (its blockedTest) and the
    blockedTest of each result the declaration's `tested` names, under its key; None where effectTest has no test
    (no response, or fewer than two values of two runs each)."""
    test = effectTest(data) if data.response else None
    if test is None:
        return None
    alpha, power = test['alpha'], test['power']

    def blocked(quantity=None):
        # within seeds a seed is one realization at every value: a study whose other parameters vary too (two runs
        # of a seed at one value) has no such blocks; the test across values above stands
        try:
            return blockedTest(data, quantity, alpha, power)
        except ValueError as e:
            return {'test': 'Friedman', 'skipped': str(e)}
    return dict(test, blocked=blocked(), **{key: blocked(name) for key, (name, _) in data.declaration.tested.items()})


def trend(t):
    """'; Page trend: rise, p = 0.01' of a within-seed test with a trend ('' without)."""
    return '; Page trend: %s, p = %.3g' % (t['trend'], t['pTrend']) if 'trend' in t else ''


def table(data):
    """The printed table's lines: per value of the parameter, n and the mean +- sd of columns(data)."""
    shownCols = [(k, shown(unitOf(data, k))) for k in columns(data)]
    lines = ['%-12s %3s' % (data.param, 'n') + ''.join('  %24s' % ('%s [%s]' % (k, u))[:24] for k, (u, _) in shownCols)]
    for st in stats(data):
        lines.append('%-12s %3d' % (label(st['value']), st['n']) + ''.join(
            '  %11.4g +- %-9.3g' % (st[k + '_mean'] * f, st[k + '_std'] * f) for k, (_, f) in shownCols))
    return lines


def say(data, test):
    """The lines the report prints on the tests of test.json."""
    if test is None:
        return []
    r = data.response
    detectable = 'detectableDifference [%s]' % unitOf(data, r)
    lines = ['Kruskal-Wallis across %s: H = %.3g, p = %.3g (%d groups, %d runs); a difference of two means of %s would '
             'have been found with probability %g at the %g level' % (
                 data.param, test['H'], test['p'], test['groups'], test['runs'],
                 amount(data, r, test[detectable]),
                 test['power'], test['alpha'])]
    blocked = test['blocked']
    if blocked is not None and 'skipped' in blocked:
        lines.append('Friedman across %s within seeds: not made (%s)' % (data.param, blocked['skipped']))
    elif blocked is not None:
        lines.append('Friedman across %s within seeds: chi2 = %.3g, p = %.3g (%d seeds complete); detectable difference '
                     '%s%s' % (data.param, blocked['chi2'], blocked['p'], blocked['seeds'],
                               amount(data, r, blocked[detectable]), trend(blocked)))
    for key, (_, words) in data.declaration.tested.items():
        t = test[key]
        if t is not None and 'skipped' not in t:
            lines.append('%s, within seeds: Friedman p = %.3g (%d seeds)%s' % (words, t['p'], t['seeds'], trend(t)))
    return lines


def aggregate(path, param=None, outDir=None, xlog='auto', figures=True, experiment=None):
    """Aggregate the study folder `path` into outDir (default <path>/aggregate): the CSV tables, the
    tests, the figures unless figures=False, and a report on standard output. experiment: its name or
    Declaration (default: study.json's). Returns the StudyData."""
    outDir = outDir or os.path.join(path, 'aggregate')
    if os.path.exists(outDir) and not os.path.isdir(outDir):
        raise StudyError('--out: %s exists and is not a directory' % outDir)
    data = StudyData(path, param, experiment)
    os.makedirs(outDir, exist_ok=True)
    runsCsv, statsCsv = writeCsv(data, outDir)
    print('%s: %s of %d rows (%s); studied parameter %s (%s), %s' % (
        data.dir, count(len(data.runs), 'finished run'), len(data.info['rows']), data.declaration.name, data.param,
        count(len(data.values), 'value'), count(len(data.seeds), 'realization')))
    shas = data.codeVersions()
    if len(shas) > 1:
        print('warning: the runs were made by %d versions of the code (sha1 %s; None: runs without a code sha1)' % (
            len(shas), ', '.join(sorted(str(x)[:10] for x in shas))))
    if data.missing:
        print('not finished (left out): %d: %s%s' % (len(data.missing), ', '.join(data.missing[:8]),
                                                     ' ...' if len(data.missing) > 8 else ''))
    print('\n'.join(table(data)))
    test = tests(data)
    if test is not None:
        with open(os.path.join(outDir, 'test.json'), 'w') as fh:
            json.dump(test, fh, indent=1)
    for line in say(data, test):
        print(line)
    print('tables: %s, %s' % (runsCsv, statsCsv))
    if figures:
        print('figures: %s' % ', '.join(plots(data, outDir, xlog)))
    return data
