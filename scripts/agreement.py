#!/usr/bin/python3
"""Does an option change the answer? A study's runs against a reference study's on the same seeds, on what
cycles.csv says after chosen cycles (ballast.analysis.agreement: the paired t test of a bias and the test of
equivalence within the seed scatter):

    scripts/agreement.py docs/studies/qs-box-scaled --reference docs/studies/qs-box-true
        --quantities settlement resilient tilt --at 1 2 5 --out docs/studies/qs-box-scaled

writes agreement-pairs.csv (per quantity, cycle and seed both values and their difference) and agreement.json
(per quantity and cycle the test and its verdict), and prints the verdicts. One study whose table holds both the
option's rows and the reference's is split by a parameter's values:

    scripts/agreement.py 'docs/studies/qs-box-crush[quasiStatic=1e-3]' \
        --reference 'docs/studies/qs-box-crush[quasiStatic=0]' --quantities settlement crushes --at 1 \
        --out docs/studies/qs-box-crush"""
import argparse
import json
import os
import sys

from ballast.analysis import agreement
from ballast.study.options import StudyError, cycleNumber


def alphaLevel(text):
    """--alpha's value: a level in (0, 0.5)."""
    try:
        value = float(text)
    except ValueError:
        value = float('nan')
    if not 0 < value < 0.5:
        raise argparse.ArgumentTypeError('%r; allowed: a level above 0 and below 0.5, e.g. 0.05' % text)
    return value



def main(argv=None):
    ap = argparse.ArgumentParser(prog='scripts/agreement.py', description=__doc__.split('\n\n')[0])
    ap.add_argument('study', help='the study (or its records) run with the option; PATH[NAME=VALUE ...]: its runs '
                                  'with those parameter values')
    ap.add_argument('--reference', required=True, help='the study (or its records) run without it, on the same '
                                                       'seeds; PATH[NAME=VALUE ...] as for study')
    ap.add_argument('--quantities', nargs='+', default=['settlement', 'resilient'], metavar='COLUMN',
                    help='columns of cycles.csv compared (default: settlement resilient)')
    ap.add_argument('--at', type=cycleNumber, nargs='+', default=[1, 2, 5], metavar='N', help='cycles (default: 1 2 5)')
    ap.add_argument('--alpha', type=alphaLevel, default=0.05, help='the tests\' level (default 0.05)')
    ap.add_argument('--out', required=True, help='where agreement-pairs.csv and agreement.json go')
    a = ap.parse_args(argv)
    try:
        (path, study, by), (refPath, reference, refBy) = (agreement.selection(x) for x in (a.study, a.reference))
        if by != refBy:
            raise ValueError('agreement: %s and %s select runs by different parameters (%s; %s): name the same '
                             'ones, or none' % (a.study, a.reference, ' '.join(by) or 'none',
                                                ' '.join(refBy) or 'none'))
        frame = agreement.values(list(dict.fromkeys([path, refPath])), a.quantities, a.at, by)
        pairs, verdicts = agreement.compare(frame, study, reference, a.quantities, a.at, a.alpha)
    except (StudyError, ValueError) as e:
        print('agreement.py: %s' % e, file=sys.stderr)
        return 2
    os.makedirs(a.out, exist_ok=True)
    pairs.to_csv(os.path.join(a.out, 'agreement-pairs.csv'), index=False, float_format='%.9g')
    with open(os.path.join(a.out, 'agreement.json'), 'w') as fh:
        json.dump({'study': a.study, 'reference': a.reference, 'verdicts': verdicts}, fh, indent=1)
    for v in verdicts:
        print('%-10s N=%-3d %d seeds: reference %.4g, difference %+.3g (%+.0f %%), seed scatter %.3g, '
              'difference sd %.3g, p %s: %s' % (
                  v['quantity'], v['cycle'], v['seeds'], v['referenceMean'], v['meanDifference'],
                  100 * v['relativeDifference'], v.get('seedStd', float('nan')), v.get('differenceStd', float('nan')),
                  '%.3f' % v['p'] if 'p' in v else '-', v['verdict'] or 'one seed: no test'))
    return 0


if __name__ == '__main__':
    sys.exit(main())
