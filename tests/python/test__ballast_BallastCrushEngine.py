"""Tests of pkg/python/bind_BallastCrushEngine.cpp: the bulk crushing decision of eq. 1 for all grains,
crush <=> r >= rMin and sigma > f_t = w ft0 / r^m (eq. 4, w a strength factor), the parameters checked once
against their ranges (ft0 > 0, m in [0, 3], rMin >= 0) and each bad grain value named by its index."""
import math

import numpy as np
import pytest

import ballast._ballast as B


def squeezed(r, F):
    """Eq. 3 of a grain of radius r squeezed along x by two opposite forces F: sigma_xx = -3F / (2 pi r^2)."""
    return np.diag([-3 * F / (2 * math.pi * r ** 2), 0.0, 0.0])


def forceFor(sigma, r):
    """The force giving sigma_e = sigma (eq. 2 of the uniaxial stress above)."""
    return sigma * 2 * math.pi * r ** 2 / 3


def test_threshold_and_rmin():
    r, ft0 = 0.02, 2.0e5
    ft = ft0 / r
    S = np.array([squeezed(r, forceFor(1.01 * ft, r)), squeezed(r, forceFor(0.99 * ft, r)), squeezed(r / 4, 1e9)])
    radii = np.array([r, r, r / 4])
    se, st, crush = B.crushCheck(S, radii, ft0, 1.0, r / 2)
    np.testing.assert_allclose(se[:2], [1.01 * ft, 0.99 * ft], rtol=1e-12)
    np.testing.assert_allclose(st, ft0 / radii, rtol=1e-15)
    assert crush.dtype == bool and list(crush) == [True, False, False]  # the third is below rMin
    _, _, crush = B.crushCheck(S, radii, ft0, 1.0, r / 4)  # r == rMin may crush
    assert list(crush) == [True, False, True]


def test_exactly_at_the_strength_does_not_crush():
    # eq. 1 is strict; a uniaxial -f_t has sigma_e = f_t exactly, f_t = ft0 / r one division
    r, ft0 = 0.019, 3e5
    se, st, crush = B.crushCheck(np.diag([-ft0 / r, 0, 0])[None], [r], ft0, 1.0, 0.0)
    assert se[0] == st[0] and not crush[0]


def test_size_exponent_at_the_ends_of_its_range():
    # m = 0: f_t = ft0 at every size; m = 3: f_t = ft0 / r^3
    r = 0.5
    _, st, _ = B.crushCheck(np.zeros((1, 3, 3)), [r], 2.0, 0.0, 0.0)
    assert st[0] == 2.0
    _, st, _ = B.crushCheck(np.zeros((1, 3, 3)), [r], 2.0, 3.0, 0.0)
    assert st[0] == pytest.approx(16.0, rel=1e-15)


def test_strength_factors_and_the_largest_contact_force():
    # sigma_e = 0.9 f_t: intact; with w = 0.8 the strength is 0.8 f_t < 0.9 f_t: crushed.
    # maxContactForce: F / d^2 = F / (4 r^2)
    r, ft0 = 0.02, 2e5
    ft, F = ft0 / r, forceFor(0.9 * ft0 / r, r)
    S = np.array([squeezed(r, F)] * 2)
    _, st, crush = B.crushCheck(S, [r, r], ft0, 1.0, 0.0, factor=[1.0, 0.8])
    np.testing.assert_allclose(st, [ft, 0.8 * ft], rtol=1e-15)
    assert list(crush) == [False, True]
    se, _, crush = B.crushCheck(S, [r, r], ft0, 1.0, 0.0, 'maxContactForce', fMax=[F, 5 * F])
    np.testing.assert_allclose(se, [F / (4 * r ** 2), 5 * F / (4 * r ** 2)], rtol=1e-15)
    assert list(crush) == [F / (4 * r ** 2) > ft, 5 * F / (4 * r ** 2) > ft]


def test_no_grains():
    se, st, crush = B.crushCheck(np.zeros((0, 3, 3)), [], 2e5, 1.0, 0.0)
    assert se.shape == st.shape == crush.shape == (0,)


S1 = np.array([squeezed(0.02, 2e3)])


@pytest.mark.parametrize('call,exc,message', [
    # the parameters, each against its range
    (lambda: B.crushCheck(S1, [0.02], -2.0, 1.0, 0.0), ValueError, 'ft0: expected a finite number > 0, got -2'),
    (lambda: B.crushCheck(S1, [0.02], 0.0, 1.0, 0.0), ValueError, 'ft0: expected a finite number > 0, got 0'),
    (lambda: B.crushCheck(S1, [0.02], 2e5, -1.0, 0.0), ValueError, 'm: expected a number in [0, 3], got -1'),
    (lambda: B.crushCheck(S1, [0.02], 2e5, 3.5, 0.0), ValueError, 'm: expected a number in [0, 3], got 3.5'),
    (lambda: B.crushCheck(S1, [0.02], 2e5, 1.0, -0.01), ValueError, 'rMin: expected a finite number >= 0, got -0.01'),
    (lambda: B.crushCheck(S1, [0.02], 2e5, 1.0, 0.0, 'maxContactForce'), ValueError,
     'fMax: the maxContactForce criterion needs the largest contact force of every grain'),
    # the arrays, each grain
    (lambda: B.crushCheck(np.zeros((2, 3, 3)), [1.0], 1.0, 1.0, 0.0), TypeError,
     'stresses: expected an (1,3,3) array, one tensor per radius, got shape (2,3,3)'),
    (lambda: B.crushCheck(np.zeros((2, 3, 3)), [0.01, -0.02], 2e5, 1.0, 0.0), ValueError,
     'radii[1]: expected a finite number > 0, got -0.02'),
    (lambda: B.crushCheck(S1, [0.02], 2e5, 1.0, 0.0, 'maxContactForce', [-1.0]), ValueError,
     'fMax[0]: expected a finite number >= 0, got -1'),
    (lambda: B.crushCheck(S1, [0.02], 2e5, 1.0, 0.0, factor=[0.0]), ValueError, 'factor[0]: expected a finite number > 0, got 0'),
    (lambda: B.crushCheck(S1, [0.02], 2e5, 1.0, 0.0, factor=[1.0, 1.0]), TypeError,
     'factor: expected None or an (1,) array, one value per radius, got shape (2,)'),
    # results that would not be finite
    (lambda: B.crushCheck(np.array([np.diag([1e200, 0, 0])]), [0.02], 2e5, 1.0, 0.0), ValueError,
     "stresses, fMax, radii: expected values whose criterion's stress is finite, the result would be inf at index 0"),
    (lambda: B.crushCheck(S1, [1e-100], 1e300, 3.0, 0.0), ValueError,
     'ft0, radii, m, factor: expected values whose strength factor x ft0 / r^m is finite, the result would be inf at index 0'),
])
def test_bad_input_names_the_argument_the_value_and_what_is_allowed(call, exc, message):
    with pytest.raises(exc) as e:
        call()
    assert str(e.value) == message
