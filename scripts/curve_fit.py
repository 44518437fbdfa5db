#!/usr/bin/python3
"""How far a study's runs lie from measured curves (ballast.analysis.curvefit): each run's cycles.csv column against
a measured curve of the same quantity, at chosen cycles, the runs ranked by the root mean square difference:

    scripts/curve_fit.py docs/studies/triax-calib-a \\
        --curve axialStrain=../shared/data/cyclic-triaxial-p60-q230-f5-axial.csv \\
        --curve volumetricStrain=../shared/data/cyclic-triaxial-p60-q230-f5-volumetric.csv \\
        --at 1 10 20 --params rollingFriction ft0 --out docs/studies/triax-calib-a

writes fit.csv (a row per run, quantity and cycle), scores.csv (a row per run, the closest first) and fit.png."""
import argparse
import os
import sys

from ballast.analysis import curvefit
from ballast.experiments.triaxial.strains import CurveError
from ballast.study.options import StudyError, cycleNumber, measuredCurve


def main(argv=None):
    ap = argparse.ArgumentParser(prog='scripts/curve_fit.py', description=__doc__.split('\n\n')[0])
    ap.add_argument('studies', nargs='+', help='studies (or their records)')
    ap.add_argument('--curve', type=measuredCurve, action='append', required=True, metavar='COLUMN=PATH',
                    help='a column of cycles.csv and the measured curve it is held against (N,<name> CSV)')
    ap.add_argument('--at', type=cycleNumber, nargs='+', default=[1, 10, 100], metavar='N', help='cycles (default 1 10 100)')
    ap.add_argument('--params', nargs='*', default=[], metavar='NAME', help='parameters of the runs to list beside them')
    ap.add_argument('--out', required=True, help='where fit.csv, scores.csv and fit.png go')
    a = ap.parse_args(argv)
    curves = dict(a.curve)
    try:
        frame = curvefit.table(a.studies, curves, a.at, a.params)
        ranked = curvefit.scores(frame, a.params)
    except (StudyError, CurveError, ValueError) as e:
        print('curve_fit.py: %s' % e, file=sys.stderr)
        return 2
    os.makedirs(a.out, exist_ok=True)
    frame.to_csv(os.path.join(a.out, 'fit.csv'), index=False, float_format='%.6g')
    ranked.to_csv(os.path.join(a.out, 'scores.csv'), index=False, float_format='%.6g')
    curvefit.figure(a.studies, curves, os.path.join(a.out, 'fit.png'), title=', '.join(a.studies))
    print(ranked.to_string(index=False, float_format=lambda v: '%.4g' % v))
    return 0


if __name__ == '__main__':
    sys.exit(main())
