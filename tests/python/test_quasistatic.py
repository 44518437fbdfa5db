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
