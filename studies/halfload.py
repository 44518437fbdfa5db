#!/usr/bin/python3
"""The force network at half the peak load against the loading frequency (ballast.analysis.halfload;
docs/studies.md, Fig. 4): realizations loaded by eq. 8 only to Fmax/2, before any crush.

The sweep is a study of the oedometer with stopAt = 0.25 (studies/halfload.table), run, resumed and
recorded by scripts/study.py like every study:

    scripts/study.py run studies/halfload.table -j 1 --records docs/studies/halfload/records
    studies/halfload.py report docs/studies/halfload/records --out docs/studies/halfload

`report` reads a study folder (a study directory or its records) or the sweep's CSV of before
(docs/studies/halfload/runs.csv, 120 runs) and writes test.json and halfload.png; from a study
folder also runs.csv, the sweep's table (a row per run: seed, f, damping, the ratio, the state there).
"""
import argparse
import json
import os
import sys

from ballast.analysis import halfload
from ballast.study import StudyError


def main(argv=None):
    ap = argparse.ArgumentParser(prog='studies/halfload.py', description=__doc__, allow_abbrev=False,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest='command', metavar='COMMAND', required=True)
    rp = sub.add_parser('report', help='the tests and the figure of a sweep')
    rp.add_argument('sweep', metavar='STUDY|CSV', help="a study folder of studies/halfload.table, or the sweep's CSV")
    rp.add_argument('--out', required=True, metavar='DIR', help='where to write test.json and halfload.png (and runs.csv)')
    a = ap.parse_args(argv)
    try:
        runs = halfload.read(a.sweep)
    except (StudyError, ValueError, KeyError, OSError) as e:
        print('halfload.py: %s' % e, file=sys.stderr)
        return 2
    os.makedirs(a.out, exist_ok=True)
    if os.path.isdir(a.sweep):
        print(halfload.write(runs, os.path.join(a.out, 'runs.csv')))
    summary = halfload.summarize(runs)
    tests = halfload.tests(summary)
    for d, t in tests.items():
        print('damping %s: mean sigma/f_t at Fmax/2 per f %s: %s' % (d, t['f'], ', '.join('%.3f' % x for x in t['ratioMean'])))
        if 'pTrend' in t:
            print('  within %d seeds: Friedman p = %.3g, Page trend %s p = %.3g' % (t['seeds'], t['p'], t['trend'], t['pTrend']))
        r = t['riseAgainstBase']
        if r:
            print('  rise from the lowest to the highest f, at damping %g minus here: %.3f +- %.3f (%d seeds, Wilcoxon p = %.3g)' % (
                r['baseDamping'], r['meanDifference'], r['sem'], r['seeds'], r['pWilcoxon']))
    with open(os.path.join(a.out, 'test.json'), 'w') as fh:
        json.dump(tests, fh, indent=1)
    print(halfload.figure(summary, os.path.join(a.out, 'halfload.png')))
    return 0


if __name__ == '__main__':
    sys.exit(main())
