#!/usr/bin/python3
"""Settlement against the number of load cycles over the runs of box-test studies (ballast.analysis.settlement;
docs/box.md, "The study"):

    scripts/box_settlement.py docs/studies/box [docs/studies/box-f3 ...] --out docs/studies/box [--apart 2]
        [--tipping 0.02] [--reference docs/studies/box --at 1 5 10 25 50]
    scripts/box_settlement.py docs/studies/box-sg --by fatigue keep --reference 'docs/studies/box-sg[fatigue=1
        keep=none]' --at 1 10 100 --apart sg-volume-seed2-c96 --out docs/studies/box-sg
    scripts/box_settlement.py docs/studies/clump-box-level docs/studies/clump-box-level-slices --join
        --out docs/studies/clump-box-level

writes settlement.csv (every run's curve), runs.csv (per realization what it broke and cost: crushes, abrasions,
largest fatigue damage and stress ratio, grains, CPU per cycle and per realization, step, the largest and the last
tilt, the cycle it tips from),
settlement.json (per study: the mean curve's and every run's logarithmic and power laws with R^2) and settlement.png
(a dot on each run at the cycle most of its grains crushed in); with --reference, all three over the cycles the
other studies cover, and each other study's runs against the reference's of the same seed at the cycles --at:
settlement-paired.csv (per seed and cycle) and settlement-paired.json (per cycle: the mean difference with its 95 %
interval, the mean ratio). --tipping reads apart the realizations whose sleeper rose back by more than that many mm
above its deepest settlement (it tips or rocks instead of settling), naming the cycle it did, and --apart those
named by seed or run id; --join reads a table of slices with the table whose rows it carries on (a realization
under the study it began in); --by splits a study's runs into its variants (rows differing in those parameters), each
read as a study."""
import argparse
import json
import os
import sys

import pandas as pd

from ballast.analysis import settlement
from ballast.study.options import StudyError


def rise(text):
    """--tipping's value [mm]: a number above 0."""
    try:
        value = float(text)
    except ValueError:
        value = float('nan')
    if not value > 0 or value == float('inf'):
        raise argparse.ArgumentTypeError('%r mm; allowed: a rise above 0 mm, e.g. 0.02' % text)
    return value


def realization(text):
    """--apart's value: a seed (an integer) or a run id (its last slice's, for a realization run in slices)."""
    return int(text) if text.isdigit() else text


def span(values, fmt):
    """'lo-hi' of a column over a study's realizations in `fmt` ('lo' when all agree once printed; '?' where the
    records have no such column)."""
    values = values.dropna()
    if values.empty:
        return '?'
    lo, hi = fmt % values.min(), fmt % values.max()
    return lo if lo == hi else '%s-%s' % (lo, hi)


def main(argv=None):
    ap = argparse.ArgumentParser(prog='scripts/box_settlement.py', description=__doc__.split('\n\n')[0])
    ap.add_argument('studies', nargs='+', help='studies or their records, with runs that wrote cycles.csv')
    ap.add_argument('--out', required=True, help='where settlement.csv, settlement.json and settlement.png go')
    ap.add_argument('--apart', type=realization, nargs='+', default=[], metavar='SEED|RUNID',
                    help='realizations read apart (drawn, fitted, left out of the mean and, beside a run of the same '
                    'seed, out of its pairs), by seed or by run id: e.g. a sleeper that tips, a resumed twin')
    ap.add_argument('--tipping', type=rise, metavar='MM',
                    help='read apart the realizations whose sleeper rises back more than MM [mm] above its deepest '
                    'settlement (it tips or rocks), from a pair the cycles after it did (default: no detection)')
    ap.add_argument('--by', nargs='+', default=[], metavar='PARAM',
                    help="the parameters whose values split a study's runs into variants, each its own study named "
                    "'STUDY[PARAM=value ...]' (e.g. --by fatigue keep)")
    ap.add_argument('--join', action='store_true',
                    help='a realization whose slices go on in another of the studies belongs to the study it began in '
                    '(a table of slices with the table whose rows it carries on: one mean over their seeds); '
                    'default: to the study of its last slice')
    ap.add_argument('--reference', metavar='STUDY', help='a study (read too if not listed), or with --by a variant '
                    "'STUDY[PARAM=value ...]', whose runs the others are compared with, seed by seed (the same bed)")
    ap.add_argument('--at', type=int, nargs='+', default=[1, 10, 100], metavar='N',
                    help='the cycles of the paired comparison (default: 1 10 100)')
    a = ap.parse_args(argv)
    referenceStudy = a.reference.split('[')[0] if a.by and a.reference else a.reference
    if referenceStudy and referenceStudy not in a.studies:
        a.studies.append(referenceStudy)
    try:
        frame = settlement.curves(a.studies, apart=a.apart, tipping=None if a.tipping is None else 1e-3 * a.tipping,
                                  by=a.by, join=a.join)
        names = list(frame.study.unique())
        if a.reference and a.reference not in names:
            raise ValueError('--reference %s: no such study or variant; there are %s' % (a.reference, ', '.join(names)))
        others = frame[frame.study != a.reference]
        if a.reference and others.empty:   # a variants study under way: its first variant only, nothing to pair yet
            print('box_settlement.py: --reference %s: no other study or variant yet, nothing paired' % a.reference,
                  file=sys.stderr)
        elif a.reference:   # compared over the cycles the other studies cover: the reference's curves cut there
            frame = settlement.upTo(frame, others.cycle.max())
        fits = settlement.summary(frame)
        pairs = {study: settlement.paired(frame, study, a.reference, a.at) for study in names
                 if a.reference and study != a.reference}
    except (StudyError, ValueError) as e:
        print('box_settlement.py: %s' % e, file=sys.stderr)
        return 2
    os.makedirs(a.out, exist_ok=True)
    frame.to_csv(os.path.join(a.out, 'settlement.csv'), index=False, float_format='%.9g')
    runs = settlement.realizations(a.studies, by=a.by, join=a.join).merge(
        frame.groupby('runId').tippedAt.first().reset_index())
    runs.to_csv(os.path.join(a.out, 'runs.csv'), index=False, float_format='%.9g')
    if pairs:
        rows = [r.assign(study=study) for study, (r, _) in pairs.items()]
        pd.concat(rows, ignore_index=True).to_csv(os.path.join(a.out, 'settlement-paired.csv'), index=False,
                                                  float_format='%.9g')
        with open(os.path.join(a.out, 'settlement-paired.json'), 'w') as fh:
            json.dump({study: {'reference': a.reference, 'perCycle': per} for study, (_, per) in pairs.items()}, fh,
                      indent=1)
    with open(os.path.join(a.out, 'settlement.json'), 'w') as fh:
        json.dump(fits, fh, indent=1)
    for study, (_, per) in pairs.items():
        for c in per:
            print('%s against %s, cycle %d (%d seeds): difference %+.4f mm (95 %%: %s), ratio %.3f' % (
                study, a.reference, c['cycle'], c['seeds'], 1e3 * c['meanDifference'],
                'none with one seed' if c['interval95'] is None else '+-%.4f' % (1e3 * c['interval95']),
                c['meanRatio']))
    for study, r in runs.groupby('study', sort=False):
        print('%s: crushes %s, abrasions %s, largest fatigue damage %s, largest stress ratio %s, largest tilt %s rad, '
              'grains %s after cycle 1 and %s at the end, %s s of CPU a cycle (%s h a realization), step %s s (%s steps '
              'a cycle)' % (
                  study, span(r.crushes, '%d'), span(r.abrasions, '%d'), span(r.maxDamage, '%.3g'),
                  span(r.maxStressRatio, '%.3g'), span(r.tiltMax, '%.3g'),
                  span(r.grainsCycle1, '%d'), span(r.grainsLast, '%d'), span(r.cpuPerCycle, '%.1f'),
                  span(r.cpuPerRealization / 3600, '%.1f'), span(r.timeStep, '%.3g'),
                  span(r.stepsPerCycle, '%.0f')))
    for r in runs[runs.avalancheCrushes.notna()].itertuples():
        print('%s: %s, most crushes in cycle %d (%d)' % (r.study, r.runId, r.avalancheCycle, r.avalancheCrushes))
    for study, f in fits.items():
        for rid, n in f['tippedAt'].items():
            print('%s: %s tips from cycle %d (read apart)' % (study, rid, n))
        if not f['runs']:
            print('%s: every run read apart (%s): no mean' % (study, ', '.join(f['apart'])))
            continue
        law = (f['mean'] or {}).get('log')
        print('%s: %d runs to cycle %d%s, settlement %.3f mm after cycle 1, %.3f mm after %d%s' % (
            study, f['runs'], f['cycles'], ' (read apart: %s)' % ', '.join(f['apart']) if f['apart'] else '',
            1e3 * f['settlementFirst'], 1e3 * f['settlementLast'], f['cycles'],
            ', a + b ln N with b = %.4g mm (R^2 %.3f)' % (1e3 * law['b'], law['r2']) if law else ''))
    print(settlement.figure(frame, fits, os.path.join(a.out, 'settlement.png'),
                            marks=runs.dropna(subset=['avalancheCycle']).set_index('runId').avalancheCycle.to_dict()))
    return 0


if __name__ == '__main__':
    sys.exit(main())
