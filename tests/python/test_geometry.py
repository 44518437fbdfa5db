"""ballast.geometry: the sphere volume, the equivalent radius of a volume and the mean volume of a uniform
diameter, by hand."""
import math

import numpy as np
import pytest

from ballast.geometry import equivalentRadius, meanCubedDiameterVolume, sphereVolume


def test_sphere_volume_scalar_and_array():
    assert sphereVolume(1.0) == pytest.approx(4.18879020478639, rel=1e-14)
    assert sphereVolume(0.5) == pytest.approx(math.pi / 6, rel=1e-14)
    np.testing.assert_allclose(sphereVolume(np.array([1.0, 2.0])), [4 * math.pi / 3, 32 * math.pi / 3], rtol=1e-14)


def test_mean_volume_of_uniform_diameter():
    # E[d^3] for d uniform in [1, 3] is (3^4 - 1^4) / (4 * 2) = 10; the volume is pi/6 * 10
    assert meanCubedDiameterVolume(1.0, 3.0) == pytest.approx(math.pi / 6 * 10, rel=1e-14)
    # a narrow range tends to the volume of its diameter
    assert meanCubedDiameterVolume(2.0, 2.0 + 1e-7) == pytest.approx(sphereVolume(1.0), rel=1e-6)


def test_equivalent_radius_of_a_volume():
    # a cube of side 2 (volume 8): (3 8 / (4 pi))^(1/3) = (6 / pi)^(1/3)
    assert equivalentRadius(8.0) == pytest.approx((6 / math.pi) ** (1 / 3), rel=1e-14)
    assert equivalentRadius(4 * math.pi / 3) == pytest.approx(1.0, rel=1e-14)
    np.testing.assert_allclose(equivalentRadius(sphereVolume(np.array([0.01, 0.02]))), [0.01, 0.02], rtol=1e-14)
