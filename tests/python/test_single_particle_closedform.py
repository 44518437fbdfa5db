"""ballast.experiments.single_particle.closedform: the crushing force of a sphere between platens for
each criterion, worked out by hand (no YADE)."""
import math

import pytest

from ballast.experiments.single_particle.closedform import criterionStress, crushingForce

FT0, R = 3.1e6, 0.01625   # [Pa m], [m]: the calibrated ft0, a 32.5 mm grain


def test_von_mises_and_major_principal_crush_at_two_pi_r_ft0_over_three():
    """sigma_e = 3 F / (2 pi r^2) = ft0 / r  ->  F = 2 pi r ft0 / 3 = 105.5 kN; F/d^2 = pi ft0 / (6 r) = 99.89 MPa."""
    for criterion in ('vonMises', 'majorPrincipal'):
        F = crushingForce(criterion, R, FT0, 1.0)
        assert F == pytest.approx(2 * math.pi * R * FT0 / 3, rel=1e-12)
        assert F == pytest.approx(105.50e3, rel=1e-4)
        assert F / (2 * R) ** 2 == pytest.approx(99.887e6, rel=1e-5)
        assert criterionStress(criterion, F, 2 * R) == pytest.approx(FT0 / R, rel=1e-12)


def test_largest_contact_force_crushes_at_four_r_ft0():
    """F / d^2 = ft0 / r  ->  F = 4 r ft0 = 201.5 kN (1.91 times the von Mises force)."""
    F = crushingForce('maxContactForce', R, FT0, 1.0)
    assert F == pytest.approx(4 * R * FT0, rel=1e-12) and F == pytest.approx(201.5e3, rel=1e-12)
    assert F / crushingForce('vonMises', R, FT0, 1.0) == pytest.approx(6 / math.pi, rel=1e-12)


def test_the_size_exponent_enters_as_r_to_the_two_minus_m():
    """m = 0: F ~ r^2 (a size-independent strength); m = 2: F independent of r."""
    assert crushingForce('vonMises', 2 * R, FT0, 0.0) / crushingForce('vonMises', R, FT0, 0.0) == pytest.approx(4.0)
    assert crushingForce('vonMises', 2 * R, FT0, 2.0) == pytest.approx(crushingForce('vonMises', R, FT0, 2.0))


def test_a_grain_of_any_shape_crushes_at_its_strength_times_volume_over_height():
    """sigma_zz = F h / V (the torque balance of a grain between frictionless platens): F = f_t V / h, the sphere's
    at h = 2r; a flatter grain (h < 2r) needs more force; the largest contact force has no closed form there."""
    for criterion in ('vonMises', 'majorPrincipal'):
        sphere = crushingForce(criterion, R, FT0, 0.5)
        assert crushingForce(criterion, R, FT0, 0.5, height=2 * R) == pytest.approx(sphere, rel=1e-12)
        h = 1.2 * R
        F = crushingForce(criterion, R, FT0, 0.5, height=h)
        assert F * h / (4 / 3 * math.pi * R ** 3) == pytest.approx(FT0 / R ** 0.5, rel=1e-12)
    assert math.isnan(crushingForce('maxContactForce', R, FT0, 1.0, height=1.2 * R))
