"""Settlement and breakage against the number of load cycles for several oedometer runs (docs/oedometer.md,
"Many cycles"): keeps each run's compact record under --out, writes runs.csv and cycles.png there.

    /usr/bin/python3 studies/cycles_figure.py RUN_DIR [RUN_DIR ...] --out docs/studies/cycles
"""
import argparse
import os

from ballast.analysis import manycycles


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter,
                                 allow_abbrev=False)
    ap.add_argument('runs', nargs='+', help='run folders (with cycles.csv and summary.json) or kept records')
    ap.add_argument('--out', required=True, help='folder of the records, runs.csv and cycles.png')
    a = ap.parse_args()
    for r in a.runs:
        if not os.path.isfile(os.path.join(r, 'cycles.csv')):
            ap.error('%s has no cycles.csv: not a run of several cycles' % r)
    kept = []
    for r in a.runs:
        dest = os.path.join(a.out, os.path.basename(os.path.normpath(r)))
        if os.path.abspath(dest) != os.path.abspath(r):
            manycycles.keepRecord(r, dest)
        kept.append(dest)
    manycycles.writeTable(manycycles.table(kept), os.path.join(a.out, 'runs.csv'))
    manycycles.figure(kept, os.path.join(a.out, 'cycles.png'))
    print('wrote %s' % ', '.join(os.path.join(a.out, f) for f in ('runs.csv', 'cycles.png')))


if __name__ == '__main__':
    main()
