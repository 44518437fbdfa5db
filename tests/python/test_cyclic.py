"""ballast.experiments.cyclic: the cycles.csv schema every cyclic experiment writes, the cycles jumped and the
settlement extrapolated over them, the jump summary; checked against values worked out by hand."""
import math

import numpy as np
import pandas as pd
import pytest

pytest.importorskip('yade')
from ballast.experiments import cyclic  # noqa: E402

A, B = 1e-3, 2e-4   # [m] a settlement law s = A + B ln n


def rows(cycles):
    """Rows of the shared schema, the n-th simulated with s = A + B ln n exactly, nothing crushed."""
    return [dict(zip(cyclic.COLUMNS, (c, 0.1 * n, A + B * math.log(n), 1e-5, 0, 0, 0, 0, 0.0, 0.5, 100, 1.0)),
                 tilt=-0.01 * n) for n, c in enumerate(cycles, 1)]


def test_the_shared_columns_come_first_in_order_then_the_experiments_own():
    frame = cyclic.table(rows([1, 2, 3]), ('tilt',))
    assert list(frame.columns) == list(cyclic.COLUMNS) + ['tilt']
    assert list(frame.tilt) == pytest.approx([-0.01, -0.02, -0.03])
    # a missing column is NaN, never shifted into another's place
    frame = cyclic.table([{'cycle': 1, 'settlement': 0.5}], ('tilt',))
    assert frame.settlement[0] == 0.5 and math.isnan(frame.tilt[0]) and math.isnan(frame.resilient[0])


def test_jumped_cycles_and_the_settlement_extrapolated_over_them(tmp_path):
    """Six simulated cycles, the last one numbered 20 (14 jumped before it): jumped = cycle - row, and the
    settlement those cycles add is B ln(20 / 6), B fitted to the exact law; none before the jump."""
    class Jumper:
        jumped, jumps = 14, [{}]
    frame = cyclic.table(rows([1, 2, 3, 4, 5, 20]), ('tilt',), Jumper())
    assert list(frame.columns) == list(cyclic.COLUMNS) + list(cyclic.JUMP_COLUMNS) + ['tilt']
    assert list(frame.jumped) == [0, 0, 0, 0, 0, 14]
    np.testing.assert_allclose(frame.settlementJumped[:5], 0, atol=1e-15)
    assert frame.settlementJumped.iloc[-1] == pytest.approx(B * math.log(20 / 6), rel=1e-9)
    s = cyclic.jumpSummary(frame, Jumper())
    assert s == pytest.approx({'cycles': 20, 'cyclesSimulated': 6, 'cyclesJumped': 14, 'jumps': 1,
                               'settlementJumped': B * math.log(20 / 6),
                               'settlementTotal': A + B * math.log(6) + B * math.log(20 / 6)}, rel=1e-9)
    assert cyclic.jumpSummary(frame, None) == {}
    path = str(tmp_path / 'cycles.csv')
    cyclic.write(path, frame)
    back = pd.read_csv(path)
    assert list(back.columns) == list(frame.columns)
    np.testing.assert_allclose(back.settlement, frame.settlement, rtol=1e-8)


def test_a_cycle_that_crushed_or_abraded_changed_the_bed():
    frame = cyclic.table([dict(cycle=k, crushes=c, abrasions=a) for k, (c, a) in enumerate([(0, 0), (2, 0), (0, 1)], 1)])
    assert list(cyclic.changed(frame)) == [False, True, True]


def test_whole_cycles_checkpoint_after_a_cycle_closes_fractions_within():
    assert cyclic.wholeCycles(2) and cyclic.wholeCycles(50.0) and not cyclic.wholeCycles(0.45)


def test_each_cycle_says_whether_it_kept_the_quasi_static_bounds_in_its_own_row():
    """cycles.csv is written as each cycle closes, before the option has read it: the rows read so far get their
    mark, the last one NaN until it is read; never a mark in another cycle's row."""
    class Choice:
        met = [0, 1]
    frame = cyclic.table(rows([1, 2, 3]), ('tilt',), None, Choice())
    assert list(frame.columns) == list(cyclic.COLUMNS) + ['quasiStaticMet', 'tilt']
    assert list(frame.quasiStaticMet[:2]) == [0, 1] and math.isnan(frame.quasiStaticMet[2])
    Choice.met = [0, 1, 1]
    assert list(cyclic.table(rows([1, 2, 3]), ('tilt',), None, Choice()).quasiStaticMet) == [0, 1, 1]

