"""Geometry shared by the package: the one sphere volume of the Python side (the C++ core has its own
in FabricStress), the radius of the sphere of a volume (a grain kind's equivalent radius,
ballast.grainkinds), a contact's stiffness and a sample's mean grain volume."""
import math

import numpy as np


def sphereVolume(r):
    """4/3 pi r^3 [m^3] of a radius [m] or an array of radii."""
    return 4.0 / 3.0 * math.pi * np.asarray(r, dtype=float) ** 3 if np.ndim(r) else 4.0 / 3.0 * math.pi * float(r) ** 3


def equivalentRadius(v):
    """(3 v / (4 pi))^(1/3) [m]: the radius of the sphere of volume v [m^3] (a float or an array)."""
    return (3.0 / (4.0 * math.pi) * np.asarray(v, dtype=float)) ** (1.0 / 3.0) if np.ndim(v) else \
        (3.0 / (4.0 * math.pi) * float(v)) ** (1.0 / 3.0)


def frictPhysStiffness(E1, nu1, r1, E2, nu2, r2):
    """(kn [N/m], ks [N/m]) YADE's Ip2_FrictMat_FrictMat_FrictPhys gives a contact of reference radii r1, r2
    [m]: harmonic means of E r and of E r nu over the two sides (0 shear stiffness if a nu is 0)."""
    ka, kb = E1 * r1, E2 * r2
    sa, sb = ka * nu1, kb * nu2
    return 2 * ka * kb / (ka + kb), (2 * sa * sb / (sa + sb) if sa > 0 and sb > 0 else 0.0)


def meanCubedDiameterVolume(dMin, dMax):
    """Mean volume [m^3] of a sphere whose diameter is uniform in [dMin, dMax]: pi/6 E[d^3]."""
    return math.pi / 6 * (dMax ** 4 - dMin ** 4) / (4 * (dMax - dMin))
