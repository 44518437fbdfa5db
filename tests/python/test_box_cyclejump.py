"""Cycle jumping in the box test (docs/cycles.md), on the small box of test_box_experiment.py made weak enough for
fatigue damage to grow every cycle without a crush (ft0 8e4 Pa m, fatigueExponent 10): the jumps and their
records, the cycle count with the jumped cycles, each jump's damage within its bound, the states around a jump
reopen and go on (a killed run too, resumed), and a run whose jumps are never allowed is the run without jumping,
bit for bit."""
import os

import numpy as np
import pandas as pd
import pytest

pytest.importorskip('yade')
from ballast.experiments.box import BoxTest  # noqa: E402
from ballast.params import ParamError  # noqa: E402
from ballast.settlementlaws import bedChanged, settlementJumped  # noqa: E402
from test_box_experiment import SMALL  # noqa: E402

WEAK = dict(SMALL, ft0=8e4, fatigue=True, fatigueExponent=10, cycles=14, progress=600)
JUMP = dict(jump=True, jumpWindow=3, jumpSteady=1.0, jumpMaxDamage=0.3, jumpMargin=0)


@pytest.fixture(scope='module')
def beds(tmp_path_factory):
    return str(tmp_path_factory.mktemp('beds'))


@pytest.fixture(scope='module')
def jumped(tmp_path_factory, beds):
    test = BoxTest(results=str(tmp_path_factory.mktemp('jump')), runId='jump', bedDir=beds, **WEAK, **JUMP)
    return test, test.run()


def test_a_jumped_run_reaches_its_cycles_and_records_every_jump(jumped):
    test, s = jumped
    cyc = pd.read_csv(os.path.join(test.out, 'cycles.csv'))
    jumps = pd.read_csv(os.path.join(test.out, 'jumps.csv'))
    assert s['cycles'] == 14 and cyc.cycle.iloc[-1] == 14 and s['jumps'] == len(jumps) >= 1
    assert s['cyclesSimulated'] == len(cyc) and s['cyclesSimulated'] + s['cyclesJumped'] == 14
    # each row's number is its rank among the simulated cycles plus the cycles jumped before it
    assert np.array_equal(cyc.cycle, np.arange(1, len(cyc) + 1) + cyc.jumped)
    assert jumps.cycles.sum() == s['cyclesJumped'] and np.all(jumps.to == jumps.cycle + jumps.cycles)
    # the first WINDOW + 1 cycles are simulated, the last one too
    assert list(cyc.cycle[:4]) == [1, 2, 3, 4] and cyc.jumped.iloc[-1] == s['cyclesJumped']
    # the jumped cycles' settlement: b ln(N / n) at the n-th simulated cycle, b of a + b ln k fitted to k = ceil(n/2)..n
    n = np.arange(1, len(cyc) + 1)
    b = [np.polyfit(np.log(n[(k + 1) // 2 - 1:k]), cyc.settlement[(k + 1) // 2 - 1:k], 1)[0]
         if k - (k + 1) // 2 + 1 >= 3 else 0.0 for k in n]
    np.testing.assert_allclose(cyc.settlementJumped, b * np.log(cyc.cycle / n), rtol=1e-6, atol=1e-12)
    assert s['settlementJumped'] == pytest.approx(cyc.settlementJumped.iloc[-1], rel=1e-6, abs=1e-12)
    assert s['settlementTotal'] == pytest.approx(s['settlement'] + s['settlementJumped'], rel=1e-12)
    for name in list(jumps.stateBefore) + list(jumps.stateAfter):
        assert os.path.isfile(os.path.join(test.out, name))


def test_keeping_the_last_jumps_states_only_changes_nothing_else(jumped, tmp_path, beds):
    """jumpStates 'last': the same cycles and jumps, only the latest jump's two states left on disk."""
    test, _ = jumped
    last = BoxTest(results=str(tmp_path), runId='last', bedDir=beds, jumpStates='last', **WEAK, **JUMP)
    last.run()
    read = lambda t, name: pd.read_csv(os.path.join(t.out, name))  # noqa: E731
    ref, got = read(test, 'jumps.csv'), read(last, 'jumps.csv')
    assert len(ref) >= 2, 'the run needs two jumps for an earlier pair to be removed'
    names = ['stateBefore', 'stateAfter']
    pd.testing.assert_frame_equal(ref.drop(columns=names), got.drop(columns=names), check_exact=True)
    pd.testing.assert_frame_equal(read(test, 'cycles.csv').drop(columns='cpuSeconds'),
                                  read(last, 'cycles.csv').drop(columns='cpuSeconds'), check_exact=True)
    assert got[names].iloc[:-1].isna().all().all() and list(got[names].iloc[-1]) == list(ref[names].iloc[-1])
    onDisk = sorted(f for f in os.listdir(last.out) if f.startswith('state-jump'))
    assert onDisk == sorted(ref[names].iloc[-1]) and not any('state-jump' in f and os.path.basename(f) not in onDisk
                                                             for f in last.saved)


def test_a_slice_keeping_the_last_states_leaves_those_of_the_run_it_continues(jumped, tmp_path, beds):
    test, s = jumped
    before = sorted(f for f in os.listdir(test.out) if f.startswith('state-jump'))
    cycles = 2 * s['cycles']
    last = BoxTest(results=str(tmp_path), runId='slice', bedDir=beds, jumpStates='last',
                   continueFrom=os.path.join(test.out, 'state-end.yade.gz'), **dict(WEAK, cycles=cycles), **JUMP)
    out = os.path.join(str(tmp_path), last.run()['runId'])
    ref, got = (pd.read_csv(os.path.join(d, 'jumps.csv')) for d in (test.out, out))
    assert len(got) >= len(ref) + 2, 'the slice needs two jumps of its own'
    assert sorted(f for f in os.listdir(test.out) if f.startswith('state-jump')) == before   # untouched
    names = ['stateBefore', 'stateAfter']
    pd.testing.assert_frame_equal(got[names].iloc[:len(ref)], ref[names])   # the earlier run's names kept
    assert got[names].iloc[len(ref):-1].isna().all().all()
    assert sorted(f for f in os.listdir(out) if f.startswith('state-jump')) == sorted(got[names].iloc[-1])


def test_a_jump_moves_every_grains_damage_within_its_bound_and_nothing_else(jumped):
    from yade import O
    from ballast.experiments import chain, grains
    test, _ = jumped
    jumps = pd.read_csv(os.path.join(test.out, 'jumps.csv'))
    e = jumps.iloc[0]
    states = {}
    for k in ('stateBefore', 'stateAfter'):
        run = BoxTest.reopen(os.path.join(test.out, e[k]), readOnly=True)
        ids = [b.id for b in grains.spheres()]
        states[k] = (np.array([list(O.bodies[i].state.pos) for i in ids]), run.recorder.jumped, O.iter,
                     chain.engine('crush').fatigueState(ids)[:, 0])
    (x0, j0, i0, D0), (x1, j1, i1, D1) = states['stateBefore'], states['stateAfter']
    assert np.array_equal(x0, x1) and i0 == i1                  # no grain moves, no step is taken
    assert j1 - j0 == e.cycles
    grow = D1 - D0
    assert np.all(grow >= 0) and grow.max() <= JUMP['jumpMaxDamage'] + 1e-12 and grow.max() > 0
    assert D1.max() == pytest.approx(e.maxDamage, rel=1e-8)   # jumps.csv keeps 9 digits


def test_the_state_after_a_jump_reopens_and_goes_on(jumped, tmp_path):
    test, _ = jumped
    jumps = pd.read_csv(os.path.join(test.out, 'jumps.csv'))
    e = jumps.iloc[-1]
    run = BoxTest.reopen(os.path.join(test.out, e.stateAfter), results=str(tmp_path), runId='after')
    s = run.load(2)
    cyc = pd.read_csv(os.path.join(run.out, 'cycles.csv'))
    assert s['cycles'] == cyc.cycle.iloc[-1] and cyc.cycle.iloc[-1] >= e.to + 2
    assert cyc.jumped.iloc[-1] >= jumps.cycles.sum() - 0   # the jumps so far are counted in the reopened run


def test_a_run_whose_jumps_are_never_allowed_is_the_run_without_jumping(tmp_path, beds):
    """jumpMaxDamage 1e-12: every damaged grain allows no jump (its rate is far above 1e-12 a cycle)."""
    cols = ['cycle', 't', 'settlement', 'settlementPeak', 'resilient', 'work', 'crushes', 'abrasions', 'nCrushed',
            'nAbraded', 'maxDamage', 'maxStressRatio', 'nGrains', 'tilt']
    out = {}
    for name, extra in (('off', {}), ('never', dict(JUMP, jumpMaxDamage=1e-12))):
        test = BoxTest(results=str(tmp_path), runId=name, bedDir=beds, **dict(WEAK, cycles=6), **extra)
        s = test.run()
        out[name] = pd.read_csv(os.path.join(test.out, 'cycles.csv'))[cols]
        if name == 'never':
            assert s['jumps'] == 0 and s['cyclesJumped'] == 0
    assert out['off'].maxDamage.iloc[-1] > 0
    pd.testing.assert_frame_equal(out['off'], out['never'], check_exact=True)


def test_jumping_needs_fatigue():
    with pytest.raises(ParamError, match='jump = True is not allowed: cycle jumping advances fatigue damage'):
        BoxTest(**dict(SMALL, jump=True))


def test_a_run_without_jumping_goes_on_with_it_in_a_slice(tmp_path, beds):
    """A long run's slice (continueFrom) may switch jumping on: the slice jumps, its cycles counted on from the
    saved run's."""
    first = BoxTest(results=str(tmp_path), runId='direct', bedDir=beds, **dict(WEAK, cycles=3))
    first.run()
    test = BoxTest(results=str(tmp_path), runId='slice', bedDir=beds, continueFrom=os.path.join(first.out,
                   'state-end.yade.gz'), **dict(WEAK, cycles=12), **JUMP)
    s = test.run()
    cyc = pd.read_csv(os.path.join(str(tmp_path), s['runId'], 'cycles.csv'))
    assert s['cycles'] == 15 and s['jumps'] >= 1 and cyc.cycle.iloc[-1] == 15 and cyc.jumped.iloc[-1] > 0
    assert list(cyc.cycle[:3]) == [1, 2, 3]                     # the saved run's cycles, simulated without jumps
    # each jump extrapolates as cycles.csv does, over every simulated cycle before it, the saved run's included
    # (n counted them: before 2026-12-05 the slice's jumper had seen only its own)
    jumps = pd.read_csv(os.path.join(str(tmp_path), s['runId'], 'jumps.csv'))
    for _, e in jumps.iterrows():
        rows = cyc[cyc.cycle <= e.cycle]
        N = np.append(rows.cycle.to_numpy()[:-1], e.to)
        want = settlementJumped(N, rows.settlement, bedChanged(rows.crushes.to_numpy(), rows.abrasions.to_numpy()))
        assert e.settlementJumpedTotal == pytest.approx(want[-1], rel=1e-6, abs=1e-12)
    assert jumps.settlementJumped.sum() == pytest.approx(jumps.settlementJumpedTotal.iloc[-1], rel=1e-9, abs=1e-15)


def test_a_killed_run_resumed_after_a_jump_forgets_the_later_jumps_of_the_killed_process(jumped, tmp_path, beds):
    """resume with cycle jumping: the run killed after its last jump's state, as if its process had jumped once more
    before it died (a row in jumps.csv, that jump's states on disk), goes on from that state: jumps.csv back to the
    state's jumps (and those taken since), the later jump's states gone, the run at its cycles."""
    from ballast.experiments.cyclic import JUMP_STATE
    from killed import killedCopy
    test, s = jumped
    jumps = pd.read_csv(os.path.join(test.out, 'jumps.csv'))
    folder = killedCopy(test, str(tmp_path), jumps.stateAfter.iloc[-1])
    k = len(jumps) + 1
    ghost = [JUMP_STATE % (k, w) for w in ('before', 'after')]
    for name in ghost:
        with open(os.path.join(folder, name), 'w') as fh:
            fh.write('a state of the killed process')
    pd.concat([jumps, jumps.iloc[[-1]].assign(stateBefore=ghost[0], stateAfter=ghost[1])]).to_csv(
        os.path.join(folder, 'jumps.csv'), index=False)
    s2 = BoxTest(results=str(tmp_path), runId=test.runId, resume=True, bedDir=beds, **WEAK, **JUMP).run()
    got = pd.read_csv(os.path.join(folder, 'jumps.csv'))
    assert s2['cycles'] == s['cycles'] and len(got) == s2['jumps'] >= len(jumps)
    pd.testing.assert_frame_equal(got.iloc[:len(jumps)], jumps)
    onDisk = [f for f in os.listdir(folder) if f.startswith('state-jump')]
    assert sorted(onDisk) == sorted(set(got.stateBefore) | set(got.stateAfter))
