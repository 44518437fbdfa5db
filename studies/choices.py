#!/usr/bin/python3
"""What the model options of issue 13 do at the paper's size (ballast.analysis.choices, docs/strength.md).

    studies/choices.py onset docs/studies/criteria-onset       the ft0 of each criterion at the paper's onset
    studies/choices.py compare docs/studies/choices            comparison.csv and choices.png there
"""
import argparse
import csv
import json
import os
import sys

from ballast.analysis import choices


def main(argv=None):
    ap = argparse.ArgumentParser(prog='studies/choices.py', description=__doc__, allow_abbrev=False,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('what', choices=('onset', 'compare'))
    ap.add_argument('study', metavar='STUDY', help='a study directory or its records (scripts/study.py run --records)')
    ap.add_argument('--out', metavar='DIR', help='where compare writes (default: STUDY)')
    a = ap.parse_args(argv)
    if not os.path.isfile(os.path.join(a.study, 'study.json')):
        print('choices.py: STUDY: %s holds no study.json (a study directory or records of scripts/study.py)' % a.study,
              file=sys.stderr)
        return 2
    if a.what == 'onset':
        print(json.dumps(choices.onsetStrengths(a.study), indent=1))
        return 0
    out = a.out or a.study
    rows = choices.comparison(a.study)
    with open(os.path.join(out, 'comparison.csv'), 'w', newline='') as fh:
        w = csv.DictWriter(fh, fieldnames=choices.COMPARISON_COLUMNS, extrasaction='ignore')
        w.writeheader()
        w.writerows(rows)
    print('%s, %s' % (os.path.join(out, 'comparison.csv'), choices.figure(a.study, os.path.join(out, 'choices.png'))))
    return 0


if __name__ == '__main__':
    sys.exit(main())
