"""The applied load of section 4 as a function of loading time (no YADE): eq. 8 up to its peak, and the
cycles that follow it. loading applies it; the studies read the applied force at an event from it."""
import math

import numpy as np


def eq8(Fmax, f, t):
    """Eq. 8: the force [N] at loading time t [s] (a number or an array)."""
    if np.ndim(t):
        return Fmax / 2 * (np.sin(2 * math.pi * f * np.asarray(t, dtype=float) - math.pi / 2) + 1)
    return Fmax / 2 * (math.sin(2 * math.pi * f * t - math.pi / 2) + 1)


def halfLoadTime(f):
    """The loading time [s] at which eq. 8 first passes Fmax/2: a quarter of the period, 1/(4f)."""
    return 0.25 / f


def peakTime(f):
    """The loading time [s] of eq. 8's peak, Fmax: half the period, 1/(2f)."""
    return 0.5 / f


def loadCurve(Fmax, Fmin, f, t):
    """The load [N] at loading time t [s]: eq. 8 up to its peak at T/2 = 1/(2f), then cycles between Fmax
    and Fmin, Fmin + (Fmax - Fmin)/2 [1 + cos(2 pi f (t - T/2))]; with Fmin = 0 it is eq. 8 at every t."""
    t = np.asarray(t, dtype=float)
    later = Fmin + (Fmax - Fmin) / 2 * (1 + np.cos(2 * math.pi * f * (t - peakTime(f))))
    F = np.where(t <= peakTime(f), eq8(Fmax, f, t), later)
    return F if F.ndim else float(F)
