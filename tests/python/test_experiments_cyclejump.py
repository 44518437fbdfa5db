"""ballast.experiments.cyclejump in YADE: a grain at a constant peak stress ratio (the fatigue test of the engines,
tests/python/test_engines_fatigue.py: it crushes in cycle 61 worked out by hand) crushes in the same cycle with and
without jumping, whatever the window and margin; the jump ends before that cycle; the jumper's state comes back
whole; a crush restarts the window. Cycles are driven here by hand, as an experiment drives them."""
import math

import numpy as np
import pytest
from yade import O

from ballast.experiments.cyclejump import CycleJumper
from test_engines_fatigue import PER_CYCLE, fatigueGrain

CRUSH_CYCLE = 61   # s_p = 0.6, b = 8: N_f = 0.6^-8 = 59.5 peaks, crushes in cycle 61 (test_engines_fatigue.py)


def crushCycle(monkeypatch, jumper, maxCycles=200):
    """Runs load cycles of PER_CYCLE steps, the jumper told at each cycle's end; returns (the cycle the grain
    crushed in, counting the jumped ones, the jumper)."""
    g, crush = fatigueGrain(monkeypatch)
    cycle = simulated = 0
    if jumper is not None:
        jumper.target = maxCycles
    while cycle < maxCycles:
        O.run(PER_CYCLE, True)
        cycle, simulated = cycle + 1, simulated + 1
        if crush.nCrushed:
            return cycle, jumper
        # a bed settling 1e-4 (1 + ln n) m after n simulated cycles
        if jumper is not None and jumper.cycleEnded(crush, [g], cycle, 1e-4 * (1 + math.log(simulated)), False):
            entry = jumper.apply(crush)
            assert entry['to'] < CRUSH_CYCLE - 1 - jumper.margin + 1   # never into the cycles before the failing one
            cycle = entry['to']
    return None, jumper


def test_without_a_jumper_the_grain_crushes_in_cycle_61(monkeypatch):
    assert crushCycle(monkeypatch, None)[0] == CRUSH_CYCLE


@pytest.mark.parametrize('window,margin', [(2, 0), (4, 1), (6, 3)])
def test_with_jumping_the_grain_crushes_in_the_same_cycle(monkeypatch, window, margin):
    cycle, j = crushCycle(monkeypatch, CycleJumper(window=window, steady=0.2, maxDamage=0.99, margin=margin, growth=1000.0))
    assert cycle == CRUSH_CYCLE
    assert j.jumped > 30 and len(j.jumps) >= 1
    # the first jump ends margin cycles before the last cycle the grain survives (59 peaks: 60 - 1 - margin)
    assert j.jumps[0]['to'] == CRUSH_CYCLE - 2 - margin and j.jumps[0]['limit'] == 'failure'


def test_small_jumps_add_up_to_the_same_damage(monkeypatch):
    """maxDamage 0.02 limits each jump to floor(0.02 / r) = 2 cycles (r = 0.4 0.6^8 = 0.0067): many jumps, the
    crush still in cycle 61 and each jump's damage within maxDamage."""
    cycle, j = crushCycle(monkeypatch, CycleJumper(window=2, steady=0.2, maxDamage=0.02, margin=0, growth=1000.0))
    assert cycle == CRUSH_CYCLE and len(j.jumps) > 5
    r = 0.4 * 0.6 ** 8
    assert all(e['cycles'] * r <= 0.02 for e in j.jumps) and all(e['limit'] == 'maxDamage' for e in j.jumps[:-1])


def test_the_settlement_of_a_jump_comes_from_the_log_law_of_the_simulated_cycles(monkeypatch):
    """The bed here settles s = 1e-4 (1 + ln n) after n simulated cycles exactly: the law is found; a jump from
    cycle N0 to N0 + DN adds 1e-4 ln((N0 + DN) / N0), and at the n-th simulated cycle, cycle N of the count, the
    jumped cycles' settlement is 1e-4 ln(N / n)."""
    from ballast.settlementlaws import settlementJumped
    _, j = crushCycle(monkeypatch, CycleJumper(window=4, steady=0.2, maxDamage=0.99, margin=0, growth=1000.0))
    e = j.jumps[0]   # after 5 simulated cycles: the law of rows 3..5
    assert e['settlementLawB'] == pytest.approx(1e-4, rel=1e-9) and e['settlementLawR2'] == pytest.approx(1, abs=1e-12)
    assert e['settlementJumped'] == pytest.approx(1e-4 * math.log(e['to'] / e['cycle']), rel=1e-9)
    N = np.array([d[0] for d in j.direct])
    n = np.arange(1, len(N) + 1)
    assert N[-1] > n[-1] and not any(d[2] for d in j.direct[:-1])   # no crush before the last simulated cycle
    got = settlementJumped(N, [d[1] for d in j.direct])
    assert np.all(got[:3] == 0)                                 # no law below 3 rows in the recent half
    np.testing.assert_allclose(got[3:], 1e-4 * np.log(N / n)[3:], rtol=1e-9, atol=1e-18)
    # causal: a settlement that jumps later does not move the earlier rows
    later = [d[1] for d in j.direct]
    later[-1] += 1.0
    np.testing.assert_array_equal(settlementJumped(N, later)[:-1], got[:-1])


def test_jumps_csv_and_cycles_csv_extrapolate_the_same_settlement(monkeypatch):
    """Many small jumps (maxDamage 0.02) on a bed settling 1e-4 (1 + ln n) exactly: at jump k's end, the count
    to_k, n_k = to_k - (cycles jumped so far) cycles simulated, settlementJumpedTotal is cycles.csv's definition
    1e-4 ln(to_k / n_k); each settlementJumped is the total's growth since the jump before, so the column sums to
    the last total (before 2026-12-05 each jump's 1e-4 ln(to_k / cycle_k) summed to more than that)."""
    _, j = crushCycle(monkeypatch, CycleJumper(window=2, steady=0.2, maxDamage=0.02, margin=0, growth=1000.0))
    assert len(j.jumps) > 5
    to = np.array([e['to'] for e in j.jumps], float)
    n = to - np.cumsum([e['cycles'] for e in j.jumps])
    total = np.array([e['settlementJumpedTotal'] for e in j.jumps])
    law = np.array([e['settlementLawB'] is not None for e in j.jumps])   # none below 3 simulated cycles: 0
    assert law[-1] and not law[0]
    np.testing.assert_allclose(total, np.where(law, 1e-4 * np.log(to / n), 0), rtol=1e-9, atol=1e-18)
    np.testing.assert_allclose(np.cumsum([e['settlementJumped'] for e in j.jumps]), total, rtol=1e-12, atol=1e-18)
    old = sum(1e-4 * math.log(e['to'] / e['cycle']) for e in j.jumps if e['settlementLawB'] is not None)
    assert old > 1.05 * total[-1]    # the old per-jump sum counted the cycles jumped before again


def jumperOnGrain(monkeypatch, **kw):
    """The fatigue grain and a jumper for a run of 100 cycles: (grain, engine, jumper)."""
    g, crush = fatigueGrain(monkeypatch)
    j = CycleJumper(steady=0.2, maxDamage=0.99, growth=1000.0, **kw)
    j.target = 100
    return g, crush, j


def test_the_jumpers_state_comes_back_whole(monkeypatch):
    g, crush, j = jumperOnGrain(monkeypatch, window=3, margin=1, after=2, driftNoise=1.5, driftDamage=2e-3)
    for cycle in range(1, 5):
        O.run(PER_CYCLE, True)
        plan = j.cycleEnded(crush, [g], cycle, 1e-4 * cycle, False)
    assert plan is not None
    back = CycleJumper.fromState(j.state())
    for k in ('window', 'steady', 'maxDamage', 'margin', 'growth', 'after', 'driftNoise', 'driftDamage', 'target', 'ids',
              'direct', 'jumps', 'jumped', 'on'):
        assert getattr(back, k) == getattr(j, k), k
    old = {k: v for k, v in j.state().items() if k not in ('driftNoise', 'driftDamage')}   # saved before they existed
    assert (CycleJumper.fromState(old).driftNoise, CycleJumper.fromState(old).driftDamage) == (0.0, 0.0)
    np.testing.assert_array_equal(back.last, j.last)
    assert all(np.array_equal(a, b) for a, b in zip(back.increments, j.increments))
    assert back.pending['cycles'] == plan['cycles'] and np.array_equal(back.pending['rate'], plan['rate'])


def test_a_crush_or_a_new_grain_restarts_the_window(monkeypatch):
    g, crush, j = jumperOnGrain(monkeypatch, window=2, margin=0)
    for cycle in range(1, 3):
        O.run(PER_CYCLE, True)
        assert j.cycleEnded(crush, [g], cycle, 0.0, False) is None
    O.run(PER_CYCLE, True)
    assert j.cycleEnded(crush, [g], 3, 0.0, True) is None and j.increments == []   # a crush in cycle 3
    O.run(PER_CYCLE, True)
    assert j.cycleEnded(crush, [g], 4, 0.0, False) is None and len(j.increments) == 1
    O.run(PER_CYCLE, True)
    assert j.cycleEnded(crush, [g], 5, 0.0, False) is not None                     # two steady cycles again


def test_growth_at_most_doubles_the_count_and_the_crush_stays_in_cycle_61(monkeypatch):
    cycle, j = crushCycle(monkeypatch, CycleJumper(window=2, steady=0.2, maxDamage=0.99, margin=0, growth=1.0))
    assert cycle == CRUSH_CYCLE and len(j.jumps) >= 2
    assert all(e['to'] <= 2 * e['cycle'] for e in j.jumps) and j.jumps[0]['limit'] == 'growth'
    # no grain bounded a jump the growth bounded: its grain is empty (it was -1, a body id that is none)
    assert all((e['grain'] is None) == (e['limit'] in ('growth', 'remaining')) for e in j.jumps)


def test_no_jump_before_jump_after(monkeypatch):
    cycle, j = crushCycle(monkeypatch, CycleJumper(window=2, steady=0.2, maxDamage=0.99, margin=0, growth=1000.0,
                                                   after=30))
    assert cycle == CRUSH_CYCLE and j.jumps and j.jumps[0]['cycle'] == 30
