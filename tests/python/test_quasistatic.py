"""ballast.experiments.quasistatic: the inertial number of a bed under its loading body and the ratio of the load's
period to the bed's response time, against values worked out by hand."""
import math

import pytest

pytest.importorskip('yade')
from yade import O, utils  # noqa: E402

from ballast import harvest  # noqa: E402
from ballast.experiments import quasistatic  # noqa: E402
from ballast.oedometer import check  # noqa: E402

R = 0.01   # [m] the grains' radius


@pytest.fixture
def bed():
    """Ten grains of radius R and the paper's density, apart (a table of grains is all the measure reads)."""
    O.reset()
    for k in range(10):
        O.bodies.append(utils.sphere((3 * R * k, 0, 0), R, material=utils.defaultMaterial()))
    harvest.refresh()
    yield check({})
    O.reset()


def test_the_inertial_number_is_rate_diameter_and_density_over_pressure(bed):
    """v = 0.1 m/s over h = 0.2 m, d = 2 R = 0.02 m, rho = 2600 kg/m^3, p = 1000 N / 0.01 m^2 = 1e5 Pa:
    I = 0.5 * 0.02 * sqrt(2600 / 1e5) = 1.6125e-3; the sign of the speed does not matter."""
    p = bed
    want = 0.5 * 0.02 * math.sqrt(2600 / 1e5)
    assert quasistatic.inertialNumber(p, -0.1, 0.2, 1000.0, 0.01, 4000.0) == pytest.approx(want, rel=1e-12)
    assert quasistatic.inertialNumber(p, 0.1, 0.2, 1000.0, 0.01, 4000.0) == pytest.approx(want, rel=1e-12)
    # the seating: under 1 % of the peak load any motion looks inertial, so none is reported
    assert math.isnan(quasistatic.inertialNumber(p, 0.1, 0.2, 39.0, 0.01, 4000.0))
    # density scaling: densityStep twice the paper's step (dtSafety dMin/2 sqrt(rho / E)) gives a grain of radius R
    # the own step R sqrt(rho_s / E) = 2 (dMin / 2) sqrt(rho / E): rho_s / rho = (dMin / R)^2, I grows by dMin / R
    scaled = p.replace(densityStep=2 * p.startTimeStep())
    assert quasistatic.inertialNumber(scaled, 0.1, 0.2, 1000.0, 0.01, 4000.0) == pytest.approx(
        want * p['dMin'] / R, rel=1e-9)
    assert quasistatic.bedMass(scaled, [1.0, 2.0]) == pytest.approx(3.0 * (p['dMin'] / R) ** 2, rel=1e-9)


def test_the_response_ratio_is_the_period_over_the_natural_period_of_mass_on_the_resilient_stiffness():
    """T = 1 s, M = 1 kg, K = 100 N / 0.01 m = 1e4 N/m: t = 2 pi / 100 s, the ratio 100 / (2 pi)."""
    assert quasistatic.responseRatio(1.0, 1.0, 100.0, 0.01) == pytest.approx(100 / (2 * math.pi), rel=1e-12)
    assert quasistatic.responseRatio(2.0, 4.0, 100.0, 0.01) == pytest.approx(100 / (2 * math.pi), rel=1e-12)
    assert math.isnan(quasistatic.responseRatio(1.0, 1.0, 100.0, 0.0))   # no resilient deformation: no stiffness


def test_a_cycles_inertial_numbers_largest_and_median_leave_out_the_undefined():
    assert quasistatic.cycleStats([1e-5, float('nan'), 3e-5, 2e-5, None]) == (3e-5, 2e-5)
    big, median = quasistatic.cycleStats([float('nan')])
    assert math.isnan(big) and math.isnan(median)


def test_the_step_choice_puts_the_last_cycle_at_its_bounds_grows_at_most_twice_and_falls_back_when_broken():
    """The paper's step 1e-6 s, I <= 1e-3, ratio >= 10, cycles of 0.1 s with abrasion every 100 steps: at most
    min(0.1 / 1000, 0.1 / 100) = 1e-4 s; the first cycle at 4e-6 s. I ~ dt and ratio ~ 1 / dt, aimed at 0.7 of the
    bounds: I = 2e-4, ratio 100 allow 3.5 and 7 times the step, the growth 2: 8e-6 s; I = 6e-4, ratio 30 allow
    0.7 / 0.6 and 2.1: 8e-6 x 7 / 6; I = 1.2e-3 breaks the bound: the paper's step, the cycle marked; no measure
    (unloaded): twice the step; the ratio alone broken (8 < 10): marked, and the step shrunk to put it at 10 / 0.7,
    x 0.56; so far below (ratio 1) that the paper's step is the floor."""
    c = quasistatic.StepChoice(1e-6, 1e-3, 10.0, 0.1, 100)
    assert c.largest == pytest.approx(1e-4) and c.step == pytest.approx(4e-6)
    assert c.cycleClosed(2e-4, 100.0) == pytest.approx(8e-6)
    assert c.cycleClosed(6e-4, 30.0) == pytest.approx(8e-6 * 0.7 / 0.6)
    assert c.cycleClosed(1.2e-3, 30.0) == pytest.approx(1e-6)
    assert c.cycleClosed(float('nan'), float('nan')) == pytest.approx(2e-6)
    assert c.cycleClosed(5e-4, 8.0) == pytest.approx(2e-6 * 0.7 * 8.0 / 10.0)   # the ratio below 10: broken too
    assert c.cycleClosed(5e-4, 1.0) == pytest.approx(1e-6)
    assert c.met == [1, 1, 0, 1, 0, 0]
    for _ in range(20):
        c.cycleClosed(1e-9, 1e9)   # far inside the bounds: the growth, then the cap
    assert c.step == pytest.approx(1e-4)
    c.loaded = {7: 3e-6}
    back = quasistatic.StepChoice.fromState(__import__('json').loads(__import__('json').dumps(c.state())))
    assert back.state() == c.state() and back.loaded == {7: 3e-6}
    # quasiStaticStart: the first cycle at 1 times the paper's step (the paper's), 16 times capped by the cycle's
    # 1000 steps (16e-6 s allowed here, 1.6e-5 > 1e-5 for cycles of 0.01 s)
    assert quasistatic.StepChoice(1e-6, 1e-3, 10.0, 0.1, 100, 1.0).step == 1e-6
    assert quasistatic.StepChoice(1e-6, 1e-3, 10.0, 0.1, 1, 16.0).step == pytest.approx(1.6e-5)
    assert quasistatic.StepChoice(1e-6, 1e-3, 10.0, 0.01, 1, 16.0).step == pytest.approx(1e-5)


def test_a_small_box_under_the_quasi_static_option_keeps_the_bound_or_says_so(tmp_path):
    """The small soft box at 10 Hz (I about 5e-4 at the paper's step) with quasiStatic 1e-3: the first cycle at 4
    times the paper's step, then each cycle's step the option's; cycles.csv says which cycles kept the bounds,
    those that broke the inertial bound were followed by a cycle at the paper's step, those that broke only the
    ratio bound by a shorter step, and each kept cycle had I <= 1e-3."""
    import pandas as pd
    from ballast.experiments.box import BoxTest
    small = dict(boxLength=0.3, boxWidth=0.12, bedDepth=0.1, layers=2, sleeperWidth=0.1, sleeperHeight=0.05,
                 sleeperMass=5, dMin=0.02, dMax=0.03, young=3e9, prepYoung=3e8, seatLoad=300, peakLoad=4000, crush=False,
                 strength=1.5e10, f=10, cycles=5, progress=60)
    test = BoxTest(results=str(tmp_path), runId='qs', quasiStatic=1e-3, **small)
    s = test.run()
    assert s['warnings'][0].startswith('quasiStatic 0.001: validated on the default box') and \
        'not for the resilient deflection' in s['warnings'][0]   # what its validation found, said in the summary
    cyc = pd.read_csv(str(tmp_path / 'qs' / 'cycles.csv'))
    paper = test.p.startTimeStep()
    assert cyc.dt[0] == pytest.approx(4 * paper, rel=1e-6)
    assert set(cyc.quasiStaticMet) <= {0, 1}
    kept = cyc.quasiStaticMet == 1
    assert ((cyc.inertialMax[kept] <= 1e-3) & ~(cyc.responseRatio[kept] < 10)).all()
    assert ((cyc.inertialMax[~kept] > 1e-3) | (cyc.responseRatio[~kept] < 10)).all()
    for k in range(len(cyc) - 1):   # the step of cycle k + 1 is the choice made at cycle k's end
        if cyc.inertialMax[k] > 1e-3:
            assert cyc.dt[k + 1] == pytest.approx(paper, rel=1e-6)
        elif cyc.quasiStaticMet[k] == 0:
            assert paper * (1 - 1e-9) <= cyc.dt[k + 1] < cyc.dt[k]
        else:
            assert paper * (1 - 1e-9) <= cyc.dt[k + 1] <= 2 * cyc.dt[k] * (1 + 1e-6)


def test_the_option_says_where_its_validation_found_it_changes_the_answer(tmp_path, capsys):
    """The box and the triaxial test say what the option's validation found (the box: not for the resilient
    deflection; the triaxial: its first cycle differs) when a run with it starts, and nothing without it."""
    from ballast.experiments.box import BoxTest
    from ballast.experiments.triaxial import TriaxialTest
    assert BoxTest().warnings() == [] and TriaxialTest().warnings() == []
    assert 'not validated for crushing' in BoxTest(quasiStatic=1e-3).warnings()[0]   # the crushing case's finding
    for cls, words in ((BoxTest, 'the resilient deflection came out 14 % larger'),
                       (TriaxialTest, 'cycle 1 strained 15 % less axially')):
        exp = cls(quasiStatic=2e-3, results=str(tmp_path), runId=cls.NAME)
        assert len(exp.warnings()) == 1 and exp.warnings()[0].startswith('quasiStatic 0.002: ')
        assert words in exp.warnings()[0]
        exp.openRunDirectory()
        assert 'warning: quasiStatic 0.002: ' in capsys.readouterr().out
