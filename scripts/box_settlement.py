#!/usr/bin/python3
"""Settlement against the number of load cycles over the runs of box-test studies (ballast.analysis.settlement;
docs/box.md, "The study"):

    scripts/box_settlement.py docs/studies/box [docs/studies/box-f3 ...] --out docs/studies/box [--apart 2]

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
    ap.add_argument('--apart', type=int, nargs='+', default=[], metavar='SEED',
                    help='realizations read apart (drawn, fitted, left out of the mean), e.g. a sleeper that tips')
    a = ap.parse_args(argv)
    try:
        frame = settlement.curves(a.studies, apart=a.apart)
        fits = settlement.summary(frame)
    except (StudyError, ValueError) as e:
        print('box_settlement.py: %s' % e, file=sys.stderr)
        return 2
    os.makedirs(a.out, exist_ok=True)
    frame.to_csv(os.path.join(a.out, 'settlement.csv'), index=False, float_format='%.9g')
    with open(os.path.join(a.out, 'settlement.json'), 'w') as fh:
        json.dump(fits, fh, indent=1)
    for study, f in fits.items():
        law = (f['mean'] or {}).get('log')
        print('%s: %d runs to cycle %d%s, settlement %.3f mm after cycle 1, %.3f mm after %d%s' % (
            study, f['runs'], f['cycles'], ' (read apart: %s)' % ', '.join(f['apart']) if f['apart'] else '',
            1e3 * f['settlementFirst'], 1e3 * f['settlementLast'], f['cycles'],
            ', a + b ln N with b = %.4g mm (R^2 %.3f)' % (1e3 * law['b'], law['r2']) if law else ''))
    print(settlement.figure(frame, fits, os.path.join(a.out, 'settlement.png')))
    return 0


if __name__ == '__main__':
    sys.exit(main())
