"""ballast.experiments.box: the box test in YADE on a small box (about 250 grains of 20-30 mm, soft
grains for a long step, 40 Hz): the sleeper at rest carries the applied load and its weight; a short run
end to end writes every output, its mass ledger is exact, its crushes are all mapped, its cycles and
gradings are where they should be; a saved state reopens and goes on (the command line: test_commandline.py)."""
import json
import os
import shutil
import socket
import subprocess

import numpy as np
import pandas as pd
import pytest

pytest.importorskip('yade')
from ballast.experiments.box import BoxTest  # noqa: E402
from ballast.experiments.box.zones import ZONES  # noqa: E402
from ballast.params import ParamError  # noqa: E402
from killed import killedCopy  # noqa: E402
from yade import O  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

SMALL = dict(boxLength=0.3, boxWidth=0.12, bedDepth=0.1, layers=2, sleeperWidth=0.1, sleeperHeight=0.05, sleeperMass=5,
             dMin=0.02, dMax=0.03, young=3e9, prepYoung=3e8, f=40, seatLoad=300, peakLoad=4000, cycles=3, ft0=3.5e4,
             rMin=0.008, strength=1.5e10, progress=60)
TOL_EQUILIBRIUM = 0.02   # [-] the grains' force on the sleeper, averaged over 2000 steps, against load + weight:
#                          the sleeper still creeps into the bed of spheres at about 3 mm/s (m a ~ 1e-3 of it)
G = 9.81
TOL_RESUME = 2e-3        # [-] a resumed cycle's settlement against the run that went on (measured 5e-4, see the test)


@pytest.fixture(scope='module')
def run(tmp_path_factory):
    test = BoxTest(results=str(tmp_path_factory.mktemp('box')), runId='small', vtk=1, saveEvery=2, **SMALL)
    summary = test.run()
    return test, summary


def test_the_seated_sleeper_carries_the_applied_load_and_its_weight(tmp_path):
    from yade import O
    test = BoxTest(results=str(tmp_path), crush=False, abrasion=False, **SMALL).prepare()
    rec = test.recorder
    F = []
    for _ in range(20):
        O.run(100, True)
        F.append(rec.grainsForce())
    assert rec.applied() == pytest.approx(300.0, rel=1e-12)
    assert np.mean(F) == pytest.approx(300.0 + 5 * G, rel=TOL_EQUILIBRIUM)
    assert O.bodies[rec.sleeper].state.mass == pytest.approx(5.0, rel=1e-12)


def test_crib_ballast_lies_beside_the_sleeper_up_to_its_depth(tmp_path):
    from yade import O
    from ballast.experiments import grains
    test = BoxTest(results=str(tmp_path), crush=False, abrasion=False, cribDepth=0.04, **SMALL).prepare()
    assert test.nCrib > 0
    s = O.bodies[test.recorder.sleeper]
    base = s.state.pos[2] - s.shape.extents[2]
    x, r, _ = grains.arrays()
    above = x[:, 2] - r > base + 1e-3            # grains wholly above the sleeper's underside: the crib
    assert np.sum(above) > 0.5 * test.nCrib
    assert np.all(np.abs(x[above, 0]) > SMALL['sleeperWidth'] / 2)   # none on or under the sleeper
    # a crib of 0.04 m is under two grains deep here: its grains' tops mostly within one grain of it
    assert np.median(x[above, 2] + r[above]) < base + 0.04 + SMALL['dMax']
    assert test.nCrib == pytest.approx(0.6 * 2 * 0.1 * 0.12 * 0.04 / (np.pi / 6 * 0.025 ** 3), rel=0.5)
    F = []
    for _ in range(10):
        O.run(100, True)
        F.append(test.recorder.grainsForce())
    assert np.mean(F) == pytest.approx(300.0 + 5 * G, rel=TOL_EQUILIBRIUM)   # the crib does not load the sleeper


def test_a_short_run_writes_every_output(run):
    test, s = run
    for name in ('cycles.csv', 'samples.csv', 'grading.csv', 'crushes.csv', 'zones.csv', 'summary.json',
                 'settlement.png', 'breakage.png', 'grading.png', 'state-start.yade.gz', 'state-end.yade.gz'):
        assert os.path.isfile(os.path.join(test.out, name)), name
    cyc = pd.read_csv(os.path.join(test.out, 'cycles.csv'))
    # a warning, once, exactly where cycles.csv leaves the range of a box test (this weak bed: 29 mm in 100 mm)
    said = [w.split()[0] for w in s['warnings']]
    assert said.count('settlement') == int(bool((cyc.settlement > 0.25 * SMALL['bedDepth']).any()))
    assert said.count('tilt') == int(bool((cyc.tilt.abs() > 0.05).any())) and len(said) <= 2
    assert list(cyc.cycle) == [1, 2, 3] and s['cycles'] == 3
    assert np.allclose(cyc.t, [0.025, 0.05, 0.075], atol=0.025 / SMALL.get('samples', 100) + 1e-4)
    assert s['settlement'] == pytest.approx(cyc.settlement.iloc[-1], rel=1e-8)
    samples = pd.read_csv(os.path.join(test.out, 'samples.csv'))
    # the applied load is the sine between the seat and the peak at every sample
    tau = np.mod(samples.t, 0.025)
    assert np.allclose(samples.F, 300 + 3700 * 0.5 * (1 - np.cos(2 * np.pi * 40 * tau)), atol=4000 * 1e-3)
    assert (cyc.resilient >= 0).all() and (cyc.settlementPeak >= cyc.settlement - 1e-12).all()
    # the quasi-static measures (experiments.quasistatic): each cycle's largest and median inertial number are those
    # of its samples, the steps of a cycle T / dt (to the samples' step), the response ratio from the resilient stiffness
    first = samples[samples.t <= cyc.t[0]].inertialNumber.dropna()   # the first cycle's samples, its close included
    assert cyc.inertialMax[0] == pytest.approx(first.max(), rel=1e-6)
    assert cyc.inertialMedian[0] == pytest.approx(first.median(), rel=1e-6)
    steady = np.flatnonzero(cyc.dt.to_numpy()[1:] == cyc.dt.to_numpy()[:-1]) + 1   # cycles at an unchanged step
    assert len(steady) and (cyc.stepsPerCycle > 0).all()
    np.testing.assert_allclose(cyc.stepsPerCycle[steady], 0.025 / cyc.dt[steady], rtol=0.02)
    # no resilient deflection (the bed crushes and the sleeper sinks on through the cycle): no stiffness, no ratio
    assert (np.isnan(cyc.responseRatio) == (cyc.resilient == 0)).all() and not (cyc.responseRatio <= 1).any()
    with open(os.path.join(test.out, 'summary.json')) as fh:
        assert json.load(fh)['nCrushed'] == s['nCrushed']


def test_vtk_frames_every_vtk_cycles_for_paraview(run):
    """vtk = 1 (cycles, as in every experiment): a frame at the start of cycling, after each of the 3 cycles and at
    the end, each of three files named by the step, listed in boxes.pvd at its loading time; the last has every grain."""
    test, s = run
    frames = test.frames
    T = 1 / SMALL['f']
    assert [f[0] for f in frames[:4]] == pytest.approx([0, T, 2 * T, 3 * T], abs=2 * s['dt'])
    # and the state at the end, a few samples past the last cycle's close (where the run stops)
    assert len(frames) == 5 and 3 * T < frames[-1][0] <= 3 * T + 3 * T / test.p['samples']
    with open(os.path.join(test.out, 'boxes.pvd')) as fh:
        pvd = fh.read()
    for frame in frames:
        for part, name in zip(('grains', 'contacts', 'sleeper'), frame[1:]):
            assert name.startswith('vtk/%s-' % part) and name in pvd and os.path.isfile(os.path.join(test.out, name))
    with open(os.path.join(test.out, frames[-1][1])) as fh:
        assert 'NumberOfPoints="%d"' % s['nGrains'] in fh.read()


def test_the_mass_ledger_is_exact(run):
    test, s = run
    assert s['nCrushed'] > 0, 'the small box is meant to crush a few grains'
    assert abs(s['massLedgerError']) <= 1e-12 * s['massInitial']
    assert s['massGrains'] + s['massLost'] == pytest.approx(s['massInitial'], rel=1e-12)


def test_abrasion_under_the_rolling_law_keeps_the_ledger(tmp_path):
    """strength below eq. 7's pressure of the linear law (3 E / pi = 2.86e9 Pa at E = 3e9): grains in contact
    abrade at each check; what they lose is in the ledger to the last digit."""
    test = BoxTest(results=str(tmp_path), **dict(SMALL, crush=False, strength=2e9, abrasionPeriod=400, cycles=1))
    s = test.run()
    assert s['nAbraded'] > 0 and s['massLost'] > 0 and s['params']['rollingFriction'] == 0.3
    assert abs(s['massLedgerError']) <= 1e-12 * s['massInitial']
    # nothing crushed: no depth of the crushes, written as JSON's null (Python's NaN is no JSON)
    with open(os.path.join(test.out, 'summary.json')) as fh:
        written = json.loads(fh.read(), parse_constant=lambda c: pytest.fail('summary.json holds %s' % c))
    assert s['nCrushed'] == 0 and written['local'] == {'crushedShare': 0.0, 'underShare': None, 'depthMedian': None,
                                                       'depth90': None}


def test_every_crush_is_mapped_once(run):
    test, s = run
    c = pd.read_csv(os.path.join(test.out, 'crushes.csv'))
    assert len(c) == s['nCrushed'] and set(c.zone) <= set(ZONES)
    assert sum(sum(s['zones'][z]) for z in ZONES) == s['nCrushed']
    z = pd.read_csv(os.path.join(test.out, 'zones.csv'))
    assert int(z[list(ZONES)].to_numpy().sum()) == s['nCrushed']
    assert (c.cycle >= 1).all() and (c.cycle <= 3).all()
    assert 0 < s['local']['crushedShare'] <= s['nCrushed'] / s['nGrainsInitial']


def test_gradings_after_the_graded_cycles(run):
    test, s = run
    g = pd.read_csv(os.path.join(test.out, 'grading.csv'))
    assert list(g.cycle) == [0, 1, 2, 3]   # 1, 2 of the 1-2-5 series and the last
    assert g.loc[0, 'Bg'] == 0 and g.loc[0, 'BBI'] == 0
    assert (np.diff(g.Bg) >= -1e-12).all() and g.Bg.iloc[-1] > 0   # grains crushed: the grading moved


def test_the_bed_is_stored_and_a_second_run_of_the_seed_repeats_the_first(run):
    test, s = run
    assert os.path.isfile(s['bedFile']) and os.path.dirname(s['bedFile']) == os.path.join(test.p['results'], 'beds')
    again = BoxTest(results=test.p['results'], runId='again', **SMALL)
    s2 = again.run()
    assert s2['bedFile'] == s['bedFile']   # reused, not built again
    a = pd.read_csv(os.path.join(test.out, 'cycles.csv')).drop(columns='cpuSeconds')
    b = pd.read_csv(os.path.join(again.out, 'cycles.csv')).drop(columns='cpuSeconds')
    pd.testing.assert_frame_equal(a, b)
    assert s2['nCrushed'] == s['nCrushed']


def test_a_saved_state_reopens_and_goes_on(run, tmp_path):
    test, s = run
    again = BoxTest.reopen(os.path.join(test.out, 'state-end.yade.gz'), results=str(tmp_path))
    assert len(again.recorder.samples) <= 2   # a state keeps the current cycle's samples only (one at its end)
    s2 = again.load(1)
    cyc = pd.read_csv(os.path.join(again.out, 'cycles.csv'))
    old = pd.read_csv(os.path.join(test.out, 'cycles.csv'))
    assert list(cyc.cycle) == [1, 2, 3, 4] and s2['cycles'] == 4
    pd.testing.assert_frame_equal(cyc.iloc[:3].drop(columns='cpuSeconds'), old.drop(columns='cpuSeconds'))
    assert cyc.cpuSeconds.iloc[3] > 0   # counted from the restore (this process's clock)
    assert s2['nCrushed'] >= s['nCrushed'] and abs(s2['massLedgerError']) <= 1e-12 * s2['massInitial']


def test_a_long_run_killed_goes_on_from_its_last_state(run, tmp_path):
    """saveEvery 2: a state at the start of the step after cycle 2 closed; reopened, cycle 3 comes out as in the
    run that went on, to TOL_RESUME of its settlement: YADE resumes a scene to rounding only
    (test_oedometer_experiment.py), which a bed of spheres under a sleeper amplifies; measured without crushing
    on this box: 5e-4 with the sleeper level, 2e-2 with it free to tilt, so the test holds it level."""
    test, s = run
    assert os.path.isfile(os.path.join(test.out, 'state-cycle0000002.yade.gz'))
    quiet = BoxTest(results=str(tmp_path), runId='quiet', saveEvery=2,
                    **dict(SMALL, crush=False, abrasion=False, tilt=False))
    quiet.run()
    again = BoxTest.reopen(os.path.join(quiet.out, 'state-cycle0000002.yade.gz'), runId='resumed')
    assert again.cyclesDone() == 2
    again.load(1)
    a = pd.read_csv(os.path.join(quiet.out, 'cycles.csv')).drop(columns='cpuSeconds')
    b = pd.read_csv(os.path.join(again.out, 'cycles.csv')).drop(columns='cpuSeconds')
    pd.testing.assert_frame_equal(a.iloc[:2], b.iloc[:2])   # saved with the state
    assert b.settlement.iloc[2] == pytest.approx(a.settlement.iloc[2], rel=TOL_RESUME)
    assert b.resilient.iloc[2] == pytest.approx(a.resilient.iloc[2], rel=10 * TOL_RESUME)


def test_a_killed_run_resumed_goes_on_in_its_folder_to_its_end(run, tmp_path):
    """resume: the run killed after its state of cycle 2 goes on from it in its own folder: cycles 1-2 as saved, cycle
    3 taken again, samples.csv cut back to the state's time and taken again at the same times (a row more or less
    per sample period if the cut were wrong), run.json finished and saying where it went on from."""
    test, s = run
    folder = killedCopy(test, str(tmp_path), 'state-cycle0000002.yade.gz')
    s2 = BoxTest(results=str(tmp_path), runId=test.runId, resume=True, vtk=1, saveEvery=2, **SMALL).run()
    assert sorted(os.listdir(str(tmp_path))) == [test.runId]   # no new folder
    old = pd.read_csv(os.path.join(test.out, 'cycles.csv')).drop(columns='cpuSeconds')
    new = pd.read_csv(os.path.join(folder, 'cycles.csv'))
    new, newCpu = new.drop(columns='cpuSeconds'), new.cpuSeconds
    assert list(new.cycle) == [1, 2, 3] and s2['cycles'] == 3 and s2['params']['resume'] is True
    pd.testing.assert_frame_equal(old.iloc[:2], new.iloc[:2])
    assert newCpu.iloc[2] > 0
    a, b = (pd.read_csv(os.path.join(d, 'samples.csv')) for d in (test.out, folder))
    assert len(b) == len(a) and np.allclose(b.t, a.t, rtol=0, atol=1e-6)
    assert (np.diff(b.t) > 0).all()
    with open(os.path.join(folder, 'run.json')) as fh:
        doc = json.load(fh)
    assert doc['status'] == 'finished' and doc['resumedFrom'] == 'state-cycle0000002.yade.gz'
    assert abs(s2['massLedgerError']) <= 1e-12 * s2['massInitial']


def test_resume_refuses_a_live_run_and_other_physics_and_starts_afresh_without_a_killed_run(run, tmp_path):
    test, s = run
    with pytest.raises(ParamError, match="resume = True is not allowed: give runId"):
        BoxTest(results=str(tmp_path), resume=True, **SMALL)
    assert BoxTest(results=str(tmp_path), runId='none', resume=True, **SMALL).resumeKilled() is None
    folder = killedCopy(test, str(tmp_path), 'state-cycle0000002.yade.gz')
    with pytest.raises(ParamError, match=r"ft0 = 40000.0 is not allowed with resume .*the saved run has ft0 = 35000.0"):
        BoxTest(results=str(tmp_path), runId=test.runId, resume=True, **dict(SMALL, ft0=4e4)).run()
    live = subprocess.Popen(['sleep', '60'])
    try:
        with open(os.path.join(folder, 'run.json')) as fh:
            doc = json.load(fh)
        with open(os.path.join(folder, 'run.json'), 'w') as fh:
            json.dump(dict(doc, pid=live.pid), fh)
        with pytest.raises(ParamError, match=r"resume = 1 is not allowed: the run in .* is alive \(pid %d\)" % live.pid):
            BoxTest(results=str(tmp_path), runId=test.runId, resume=True, **SMALL).run()
        # a live run that has saved no state yet: refused too (it started a second run afresh beside it)
        young = tmp_path / 'young'
        young.mkdir()
        (young / 'run.json').write_text(json.dumps({'status': 'running', 'pid': live.pid, 'host': socket.gethostname()}))
        with pytest.raises(ParamError, match=r"resume = 1 is not allowed: the run in .*young is alive"):
            BoxTest(results=str(tmp_path), runId='young', resume=True, **SMALL).run()
    finally:
        live.kill()
        live.wait()


def test_a_run_in_slices_goes_on_from_a_state_and_refuses_other_physics(run, tmp_path):
    test, s = run
    end = os.path.join(test.out, 'state-end.yade.gz')
    with pytest.raises(ParamError, match=r"ft0 = 40000.0 is not allowed with continueFrom: the saved run has ft0 = 35000.0"):
        BoxTest(results=str(tmp_path), continueFrom=end, **dict(SMALL, ft0=4e4, cycles=1)).run()
    with pytest.raises(ParamError, match='continueFrom = .* is not allowed: no such state file'):
        BoxTest(results=str(tmp_path), continueFrom=str(tmp_path / 'none.yade.gz'), **SMALL)
    # a slice may store beds elsewhere (another machine's path): the saved run has its bed
    first = str(tmp_path / 'first.yade.gz')
    shutil.copyfile(end, first)
    slice2 = BoxTest(results=str(tmp_path), runId='slice2', continueFrom=first,
                     **dict(SMALL, cycles=1, bedDir=str(tmp_path / 'other-beds')))
    s2 = slice2.run()
    cyc = pd.read_csv(os.path.join(str(tmp_path), 'slice2', 'cycles.csv'))
    assert list(cyc.cycle) == [1, 2, 3, 4] and s2['cycles'] == 4 and s2['params']['continueFrom'] == first
    with open(os.path.join(str(tmp_path), 'slice2', 'run.json')) as fh:   # its provenance (it said "None" before)
        status = json.load(fh)
    assert status['continuesState'] == first and status['continues'] == test.out
    # the state slice 2 started from is gone (another machine, a removed checkout): slice 2's own state still
    # reopens, saying where it came from, and a third slice goes on from it
    os.remove(first)
    end2 = os.path.join(str(tmp_path), 'slice2', 'state-end.yade.gz')
    assert BoxTest.reopen(end2, readOnly=True).p['continueFrom'] == first
    s3 = BoxTest(results=str(tmp_path), runId='slice3', continueFrom=end2, **dict(SMALL, cycles=1)).run()
    assert s3['cycles'] == 5 and s3['params']['continueFrom'] == end2


def test_a_sleeper_that_reaches_the_floor_stops_the_run(tmp_path):
    """Grains this weak (ft0 3.5e4 Pa m with fatigue of exponent 10) crush away under the sleeper within a few
    cycles; YADE has no contact between the sleeper (a box) and the floor (a wall), so the run must stop where
    the sleeper's underside comes within dMin / 2 of the floor, not let it fall through (it fell 5 m before)."""
    test = BoxTest(results=str(tmp_path), runId='floor', **dict(SMALL, cycles=30, fatigue=True, fatigueExponent=10))
    s = test.run()
    assert s['stoppedBy'] == 'sleeperOnFloor' and s['cycles'] < 30 and s['settlement'] < SMALL['bedDepth']
    last = pd.read_csv(os.path.join(test.out, 'samples.csv')).settlement.iloc[-1]   # where it stopped, mid-cycle
    top = test.initial['zBase']                                                      # the underside at the start
    assert top - SMALL['dMin'] / 2 < last < top - SMALL['dMin'] / 2 + SMALL['dMin']  # on the floor, not below it
    # every file says the same at the stop: the cycle cut short is the last row of cycles.csv (complete 0), its
    # settlement the last sample's and the summary's, its crush count the summary's, crushes.csv's and grading.csv's
    cyc = pd.read_csv(os.path.join(test.out, 'cycles.csv'))
    crushes = pd.read_csv(os.path.join(test.out, 'crushes.csv'))
    grading = pd.read_csv(os.path.join(test.out, 'grading.csv'))
    assert list(cyc.complete) == [1] * s['cycles'] + [0] and s['stoppedInCycle'] == s['cycles'] + 1
    assert list(cyc.cycle) == list(range(1, s['cycles'] + 2))
    assert cyc.settlement.iloc[-1] == pytest.approx(last, rel=1e-8) and s['settlement'] == pytest.approx(last, rel=1e-8)
    assert s['nCrushed'] == cyc.nCrushed.iloc[-1] == cyc.crushes.sum() == len(crushes) > 0
    assert crushes.cycle.max() <= s['stoppedInCycle'] and grading.cycle.iloc[-1] == s['stoppedInCycle']
    # on its way down it left the range a box test is for: said once, in the log and the summary
    assert [w.split()[0] for w in s['warnings']].count('settlement') == 1, s['warnings']
    # reopened, a run on the floor runs no more cycles (as a failed triaxial specimen): its outputs again, no step
    again = BoxTest.reopen(os.path.join(test.out, 'state-end.yade.gz'), results=str(tmp_path), runId='again')
    steps = O.iter
    s2 = again.load(5)
    assert O.iter == steps and s2['stoppedBy'] == 'sleeperOnFloor' and s2['cycles'] == s['cycles']


def test_a_state_saved_before_the_new_floors_reopens_and_goes_on(tmp_path):
    """A record's end state of the box study (commit 97d3503's code, vtk a flag, cycles.csv rows of 15 columns,
    no steps per cycle): reopened, its parameters come back in today's units (vtk False: no frames), it goes on one
    cycle, and cycles.csv keeps its 100 recorded rows with the new measures of the new cycle only."""
    state = os.path.join(ROOT, 'docs', 'studies', 'box', 'runs', 'box-seed1-c100', 'state-end.yade.gz')
    old = pd.read_csv(os.path.join(os.path.dirname(state), 'cycles.csv'))
    run = BoxTest.reopen(state, results=str(tmp_path), runId='old')
    assert run.p['vtk'] == 0.0 and run.p['saveEvery'] == 50
    s = run.load(1)
    cyc = pd.read_csv(os.path.join(run.out, 'cycles.csv'))
    assert s['cycles'] == 101 and list(cyc.cycle) == list(range(1, 102))
    for c in ('settlement', 'resilient', 'work', 'tilt', 'nGrains'):
        np.testing.assert_allclose(cyc[c][:100], old[c], rtol=1e-8, err_msg=c)
    assert cyc.inertialMax[:100].isna().all() and np.isfinite(cyc.inertialMax[100])
    assert cyc.responseRatio[100] > 1 and np.isnan(cyc.stepsPerCycle[100])   # the open cycle's first step unknown
