#!/usr/bin/python3
"""The fast options against the paper's settings (ballast.analysis.options; docs/performance.md):

    studies/fast_options.py docs/studies/fast-options --out docs/studies/fast-options

The study's runs of each option (ballast.analysis.options.OPTIONS) are paired by seed with the runs of
the paper's settings at the same f and T_c: the same study's, or those of --reference (an older study's
records); writes comparison.json, comparison.md (the table of docs/performance.md) and options.png."""
import argparse
import os
import sys

from ballast.analysis import options
from ballast.study.options import StudyError


def main(argv=None):
    ap = argparse.ArgumentParser(prog='studies/fast_options.py', description=__doc__.split('\n\n')[0])
    ap.add_argument('study', help='the study (or its records) with the options')
    ap.add_argument('--reference', help="the study (or its records) with the paper's settings (default: STUDY's own)")
    ap.add_argument('--f', type=float, default=4.0, help='loading frequency of both [Hz] (default 4)')
    ap.add_argument('--Tc', type=float, default=6.25e-4, help='crushing period of both [s] (default 6.25e-4)')
    ap.add_argument('--out', required=True, help='where comparison.json and options.png go')
    a = ap.parse_args(argv)
    try:
        ref = options.frame(a.reference or a.study, f=a.f, Tc=a.Tc, **options.PAPER)
        pairs, result = {}, {}
        for name, select in options.OPTIONS.items():
            opt = options.frame(a.study, f=a.f, Tc=a.Tc, **select)
            if len(opt):
                pairs[name] = (opt, ref)
                result[name] = options.compare(opt, ref)
    except (StudyError, ValueError, KeyError) as e:
        print('fast_options.py: %s' % e, file=sys.stderr)
        return 2
    options.write(result, a.out)
    for name, r in result.items():
        print('%-9s %2d seeds: delta %.1f mm (paper %.1f), difference %.1f mm [%.1f, %.1f], Wilcoxon p = %.3g, '
              'avalanching %.0f %% (paper %.0f %%), changed %s, CPU x%.2f, loading steps x%.2f' % (
                  name, r['n'], 1e3 * r['option']['mean'], 1e3 * r['reference']['mean'], 1e3 * r['meanDifference'],
                  1e3 * r['meanDifferenceLow'], 1e3 * r['meanDifferenceHigh'], r['pWilcoxon'],
                  100 * r['option']['avalanching'], 100 * r['reference']['avalanching'], r['changedClass'] or 'none',
                  r['cpuRatioMedian'], r.get('loadStepsRatioMedian', float('nan'))))
    print(options.figure(pairs, os.path.join(a.out, 'options.png')))
    return 0


if __name__ == '__main__':
    sys.exit(main())
