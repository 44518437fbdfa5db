#!/usr/bin/python3
"""The force network at half the peak load against the loading frequency (ballast.study.halfload;
docs/studies.md, Fig. 4): realizations loaded by eq. 8 only to Fmax/2, before any crush.

    yade -n -x scripts/halfload.py run --seeds 1-10 --f 0.25,1,8 --damping 0.2 --csv docs/studies/halfload/runs.csv
    scripts/halfload.py report docs/studies/halfload/runs.csv --out docs/studies/halfload

`run` appends a row per finished run to the CSV and skips the runs it has (it resumes); any parameter
of the oedometer can be set with --set NAME=VALUE. `report` writes test.json and halfload.png.
"""
import argparse
import json
import os
import sys

from ballast.params import ParamError, literal
from ballast.study import halfload
from ballast.study.options import lineList


def floatList(v):
    return [float(x) for x in v.split(',')]


def main(argv=None):
    ap = argparse.ArgumentParser(prog='scripts/halfload.py', description=__doc__, allow_abbrev=False,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest='command', metavar='COMMAND', required=True)
    ar = sub.add_parser('run', help='run the sweep (inside yade)')
    ar.add_argument('--seeds', type=lineList, required=True, metavar='A-B,C', help='realizations')
    ar.add_argument('--f', type=floatList, required=True, metavar='F1,F2', help='loading frequencies [Hz]')
    ar.add_argument('--damping', type=floatList, default=[0.2], metavar='D1,D2', help='local damping while loading [-] (default 0.2)')
    ar.add_argument('--csv', required=True, help='the CSV the runs are appended to')
    ar.add_argument('--set', action='append', default=[], metavar='NAME=VALUE', help='any other parameter of the oedometer')
    rp = sub.add_parser('report', help='the tests and the figure of a sweep')
    rp.add_argument('csv', help='the CSV of a sweep')
    rp.add_argument('--out', required=True, metavar='DIR', help='where to write test.json and halfload.png')
    a = ap.parse_args(argv)
    try:
        if a.command == 'run':
            extra = dict((kv.split('=', 1)[0], literal(kv.split('=', 1)[1])) for kv in a.set)
            runs = halfload.plan(a.seeds, a.f, a.damping, **extra)
            halfload.sweep(a.csv, runs)
            return 0
        summary = halfload.summarize(a.csv)
    except (ParamError, ValueError, OSError) as e:
        print('halfload.py: %s' % e, file=sys.stderr)
        return 2
    os.makedirs(a.out, exist_ok=True)
    tests = {'%g' % d: dict(s['test'] or {}, f=s['f'].tolist(), ratioMean=s['ratioMean'].tolist(),
                            unbalancedMedian=s['unbalancedMedian'].tolist(), vRmsMedian=s['vRmsMedian'].tolist(),
                            riseAgainstBase=s.get('riseAgainstBase')) for d, s in summary.items()}
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
