"""The cyclic triaxial test end to end on a small specimen (0.12 x 0.24 m, grains 20-30 mm, E = 3e9 Pa, 20 Hz, 2
cycles): cycles.csv in the shared schema; the strains of samples.csv are the boundary's, by hand; a scripted scaling
of the whole specimen by s changes the strains by exactly 1 - s (axial) and 1 - s^3 (volumetric); the grains carry
the deviator at its peaks within 5 %; the specimen at rest after consolidation and seating carries p' across both
diametral planes and p' + qMin across mid-height within 5 % (1.2 % and 0.2 % measured)."""
import json
import math
import os
import re

import pandas as pd
import pytest

pytest.importorskip('yade')
from yade import O, Vector3  # noqa: E402

from ballast import harvest  # noqa: E402
from ballast.experiments import cyclic  # noqa: E402
from ballast.experiments.triaxial import TriaxialTest  # noqa: E402
from ballast.experiments.triaxial.experiment import PRESS  # noqa: E402
from ballast.experiments.triaxial.outputs import OWN_COLUMNS  # noqa: E402
from ballast.experiments.triaxial.strains import axialStrain, volumetricStrain  # noqa: E402
from ballast.params import ParamError  # noqa: E402
from test_triaxial_membrane import crossing  # noqa: E402

SMALL = dict(diameter=0.12, height=0.24, dMin=0.02, dMax=0.03, layers=2, young=3e9, prepYoung=3e8, f=20.0, cycles=2,
             vtk=1, progress=1e6)


@pytest.fixture(scope='module')
def run(tmp_path_factory):
    out = str(tmp_path_factory.mktemp('triaxial'))
    test = TriaxialTest(results=out, runId='small', **SMALL)
    test.prepare()
    H, V = test.membrane.height(), test.membrane.volume
    Rm = math.sqrt(V / (math.pi * H))
    stresses = [crossing(axis, 0.0) / (2 * Rm * H) for axis in (0, 1)]   # across the diametral planes
    stresses.append(crossing(2, O.bodies[test.rig.base].state.pos[2] + H / 2) / (math.pi * Rm ** 2))   # mid-height
    s = test.load()
    return test, s, os.path.join(out, 'small'), stresses


def test_cycles_in_the_shared_schema(run):
    test, s, folder, _ = run
    c = pd.read_csv(os.path.join(folder, 'cycles.csv'))
    assert tuple(c.columns) == cyclic.COLUMNS + OWN_COLUMNS
    assert c.cycle.tolist() == [1, 2] and s['cycles'] == 2
    assert (c.nGrains == s['nGrainsInitial']).all()
    assert abs(s['massLedgerError']) < 1e-12 * s['massInitial']
    assert 0.3 < s['consolidated']['porosity'] < 0.5
    assert s['stepsPerCycle'] == c.stepsPerCycle.median()   # the steps the cycles took, not the period over dt
    for name in ('samples.csv', 'grading.csv', 'summary.json', 'strains.png', 'state-end.yade.gz'):
        assert os.path.getsize(os.path.join(folder, name)) > 0, name


def test_vtk_frames_of_grains_contacts_and_membrane(run):
    # a frame at the start of cycling, every cycle (a callback at simulated times) and at the end, once at a time (the
    # end falls a sample after the last cycle's frame): grains, contacts, membrane
    test, s, folder, _ = run
    pvd = open(os.path.join(folder, 'triaxial.pvd')).read()
    files = re.findall(r'file="([^"]+)"', pvd)
    times = [f[0] for f in test.frames]
    period = 1 / test.p['f']
    assert times[:3] == pytest.approx([0, period, 2 * period], abs=1e-3 * period) and len(times) in (3, 4)
    assert times == sorted(set(times)) and times[-1] >= 2 * period * (1 - 1e-3)
    assert len(files) == 3 * len(test.frames)
    assert all(os.path.getsize(os.path.join(folder, f)) > 0 for f in files)
    membrane = open(os.path.join(folder, files[-1])).read()
    points, cells = map(int, re.search(r'NumberOfPoints="(\d+)" NumberOfCells="(\d+)"', membrane).groups())
    rho, _, _ = test.membrane.surface()
    nZ, nT = rho.shape
    assert (points, cells) == (nZ * nT, (nZ - 1) * nT)
    R = test.p['diameter'] / 2
    assert 0.8 * R < rho.mean() < 1.05 * R


def test_strains_are_the_boundarys(run):
    test, s, folder, _ = run
    rec = test.recorder
    rows = pd.read_csv(os.path.join(folder, 'samples.csv'))   # written to 9 digits: heights to 1e-9 m
    assert rows.axialStrain.to_numpy() == pytest.approx(((rec.H0 - rows.height) / rec.H0).to_numpy(), rel=1e-6, abs=1e-8)
    assert rows.volumetricStrain.to_numpy() == pytest.approx(((rec.V0 - rows.volume) / rec.V0).to_numpy(), rel=1e-6,
                                                             abs=1e-8)
    c = pd.read_csv(os.path.join(folder, 'cycles.csv'))
    assert c.axialStrain.to_numpy() == pytest.approx((c.settlement / rec.H0).to_numpy(), rel=1e-8)


def test_a_scripted_scaling_strains_by_hand(run):
    # every grain, its radius, the platen and the membrane's cells scaled by s about the base: the membrane meets the
    # same grains at s times the radius, H -> s H, V -> s^3 V
    test, _, _, _ = run
    m = test.membrane
    m.update()
    H, V = m.height(), m.volume
    base = O.bodies[m.bottom].state.pos[2]
    s = 0.98
    for b in O.bodies:
        if b is None or b.id == m.bottom:
            continue
        p = b.state.pos
        b.state.pos = (s * p[0], s * p[1], base + s * (p[2] - base))
        if hasattr(b.shape, 'radius'):
            b.shape.radius *= s
    m.cell, m.depth = s * m.cell, s * m.depth
    harvest.refresh()   # radii changed by hand within a step: the grain table is read again (harvest's contract)
    m.update()
    assert axialStrain(H, m.height()) == pytest.approx(1 - s, rel=1e-9)
    assert volumetricStrain(V, m.volume) == pytest.approx(1 - s ** 3, rel=1e-6)


def test_the_grains_carry_the_deviator_at_its_peaks(run):
    test, s, folder, _ = run
    c = pd.read_csv(os.path.join(folder, 'cycles.csv'))
    p = test.p
    assert c.qGrainsMax.iloc[-1] == pytest.approx(p['qMax'], rel=0.05)
    summary = json.load(open(os.path.join(folder, 'summary.json')))
    assert summary['params']['qMax'] == p['qMax']


def test_the_seated_specimen_carries_the_cell_pressure_and_the_seating_deviator(run):
    # at rest under p' on every side and qMin on top: p' across the diametral planes, p' + qMin across mid-height
    test, _, _, stresses = run
    p = test.p
    assert stresses[0] == pytest.approx(p['confining'], rel=0.05)
    assert stresses[1] == pytest.approx(p['confining'], rel=0.05)
    assert stresses[2] == pytest.approx(p['confining'] + p['qMin'], rel=0.05)


@pytest.fixture(scope='module')
def mono(run):
    """A drained monotonic compression of the same stored specimen to 3 % axial strain at 0.5 /s."""
    test = TriaxialTest(results=os.path.dirname(run[2]), runId='mono',
                        **dict(SMALL, monotonic=True, strainRate=0.5, maxAxialStrain=0.03))
    s = test.run()
    return test, s, pd.read_csv(os.path.join(test.out, 'monotonic.csv'))


def test_monotonic_compression_is_driven_at_its_strain_rate(mono):
    """Displacement control, by hand: the axial strain of every row is strainRate t from where it started (a row is
    taken after the step's motion, before its time advances: eps0 = strainRate dt), and the test ends at
    maxAxialStrain, within a row's span; it starts from the isotropic state (q within 2 % of p' at the first row)."""
    test, s, m = mono
    eps0 = m.axialStrain.iloc[0]
    assert eps0 == pytest.approx(0.5 * O.dt, rel=1e-3) and abs(m.q.iloc[0]) < 0.02 * 60e3
    assert (m.axialStrain - eps0 - 0.5 * m.t).abs().max() < 1e-9
    # the end is checked every 100 steps: it stops within 100 steps of strain past 3 %, its last row within a row's span
    assert 0.03 - 0.03 / 400 - 1e-9 <= m.axialStrain.iloc[-1] <= 0.03 + 100 * 0.5 * O.dt
    assert m.p.to_numpy() == pytest.approx((60e3 + m.q / 3).to_numpy(), rel=1e-8)   # written to 9 digits


def test_monotonic_peak_and_angles_by_hand(mono):
    test, s, m = mono
    k = int(m.q.idxmax())
    assert s['qPeak'] == pytest.approx(m.q[k], rel=1e-8) and s['axialStrainAtPeak'] == pytest.approx(m.axialStrain[k],
                                                                                                       rel=1e-8)
    eta = m.q[k] / m.p[k]
    assert s['frictionAnglePeak'] == pytest.approx(math.degrees(math.asin(3 * eta / (6 + eta))), rel=1e-7)   # 9 digits
    assert 20 < s['frictionAnglePeak'] < 70   # a frictional packing with rolling resistance
    for name in ('monotonic.png', 'grading.csv', 'summary.json', 'state-end.yade.gz'):
        assert os.path.isfile(os.path.join(test.out, name)), name
    assert s['test'] == 'monotonic' and s['massLedgerError'] == pytest.approx(0, abs=1e-12)


def test_the_angles_closed_forms():
    from ballast.experiments.triaxial import monotonic
    assert monotonic.frictionAngle(1.2, 1.0) == pytest.approx(30.0, rel=1e-12)   # sin phi = 3.6 / 7.2
    assert monotonic.dilatancyAngle(-2 / 3) == pytest.approx(math.degrees(math.asin(0.25)), rel=1e-12)
    assert monotonic.dilatancyAngle(0.0) == 0.0   # no volume change: no dilatancy


def test_monotonic_refuses_the_options_of_cycles():
    from ballast.experiments.triaxial import check
    from ballast.params import ParamError
    for k, v in (('quasiStatic', 1e-3), ('jump', True)):
        with pytest.raises(ParamError, match='TriaxialTest: %s = .* not a monotonic compression' % k):
            check(dict(monotonic=True, **{k: v}, **({'fatigue': True} if k == 'jump' else {})))


def test_a_long_run_goes_on_in_slices(run, tmp_path):
    """continueFrom: the saved run's state goes on for `cycles` more cycles in this run's folder, its cycles.csv
    numbering on from the saved run's (1, 2, then 3), its run.json naming the state; a physics parameter that
    differs from the saved run's is refused before any step, naming it."""
    state = os.path.join(run[2], 'state-end.yade.gz')
    s = TriaxialTest(results=str(tmp_path), runId='slice', continueFrom=state, **dict(SMALL, cycles=1, vtk=0)).run()
    cyc = pd.read_csv(os.path.join(str(tmp_path), s['runId'], 'cycles.csv'))
    assert list(cyc.cycle) == [1, 2, 3] and s['cycles'] == 3
    with open(os.path.join(str(tmp_path), s['runId'], 'run.json')) as fh:
        assert json.load(fh)['continuesState'] == state
    with pytest.raises(ParamError, match='young = 4000000000.0 is not allowed with continueFrom'):
        TriaxialTest(results=str(tmp_path), runId='other', continueFrom=state, **dict(SMALL, young=4e9)).run()
    with pytest.raises(ParamError, match='continueFrom'):
        TriaxialTest(continueFrom=str(tmp_path / 'none.yade.gz'), **SMALL)


def test_a_reopened_state_carries_the_loads_it_was_saved_with(run):
    """YADE saves no permanent force: a state reopened stood unconfined and unloaded until the membrane's next update
    (the cycle after it strained twice as much). Reopened, every grain the membrane pressed and the top platen carry
    the very forces of the last update before the save (kept with the state), to the bit, before any new update."""
    again = TriaxialTest.reopen(os.path.join(run[2], 'state-end.yade.gz'))
    m = again.membrane
    want = {i: tuple(f) for i, f in zip(m.loaded, m.forces)}
    assert len(want) > 20 and again.platenForce < 0
    for e in O.engines:   # YADE reads a permanent force back once a step synced it: a step with no new update
        if e.label == PRESS:
            e.dead = True
    O.run(1, True)
    assert {i: tuple(O.forces.permF(i)) for i in m.loaded} == want
    assert tuple(O.forces.permF(again.rig.top)) == (0.0, 0.0, again.platenForce)


def test_cycling_stops_where_the_specimen_fails(run, tmp_path):
    """failureStrain: the axial strain of the sample that first reaches it stops cycling in that cycle (here the
    third, as it loads: the saved run's last strain plus half its resilient strain); summary.json says so with the
    whole cycles before it; the failed run reopened runs no more cycles."""
    test, s, folder, _ = run
    before = pd.read_csv(os.path.join(folder, 'samples.csv'))
    limit = before.axialStrain.iloc[-1] + 0.5 * s['resilientStrain']
    f = TriaxialTest(results=str(tmp_path), runId='fail', continueFrom=os.path.join(folder, 'state-end.yade.gz'),
                     **dict(SMALL, cycles=3, vtk=0, failureStrain=limit)).run()
    rows = pd.read_csv(os.path.join(str(tmp_path), f['runId'], 'samples.csv'))
    rows = rows[rows.t > 2 * s['loadPeriod']]   # cycle 3's (samples.csv's cycle: the cycles closed by then)
    assert f['stoppedBy'] == 'failure' and f['failedInCycle'] == 3 and f['cycles'] == 2
    assert f['axialStrainAtStop'] >= limit and abs(f['axialStrainAtStop'] - rows.axialStrain.iloc[-1]) < 1e-9   # CSV digits
    assert len(rows) > 1 and (rows.axialStrain.iloc[:-1] < limit).all()
    again = TriaxialTest.reopen(os.path.join(str(tmp_path), f['runId'], 'state-end.yade.gz'))
    steps = O.iter
    assert again.load(5)['failedInCycle'] == 3 and O.iter == steps


def test_a_collapse_between_two_samples_stops_as_a_failure(run, tmp_path):
    """A specimen that collapses (q_max 370 kPa with crushing: the platen fell through it within a cycle's 1/50) is
    caught at the membrane's next update, not at the next sample: the platen put below the base, the run stops as a
    failure at once (no membrane for a specimen with no height, no exception), with the failure's row in samples.csv."""
    again = TriaxialTest.reopen(os.path.join(run[2], 'state-end.yade.gz'), results=str(tmp_path), failureStrain=0.2)
    top, base = O.bodies[again.rig.top].state, O.bodies[again.rig.base].state
    top.pos = Vector3(top.pos[0], top.pos[1], base.pos[2] - 0.01)
    steps = O.iter
    s = again.load(1)
    assert s['stoppedBy'] == 'failure' and s['failedInCycle'] == 3 and s['axialStrainAtStop'] > 1.0
    assert O.iter - steps <= 60   # stopped within the run's check interval (50 steps) of the first update


def test_the_quasi_static_option_scales_what_the_engines_create_from_its_first_step(run, tmp_path):
    """quasiStatic: from the first step of cycling the crushing and abrasion engines give what they create the density
    scaling of the option's step (its first: 4 times the paper's, own step that over dtSafety). They were built with
    densityStep's 0 and learnt the step only at the first cycle's end: fragments of a crush in cycle 1 had unscaled
    density at 4 times their step, and at q_max 370 kPa the specimen exploded (issue 45)."""
    from ballast.experiments import chain
    specimens = os.path.join(os.path.dirname(run[2]), 'specimens')
    t = TriaxialTest(results=str(tmp_path), runId='qs', specimenDir=specimens, quasiStatic=1e-3, **SMALL)
    t.prepare()
    t.startCycling()
    own = t.ownStep()
    assert own == pytest.approx(4 * t.p.startTimeStep() / t.p['dtSafety'], rel=1e-12)
    assert [chain.engine(k).scaledPWaveStep for k in ('crush', 'abrasion')] == [own, own]
