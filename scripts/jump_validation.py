#!/usr/bin/python3
"""Cycle jumping against direct simulation over the runs of a study (ballast.analysis.jumps; docs/cycles.md,
"Validation"):

    scripts/jump_validation.py docs/studies/jump-box --out docs/studies/jump-box

writes validation.csv (per seed: the first crushes' cycles, the crushes and the settlement after the last cycle,
direct and jumping, whether each agrees within its tolerance, the CPU of both), covered.csv (the same for each
jumping run longer than its seed's direct run, over the cycles both cover), long.csv (the runs of 10^4 cycles and
more), validation.json (the tolerances and how many agree) and jumps.png."""
import argparse
import json
import os
import sys

from ballast.analysis import jumps
from ballast.study.options import StudyError


def main(argv=None):
    ap = argparse.ArgumentParser(prog='scripts/jump_validation.py', description=__doc__.split('\n\n')[0])
    ap.add_argument('study', help='a study or its records, with runs of the same seeds directly and with jump')
    ap.add_argument('--out', required=True,
                    help='where validation.csv, covered.csv, long.csv, validation.json and jumps.png go')
    ap.add_argument('--reference', help='a study whose direct runs the jumping runs of STUDY are compared with')
    a = ap.parse_args(argv)
    try:
        table, long = jumps.compare(a.study, a.reference), jumps.longRuns(a.study)
        cover = jumps.covered(a.study, a.reference)
    except (StudyError, ValueError, KeyError) as e:
        print('jump_validation.py: %s' % e, file=sys.stderr)
        return 2
    os.makedirs(a.out, exist_ok=True)
    table.to_csv(os.path.join(a.out, 'validation.csv'), index=False, float_format='%.6g')
    long.to_csv(os.path.join(a.out, 'long.csv'), index=False, float_format='%.6g')
    cover.to_csv(os.path.join(a.out, 'covered.csv'), index=False, float_format='%.6g')
    result = {'tolerances': {'crushCycle': jumps.TOL_CYCLE, 'crushes': jumps.TOL_CRUSHES,
                             'settlement': jumps.TOL_SETTLEMENT, 'firstCrushes': jumps.FIRST},
              'agree': jumps.verdict(table), 'pairs': len(table), 'longRuns': len(long),
              'agreeCovered': jumps.verdict(cover), 'covered': len(cover)}
    with open(os.path.join(a.out, 'validation.json'), 'w') as fh:
        json.dump(result, fh, indent=1)
    print(table.to_string(index=False))
    print(cover.to_string(index=False))
    print(long.to_string(index=False))
    print(json.dumps(result['agree']))
    jumps.figure(a.study, os.path.join(a.out, 'jumps.png'), a.reference)
    print(os.path.join(a.out, 'jumps.png'))
    return 0


if __name__ == '__main__':
    sys.exit(main())
