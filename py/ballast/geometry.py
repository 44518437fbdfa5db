"""Sphere geometry shared by the package (the one sphere volume of the Python side; the C++ core has
its own in FabricStress)."""
import math

import numpy as np


def sphereVolume(r):
    """4/3 pi r^3 [m^3] of a radius [m] or an array of radii."""
    return 4.0 / 3.0 * math.pi * np.asarray(r, dtype=float) ** 3 if np.ndim(r) else 4.0 / 3.0 * math.pi * float(r) ** 3


def meanCubedDiameterVolume(dMin, dMax):
    """Mean volume [m^3] of a sphere whose diameter is uniform in [dMin, dMax]: pi/6 E[d^3]."""
    return math.pi / 6 * (dMax ** 4 - dMin ** 4) / (4 * (dMax - dMin))
