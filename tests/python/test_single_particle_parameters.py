"""ballast.experiments.single_particle.parameters (no YADE): grain sizes outside those of ballast and its fragments, and
a test the step of the smallest grain would take more than 1e8 steps to run on the largest, refused before any work."""
import math

import pytest

from ballast.experiments.single_particle import check
from ballast.params import ParamError


@pytest.mark.parametrize('d', [1e-6, 100.0, 0.5])
def test_a_diameter_beyond_ballast_sizes_is_refused_with_a_hint_on_units(d):
    with pytest.raises(ParamError, match=r'diameters = .* is not allowed: %g m is outside 0.001-0.3 m.*in metres' % d):
        check({'diameters': [0.03, d]})


def test_the_largest_grain_at_the_smallest_grains_step_is_bounded():
    # 0.3 and 0.001 m at 1e-4 m/s: the step is dtSafety r sqrt(rho / E) = 0.8 x 0.0005 sqrt(2600 / 3e11) = 3.72e-8 s;
    # the smallest closes by 1 % in 2.7e6 steps (within bounds), the largest in 8.06e8 (refused)
    dt = 0.8 * 0.0005 * math.sqrt(2600 / 3e11)
    assert 100 < 0.01 * 0.001 / 1e-4 / dt < 1e8 < 0.01 * 0.3 / 1e-4 / dt
    check({'diameters': [0.03, 0.001], 'speed': 1e-4})
    with pytest.raises(ParamError, match=r'speed = 0.0001 is not allowed: takes 8.06e\+08 time steps'):
        check({'diameters': [0.3, 0.001], 'speed': 1e-4})
