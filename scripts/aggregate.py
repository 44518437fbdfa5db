#!/usr/bin/python3
"""Aggregate a study of any experiment run by scripts/study.py into tables, tests and figures, as its declaration says
(ballast.analysis.report).

    scripts/aggregate.py results/studies/frequency            -> results/studies/frequency/aggregate/
    scripts/aggregate.py results/studies/Tc --param Tc --out docs/figures/Tc
"""
import argparse
import sys

from ballast.analysis.report import __doc__ as TABLES, aggregate
from ballast.study import StudyError


def main(argv=None):
    ap = argparse.ArgumentParser(prog='scripts/aggregate.py', description=__doc__ + '\n' + TABLES, epilog='See docs/studies.md.',
                                 allow_abbrev=False, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('study', metavar='STUDY', help='study directory written by scripts/study.py run (its --out)')
    ap.add_argument('--param', help='the studied column (default: the only one that varies besides seed)')
    ap.add_argument('--out', metavar='DIR', help='where to write (default STUDY/aggregate)')
    ap.add_argument('--xlog', choices=('auto', 'yes', 'no'), default='auto', help='log axis for the parameter in response.png')
    ap.add_argument('--no-plots', action='store_true', help='only the CSV tables')
    a = ap.parse_args(argv)
    try:
        aggregate(a.study, a.param, a.out, a.xlog, figures=not a.no_plots)
    except StudyError as e:
        print('aggregate.py: %s' % e, file=sys.stderr)
        return 2
    return 0


if __name__ == '__main__':
    sys.exit(main())
