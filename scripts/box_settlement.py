#!/usr/bin/python3
"""Settlement against the number of load cycles over the runs of box-test studies (ballast.analysis.settlement;
docs/box.md, "The study"):

    scripts/box_settlement.py docs/studies/box [docs/studies/box-f3 ...] --out docs/studies/box

writes settlement.csv (every run's curve), settlement.json (per study: the mean curve's and every run's
logarithmic and power laws with R^2) and settlement.png."""
import argparse
import json
import os
import sys

from ballast.analysis import settlement
from ballast.study.options import StudyError


def main(argv=None):
    ap = argparse.ArgumentParser(prog='scripts/box_settlement.py', description=__doc__.split('\n\n')[0])
    ap.add_argument('studies', nargs='+', help='studies or their records, with runs that wrote cycles.csv')
    ap.add_argument('--out', required=True, help='where settlement.csv, settlement.json and settlement.png go')
    a = ap.parse_args(argv)
    try:
        frame = settlement.curves(a.studies)
    except (StudyError, ValueError) as e:
        print('box_settlement.py: %s' % e, file=sys.stderr)
        return 2
    fits = settlement.summary(frame)
    os.makedirs(a.out, exist_ok=True)
    frame.to_csv(os.path.join(a.out, 'settlement.csv'), index=False, float_format='%.9g')
    with open(os.path.join(a.out, 'settlement.json'), 'w') as fh:
        json.dump(fits, fh, indent=1)
    for study, f in fits.items():
        law = (f['mean'] or {}).get('log')
        print('%s: %d runs to cycle %d, settlement %.3f mm after cycle 1, %.3f mm after %d%s' % (
            study, f['runs'], f['cycles'], 1e3 * f['settlementFirst'], 1e3 * f['settlementLast'], f['cycles'],
            ', a + b ln N with b = %.4g mm (R^2 %.3f)' % (1e3 * law['b'], law['r2']) if law else ''))
    print(settlement.figure(frame, fits, os.path.join(a.out, 'settlement.png')))
    return 0


if __name__ == '__main__':
    sys.exit(main())
