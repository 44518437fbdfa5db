#!/usr/bin/python3
"""What a study's realizations say at chosen cycles, condition by condition (ballast.analysis.conditions): each
quantity of cycles.csv (with the jumped cycles' share), BBI and failures, per seed and over the seeds:

    scripts/conditions.py docs/studies/triax-predict --by confining qMax f \\
        --quantities axialStrain volumetricStrain --at 10 100 1000 10000 --out docs/studies/triax-predict

writes conditions-seeds.csv (a row per realization and cycle), conditions.csv (a row per condition and cycle: the
mean, smallest and largest over the seeds, the failures) and conditions.md (that table in Markdown, strains in %).
With --curve COLUMN=PATH (as scripts/curve_fit.py) a measured curve's value at each N stands beside its quantity: a
calibration's fit, seed by seed and over the seeds."""
import argparse
import os
import sys

from ballast.analysis import conditions
from ballast.experiments.triaxial.strains import CurveError
from ballast.study.options import StudyError, cycleNumber, measuredCurve


def main(argv=None):
    ap = argparse.ArgumentParser(prog='scripts/conditions.py', description=__doc__.split('\n\n')[0])
    ap.add_argument('studies', nargs='+', help='studies (or their records)')
    ap.add_argument('--by', nargs='+', required=True, metavar='NAME', help='the parameters that make a condition')
    ap.add_argument('--quantities', nargs='+', default=['axialStrain', 'volumetricStrain'], metavar='COLUMN',
                    help='columns of cycles.csv (default axialStrain volumetricStrain)')
    ap.add_argument('--at', type=cycleNumber, nargs='+', default=[10, 100], metavar='N', help='cycles (default 10 100)')
    ap.add_argument('--curve', type=measuredCurve, action='append', default=[], metavar='COLUMN=PATH',
                    help='a quantity and the measured curve to show beside it (N,<name> CSV)')
    ap.add_argument('--out', required=True, help='where conditions-seeds.csv, conditions.csv and conditions.md go')
    a = ap.parse_args(argv)
    try:
        seeds = conditions.realizationTable(a.studies, a.by, a.quantities, a.at)
        table = conditions.conditionTable(seeds, a.quantities)
        if a.curve:
            table = conditions.withMeasured(table, a.quantities, dict(a.curve))
    except (StudyError, CurveError, ValueError) as e:
        print('conditions.py: %s' % e, file=sys.stderr)
        return 2
    os.makedirs(a.out, exist_ok=True)
    seeds.to_csv(os.path.join(a.out, 'conditions-seeds.csv'), index=False, float_format='%.6g')
    table.to_csv(os.path.join(a.out, 'conditions.csv'), index=False, float_format='%.6g')
    text = conditions.markdown(table, a.quantities)
    with open(os.path.join(a.out, 'conditions.md'), 'w') as fh:
        fh.write(text)
    print(text, end='')
    return 0


if __name__ == '__main__':
    sys.exit(main())
