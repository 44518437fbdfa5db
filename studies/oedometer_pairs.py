#!/usr/bin/python3
"""Two groups of oedometer runs paired by seed (ballast.analysis.options.compare): delta at the applied peak of eq. 8,
the crushes, the share of realizations that avalanche with Fisher's and McNemar's exact tests, and the CPU ratio.

    studies/oedometer_pairs.py 'docs/studies/clump-oedometer[ft0=3.1e6]' --reference 'docs/studies/frequency[f=8]' \\
        --name clumps --reference-name 'spheres' --out docs/studies/clump-oedometer

A group is a study (or its records), PATH[NAME=VALUE ...] for its runs with those parameter values. Writes
comparison.json, comparison.md (a row of docs/performance.md's table) and pairs.png."""
import argparse
import os
import sys

from ballast.analysis import options
from ballast.analysis.pairs import parseSelection
from ballast.study.options import StudyError


def main(argv=None):
    ap = argparse.ArgumentParser(prog='studies/oedometer_pairs.py', description=__doc__.split('\n\n')[0])
    ap.add_argument('study', help='the runs compared: PATH or PATH[NAME=VALUE ...]')
    ap.add_argument('--reference', required=True, help='the runs they are paired with by seed, as study')
    ap.add_argument('--name', default='study', help="the compared runs' name in the outputs (default: study)")
    ap.add_argument('--reference-name', default='reference', help="the reference's name in them (default: reference)")
    ap.add_argument('--out', required=True, help='where comparison.json, comparison.md and pairs.png go')
    a = ap.parse_args(argv)
    try:
        mine, ref = (options.frame(path, **chosen) for path, chosen in
                     (parseSelection(x, 'oedometer_pairs') for x in (a.study, a.reference)))
        result = {a.name: dict(options.compare(mine, ref), selection=a.study, referenceSelection=a.reference)}
    except (StudyError, ValueError, KeyError) as e:
        print('oedometer_pairs.py: %s' % e, file=sys.stderr)
        return 2
    options.write(result, a.out, a.reference_name)
    r = result[a.name]
    print('%s against %s, %d seeds: delta %.2f mm (reference %.2f), difference %.1f mm [%.1f, %.1f], Wilcoxon p = %.3g;'
          ' avalanching %.0f %% (reference %.0f %%), Fisher p = %.3g, McNemar p = %.3g; CPU x%.2f' % (
              a.study, a.reference, r['n'], 1e3 * r['option']['mean'], 1e3 * r['reference']['mean'],
              1e3 * r['meanDifference'], 1e3 * r['meanDifferenceLow'], 1e3 * r['meanDifferenceHigh'], r['pWilcoxon'],
              100 * r['option']['avalanching'], 100 * r['reference']['avalanching'], r['pFisherAvalanching'],
              r['pMcNemarAvalanching'], r['cpuRatioMedian']))
    print(options.figure({a.name: (mine, ref)}, os.path.join(a.out, 'pairs.png'), a.reference_name))
    return 0


if __name__ == '__main__':
    sys.exit(main())
