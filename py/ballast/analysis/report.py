"""A study's tables, tests and figures, as scripts/aggregate.py writes them (docs/studies.md,
"Aggregating"):

    runs.csv, stats.csv   the finished runs and their statistics per value (ballast.study.aggregate)
    test.json             does the parameter change the response (the displacement at peak)?
                          Kruskal-Wallis across its values, with the difference of two means the runs
                          could have detected; under "blocked" the same question asked within each
                          realization (Friedman, seeds as blocks; Page's trend test), under "onset" for
                          the applied force at the first crush, under "network" for the largest
                          sigma/f_t at half the peak load before any crush (ballast.analysis.effects)
    fd_curves.png, delta_peak.png, checks.png   the figures (ballast.analysis.figures)

The studied parameter is the column of the table that varies besides the seed (or the one named).
Runs not finished are left out and listed.
"""
import json
import os

from ..study.aggregate import count, label, stats, writeCsv
from ..study.data import StudyData
from ..study.options import StudyError
from .effects import blockedTest, effectTest
from .figures import plots


def tests(data):
    """test.json of `data` (StudyData): effectTest with blocked, onset and network (blockedTest of the
    response, of the applied force at the first crush and of sigma/f_t at Fmax/2); None where
    effectTest has no test."""
    test = effectTest(data)
    if test is None:
        return None
    alpha, power = test['alpha'], test['power']
    return dict(test, blocked=blockedTest(data, alpha=alpha, power=power),
                onset=blockedTest(data, 'forceAtFirstCrush', alpha, power),
                network=blockedTest(data, 'stressRatioAtHalfLoad', alpha, power))


def trend(t):
    """'; Page trend: rise, p = 0.01' of a within-seed test with a trend ('' without)."""
    return '; Page trend: %s, p = %.3g' % (t['trend'], t['pTrend']) if 'trend' in t else ''


def aggregate(path, param=None, outDir=None, xlog='auto', figures=True):
    """Aggregate the study folder `path` into outDir (default <path>/aggregate): the CSV tables, the
    tests, the figures unless figures=False, and a report on standard output. Returns the StudyData."""
    outDir = outDir or os.path.join(path, 'aggregate')
    if os.path.exists(outDir) and not os.path.isdir(outDir):
        raise StudyError('--out: %s exists and is not a directory' % outDir)
    data = StudyData(path, param)
    os.makedirs(outDir, exist_ok=True)
    runsCsv, statsCsv = writeCsv(data, outDir)
    print('%s: %s of %d rows; studied parameter %s (%s), %s' % (
        data.dir, count(len(data.runs), 'finished run'), len(data.info['rows']), data.param,
        count(len(data.values), 'value'), count(len(data.seeds), 'realization')))
    shas = data.codeVersions()
    if len(shas) > 1:
        print('warning: the runs were made by %d versions of the code (sha1 %s; None: runs without a code sha1)' % (
            len(shas), ', '.join(sorted(str(x)[:10] for x in shas))))
    if data.missing:
        print('not finished (left out): %d: %s%s' % (len(data.missing), ', '.join(data.missing[:8]),
                                                     ' ...' if len(data.missing) > 8 else ''))
    print('%-12s %3s  %22s  %22s  %16s  %20s' % (data.param, 'n', 'delta at peak [mm]', 'delta max [mm]', 'crushed',
                                                  'F at 1st crush [kN]'))
    for st in stats(data):
        print('%-12s %3d  %10.2f +- %8.2f  %10.2f +- %8.2f  %6.1f +- %5.1f  %8.0f +- %7.0f' % (
            label(st['value']), st['n'], st[data.response + '_mean'] * 1e3, st[data.response + '_std'] * 1e3,
            st['deltaMax_mean'] * 1e3, st['deltaMax_std'] * 1e3, st['nCrushed_mean'], st['nCrushed_std'],
            st['forceAtFirstCrush_mean'] / 1e3, st['forceAtFirstCrush_std'] / 1e3))
    test = tests(data)
    if test is not None:
        with open(os.path.join(outDir, 'test.json'), 'w') as fh:
            json.dump(test, fh, indent=1)
        print('Kruskal-Wallis across %s: H = %.3g, p = %.3g (%d groups, %d runs); a difference of two means of %.1f mm '
              'would have been found with probability %g at the %g level' % (
                  data.param, test['H'], test['p'], test['groups'], test['runs'], test['detectableDifference [m]'] * 1e3,
                  test['power'], test['alpha']))
        blocked = test['blocked']
        if blocked is not None:
            print('Friedman across %s within seeds: chi2 = %.3g, p = %.3g (%d seeds complete); detectable difference %.1f mm%s' % (
                data.param, blocked['chi2'], blocked['p'], blocked['seeds'], blocked['detectableDifference [m]'] * 1e3,
                trend(blocked)))
        for what, t in (('applied force at the first crush', test['onset']),
                        ('largest sigma/f_t at Fmax/2 before a crush', test['network'])):
            if t is not None:
                print('%s, within seeds: Friedman p = %.3g (%d seeds)%s' % (what, t['p'], t['seeds'], trend(t)))
    print('tables: %s, %s' % (runsCsv, statsCsv))
    if figures:
        print('figures: %s' % ', '.join(plots(data, outDir, xlog)))
    return data
