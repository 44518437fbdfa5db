#!/usr/bin/python3
"""Why delta depends on the crushing period: the T_c study beside its controlled variants
(ballast.analysis.mechanisms; issue 14, docs/studies.md).

    studies/tc_mechanisms.py docs/studies/Tc-4Hz docs/studies/Tc-variants --out docs/studies/Tc-variants
writes mechanisms.csv (per variant and T_c: n, mean, std, standard error of delta, mean crushes, the share of
crushes after the peak of the applied force, the largest sigma/f_t of a grain when it crushed),
trends.csv (per variant, the change of delta from one T_c to the next beside the baseline's on the same seeds,
and the difference of the two: does the variant keep the trend?) and
mechanisms.png.
"""
import argparse
import csv
import os
import sys

from ballast.analysis import mechanisms
from ballast.study import StudyError


def writeCsv(rows, path):
    with open(path, 'w', newline='') as fh:
        w = csv.DictWriter(fh, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    return path


def main(argv=None):
    ap = argparse.ArgumentParser(prog='studies/tc_mechanisms.py', description=__doc__, allow_abbrev=False,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('studies', nargs='+', metavar='STUDY', help='study directories or records (the baseline and the variants)')
    ap.add_argument('--out', metavar='DIR', required=True, help='where to write')
    a = ap.parse_args(argv)
    try:
        rows = mechanisms.collect(*a.studies)
    except StudyError as e:
        print('tc_mechanisms.py: %s' % e, file=sys.stderr)
        return 2
    os.makedirs(a.out, exist_ok=True)
    table = mechanisms.table(rows)
    for r in table:
        print('%-28s Tc %-9g n %3d  delta %6.1f +- %5.1f mm  crushed %6.1f  after the peak %4.0f %%  largest ratio %4.2f' % (
            r['variant'], r['Tc'], r['n'], 1e3 * r['delta_mean'], 1e3 * r['delta_std'], r['nCrushed_mean'],
            100 * r['afterPeak_mean'], r['ratioAtCrushMax_mean']))
    print(writeCsv(table, os.path.join(a.out, 'mechanisms.csv')))
    tr = mechanisms.trends(rows)
    for r in tr:
        print('%-28s Tc %-9g -> %-9g n %3d  change %6.1f +- %4.1f mm  baseline %6.1f +- %4.1f mm  effect %6.1f +- %4.1f mm' % (
            r['variant'], r['Tc0'], r['Tc1'], r['n'], *(1e3 * r[k] for k in (
                'change', 'sem', 'baselineChange', 'baselineSem', 'effect', 'effectSem'))))
    print(writeCsv(tr, os.path.join(a.out, 'trends.csv')))
    print(mechanisms.figure(rows, os.path.join(a.out, 'mechanisms.png')))
    return 0


if __name__ == '__main__':
    sys.exit(main())
