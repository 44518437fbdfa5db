"""What each crushing criterion gives a sphere between two flat platens, by hand (docs/calibration.md).

Two opposite forces F along a diameter, at the contact points r from the centre: the fabric stress of
eq. 3 is uniaxial, sigma_zz = 2 F r / V = 3 F / (2 pi r^2). Its von Mises stress (eq. 2) and its major
principal stress are both |sigma_zz|; the largest contact force over d^2 is F / (4 r^2). A grain crushes
when the criterion's stress reaches f_t = ft0 / r^m (eq. 4), so at

    vonMises, majorPrincipal:  F = 2 pi ft0 r^(2-m) / 3
    maxContactForce:           F = 4 ft0 r^(2-m)

(r = d/2). McDowell's characteristic stress of the test is F / d^2.

A grain of any shape (a clump) of volume V and height h between the platens, touching each at any number of
points: with the platens' forces normal and the grain at rest, its torque balance makes the Love-Weber stress
uniaxial whatever the points, sigma_zz = F h / V (the top platen's F at h above the bottom's), so von Mises and
the major principal stress reach f_t = ft0 / r_eq^m at F = f_t V / h (the sphere's 2 pi ft0 r^(2-m) / 3 at h = 2r).
The largest contact force depends on how the points share F: no closed form but the sphere's. Needs no YADE."""
import math

import numpy as np

# the criterion's stress per unit F / d^2 for a sphere between platens: sigma = FACTOR F / d^2
STRESS_PER_F_OVER_D2 = {'vonMises': 6 / math.pi, 'majorPrincipal': 6 / math.pi, 'maxContactForce': 1.0}


def criterionStress(criterion, force, d):
    """The criterion's stress [Pa] of a sphere of diameter d [m] squeezed by `force` [N] between platens."""
    return STRESS_PER_F_OVER_D2[criterion] * np.asarray(force, dtype=float) / np.asarray(d, dtype=float) ** 2


def crushingForce(criterion, r, ft0, m, height=None):
    """The force [N] at which the criterion's stress of a grain of volume-equivalent radius r [m] and height `height`
    [m] between the platens (None: a sphere's, 2r) reaches ft0 / r^m; NaN for maxContactForce on a grain that is not
    a sphere (the force shares out among its contacts)."""
    r = np.asarray(r, dtype=float)
    if height is None:
        d = 2 * r
        return ft0 / r ** m * d ** 2 / STRESS_PER_F_OVER_D2[criterion]
    if criterion == 'maxContactForce':
        return np.full(np.broadcast(r, height).shape, math.nan)
    return ft0 / r ** m * (4 * math.pi / 3 * r ** 3) / np.asarray(height, dtype=float)   # f_t V / h
