"""ballast.analysis.jumps on records made by hand (no YADE): the cycle of a crush in the count with jumped cycles,
the pairing of direct and jumping runs, each tolerance deciding agreement, the long runs, the figure; and
analysis.settlement reading a jumped run's settlement with its extrapolated part."""
import json
import os

import numpy as np
import pandas as pd
import pytest

from ballast.analysis import jumps, settlement

T = 0.025   # [s] a load cycle


def run(root, rid, seed, cycles, jump, rows, crushT, jumped=None, cpu=10.0):
    """A record: rows the cycles.csv cycle numbers of the simulated cycles (the n-th ends at n T), crushes at
    times crushT [s], settlement 1e-4 n (plus 1e-5 per jumped cycle when jumping)."""
    d = os.path.join(root, 'runs', rid)
    os.makedirs(d)
    rows = np.asarray(rows)
    n = np.arange(1, len(rows) + 1)
    c = pd.DataFrame({'cycle': rows, 't': n * T, 'settlement': 1e-4 * n})
    if jump:
        c['jumped'] = rows - n
        c['settlementJumped'] = 1e-5 * (rows - n)
    c.to_csv(os.path.join(d, 'cycles.csv'), index=False)
    pd.DataFrame({'t': crushT, 'radius': 0.01, 'ratio': 1.0}).to_csv(os.path.join(d, 'crushes.csv'), index=False)
    s = {'params': {'seed': seed, 'cycles': cycles, 'jump': jump}, 'nCrushed': len(crushT), 'cpuSeconds': cpu,
         'cycles': int(rows[-1])}
    if jump:
        s.update(cyclesSimulated=len(rows), jumps=1, settlementJumped=float(c.settlementJumped.iloc[-1]))
    with open(os.path.join(d, 'summary.json'), 'w') as fh:
        json.dump(s, fh)
    return {'line': 0, 'runId': rid, 'row': {}}


def study(root, specs):
    rows = [run(root, *spec) for spec in specs]
    with open(os.path.join(root, 'study.json'), 'w') as fh:
        json.dump({'experiment': 'box', 'rows': rows}, fh)
    return root


def test_a_crush_is_counted_in_the_cycle_of_its_simulated_row(tmp_path):
    """Rows 1, 2, 3, 4, 8, 9, 10: a crush during the 5th simulated cycle (t in (4T, 5T]) is in cycle 8."""
    root = study(str(tmp_path), [('j', 1, 10, True, [1, 2, 3, 4, 8, 9, 10], [2.5 * T, 4.5 * T, 5 * T])])
    r = jumps._runs(root).iloc[0].run
    assert list(jumps.crushCycles(r)) == [3, 8, 8]


def test_pairs_agree_within_the_stated_tolerances_and_not_beyond(tmp_path):
    root = study(str(tmp_path), [
        ('d1', 1, 10, False, range(1, 11), [2.5 * T, 6.5 * T], None, 20.0),
        ('j1', 1, 10, True, [1, 2, 3, 4, 8, 9, 10], [2.5 * T, 4.5 * T], None, 8.0),  # crushes in 3 and 8 (7 directly)
        ('d2', 2, 10, False, range(1, 11), [0.5 * T] * 5, None, 20.0),
        ('j2', 2, 10, True, [1, 2, 3, 4, 9, 10], [5.5 * T], None, 5.0),              # one crush in cycle 10, not 1
        ('long', 2, 100000, True, [1, 2, 100000], [], None, 30.0)])
    t = jumps.compare(root).set_index('seed')
    a = t.loc[1]
    assert (a.crush1Direct, a.crush1Jump, a.crush2Direct, a.crush2Jump) == (3, 3, 7, 8)
    assert a.crush1Agrees and a.crush2Agrees and a.crush3Agrees            # 7 against 8: within 2 cycles; no 3rd
    assert a.crushesAgree and a.cpuRatio == pytest.approx(0.4)
    # settlement: 1e-3 directly against 7e-4 + b ln(10 / 7) with b of the 7 simulated cycles' law, 0.81e-3: 19 %
    # off, within 25 %
    assert a.settlementDirect == pytest.approx(1e-3) and a.settlementJump == pytest.approx(law(7, 10), rel=1e-9)
    assert a.settlementAgrees
    b = t.loc[2]
    assert b.crush1Direct == 1 and b.crush1Jump == 10 and not b.crush1Agrees
    assert b.crush2Direct == 1 and pd.isna(b.crush2Jump) and not b.crush2Agrees          # none to compare
    assert not b.crushesAgree                                               # 1 against 5: more than 2 and 20 %
    assert b.settlementJump == pytest.approx(law(6, 10), rel=1e-9)
    assert b.settlementAgrees == (abs(law(6, 10) - 1e-3) <= max(0.25 * 1e-3, 5e-5))
    assert jumps.verdict(jumps.compare(root))['crush1Agrees'] == '1 of 2'
    long = jumps.longRuns(root)
    assert list(long.runId) == ['long'] and long.cycles.iloc[0] == 100000 and long.simulated.iloc[0] == 3
    # its extrapolation as today's law gives it from cycles.csv (3 simulated rows: no law yet, 0), not the summary's
    assert long.settlementJumped.iloc[0] == 0.0 and long.settlement.iloc[0] == pytest.approx(3e-4, rel=1e-12)
    out = str(tmp_path / 'jumps.png')
    jumps.figure(root, out)
    assert os.path.getsize(out) > 0


def test_a_long_run_is_compared_with_the_direct_run_over_the_cycles_both_cover(tmp_path):
    """Seed 1: direct over 10 cycles, crushes in cycles 3 and 7; the long run simulates 1-4, 8, 9, 12, 100 with
    crushes in cycles 3 (2.5 T), 8 (4.5 T) and 100 (7.5 T): over cycles 1-10 both crush twice (3, 7 against 3,
    8: within 2 cycles); its settlement at cycle 9 (its last simulated cycle up to 10) is 6e-4 + b ln(9 / 6);
    a run of seed 2 without a direct run of its seed is not compared."""
    root = study(str(tmp_path), [
        ('d1', 1, 10, False, range(1, 11), [2.5 * T, 6.5 * T], None, 20.0),
        ('long1', 1, 100, True, [1, 2, 3, 4, 8, 9, 12, 100], [2.5 * T, 4.5 * T, 7.5 * T], None, 5.0),
        ('long2', 2, 100, True, [1, 2, 100], [], None, 5.0)])
    t = jumps.covered(root)
    assert list(t.runId) == ['long1']
    r = t.iloc[0]
    assert (r.covered, r.settledAt, r.crushesDirect, r.crushesJump) == (10, 9, 2, 2)
    assert (r.crush1Direct, r.crush1Jump, r.crush2Direct, r.crush2Jump) == (3, 3, 7, 8)
    assert r.crush1Agrees and r.crush2Agrees and r.crush3Agrees and r.crushesAgree
    assert r.settlementJump == pytest.approx(law(6, 9), rel=1e-9) and r.cpuRatio == pytest.approx(0.25)
    assert r.settlementAgrees == (abs(law(6, 9) - 1e-3) <= 0.25e-3)
    # five crushes in cycle 9 of the long run: 9 against 3 is beyond 2 cycles and 10 %, 5 against 2 beyond 2 and 20 %
    root2 = study(str(tmp_path / 'b'), [
        ('d1', 1, 10, False, range(1, 11), [2.5 * T, 6.5 * T], None, 20.0),
        ('long1', 1, 100, True, [1, 2, 3, 4, 8, 9, 12, 100], [5.5 * T] * 5, None, 5.0)])
    r = jumps.covered(root2).iloc[0]
    assert r.crushesJump == 5 and not r.crushesAgree and r.crush1Jump == 9 and not r.crush1Agrees


def law(n, N):
    """The settlement after the n-th simulated cycle, cycle N of the count, of these records: 1e-4 n plus the
    jumped cycles' b ln(N / n), b of s = a + b ln k fitted to k = ceil(n / 2)..n."""
    k = np.arange((n + 1) // 2, n + 1)
    return 1e-4 * n + np.polyfit(np.log(k), 1e-4 * k, 1)[0] * np.log(N / n)


def test_the_settlement_curves_of_a_jumped_run_include_the_jumped_cycles(tmp_path):
    root = study(str(tmp_path), [('j', 1, 10, True, [1, 2, 3, 4, 8, 9, 10], [])])
    frame = settlement.curves([root])
    assert frame.settlement.iloc[-1] == pytest.approx(law(7, 10), rel=1e-9)


def test_the_command_line_writes_its_files_and_refuses_a_folder_that_is_no_study(tmp_path, capsys):
    import runpy
    script = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), 'scripts',
                          'jump_validation.py')
    main = runpy.run_path(script)['main']
    root = study(str(tmp_path / 's'), [('d1', 1, 10, False, range(1, 11), [2.5 * T]),
                                       ('j1', 1, 10, True, [1, 2, 3, 4, 8, 9, 10], [2.5 * T])])
    out = str(tmp_path / 'out')
    assert main([root, '--out', out]) == 0
    for name in ('validation.csv', 'covered.csv', 'long.csv', 'validation.json', 'jumps.png'):
        assert os.path.getsize(os.path.join(out, name)) > 0
    with open(os.path.join(out, 'validation.json')) as fh:
        assert json.load(fh)['agree']['crush1Agrees'] == '1 of 1'
    # a variant's jumping runs against the direct runs of another study
    variant = study(str(tmp_path / 'v'), [('j1', 1, 10, True, [1, 2, 3, 4, 5, 9, 10], [2.5 * T])])
    assert main([variant, '--reference', root, '--out', out]) == 0
    t = pd.read_csv(os.path.join(out, 'validation.csv'))
    assert len(t) == 1 and t.simulatedJump.iloc[0] == 7 and t.simulatedDirect.iloc[0] == 10
    assert main([str(tmp_path / 'nothing'), '--out', out]) == 2
    assert 'no such directory' in capsys.readouterr().err
