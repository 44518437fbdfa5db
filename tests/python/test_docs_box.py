"""The settlements docs/box.md quotes for the box study's realizations are the committed records': each row of its
table "The realizations so far" read back against the runs' cycles.csv (through ballast.analysis.settlement, as
scripts/box_settlement.py reads them), to the digits the table prints, and the cycle each sleeper tips from."""
import os
import re

import pytest

from ballast.analysis import settlement

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
HEADING = '**The realizations so far**'


def table():
    """The header cells and the rows (lists of cells) of the markdown table after HEADING in docs/box.md."""
    with open(os.path.join(ROOT, 'docs', 'box.md')) as fh:
        text = fh.read()
    lines = text[text.index(HEADING):].splitlines()
    start = next(k for k, line in enumerate(lines) if line.startswith('|'))
    rows = []
    for line in lines[start:]:
        if not line.startswith('|'):
            break
        rows.append([c.strip() for c in line.strip().strip('|').split('|')])
    return rows[0], rows[2:]


def test_the_table_of_realizations_is_the_records():
    head, rows = table()
    cycles = [int(re.search(r'\d+', h).group()) for h in head[1:-1]]   # "N = 1" ... between seed and tips
    frame = settlement.curves([os.path.join(ROOT, 'docs', 'studies', 'box')], tipping=2e-5)
    assert sorted(int(r[0]) for r in rows) == sorted(frame.seed.unique())
    for cells in rows:
        run = frame[frame.seed == int(cells[0])].set_index('cycle')
        for N, cell in zip(cycles, cells[1:-1]):
            if cell == '':
                assert N > run.index.max(), 'seed %s reached cycle %d: its cell is empty' % (cells[0], N)
            else:
                assert float(cell) == pytest.approx(1e3 * run.settlement[N], abs=5.1e-4), (cells[0], N)
        onset = run.tippedAt.iloc[0]
        assert cells[-1] == ('' if onset != onset else str(int(onset))), cells[0]
