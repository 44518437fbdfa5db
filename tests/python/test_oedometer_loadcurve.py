"""ballast.oedometer.loadcurve: eq. 8 and its cycles by hand, without YADE."""
import numpy as np
import pytest

from ballast.oedometer.loadcurve import eq8, halfLoadTime, loadCurve

FMAX, F = 2e4, 50.0   # [N], [Hz]


def test_eq8_by_hand():
    T = 1 / F
    assert eq8(FMAX, F, 0.0) == pytest.approx(0.0, abs=1e-9 * FMAX)
    assert eq8(FMAX, F, T / 4) == pytest.approx(FMAX / 2, rel=1e-12)
    assert eq8(FMAX, F, T / 2) == pytest.approx(FMAX, rel=1e-12)
    assert eq8(FMAX, F, 3 * T / 4) == pytest.approx(FMAX / 2, rel=1e-12)
    assert halfLoadTime(F) == pytest.approx(T / 4, rel=1e-15)  # where the first rise passes Fmax/2
    t = np.linspace(0, T, 7)
    np.testing.assert_allclose(eq8(FMAX, F, t), [eq8(FMAX, F, float(x)) for x in t], rtol=1e-14, atol=1e-9)


def test_load_curve_by_hand():
    """Eq. 8 up to the peak at T/2, then between Fmax and Fmin: Fmin at T, 2T, ...; Fmax at 3T/2; halfway
    at 5T/4; with Fmin = 0 eq. 8 itself."""
    T, Fmin = 1 / F, 0.25 * FMAX
    for t, want in ((0, 0), (T / 4, FMAX / 2), (T / 2, FMAX), (T, Fmin), (1.25 * T, (FMAX + Fmin) / 2), (1.5 * T, FMAX),
                    (2 * T, Fmin)):
        assert loadCurve(FMAX, Fmin, F, t) == pytest.approx(want, rel=1e-12, abs=1e-9 * FMAX)
    t = np.linspace(0, 3 * T, 50)
    np.testing.assert_allclose(loadCurve(FMAX, 0.0, F, t), eq8(FMAX, F, t), rtol=1e-12, atol=1e-9 * FMAX)


def test_readable_without_yade():
    # the studies read the applied force at an event on machines without YADE (plain python3)
    import subprocess
    import sys
    code = 'import sys; import ballast.oedometer.loadcurve; print("yade" in sys.modules)'
    out = subprocess.run([sys.executable, '-c', code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == 'False'
