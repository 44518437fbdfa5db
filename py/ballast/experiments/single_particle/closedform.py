"""What each crushing criterion gives a sphere between two flat platens, by hand (docs/calibration.md).

Two opposite forces F along a diameter, at the contact points r from the centre: the fabric stress of
eq. 3 is uniaxial, sigma_zz = 2 F r / V = 3 F / (2 pi r^2). Its von Mises stress (eq. 2) and its major
principal stress are both |sigma_zz|; the largest contact force over d^2 is F / (4 r^2). A grain crushes
when the criterion's stress reaches f_t = ft0 / r^m (eq. 4), so at

    vonMises, majorPrincipal:  F = 2 pi ft0 r^(2-m) / 3
    maxContactForce:           F = 4 ft0 r^(2-m)

(r = d/2). McDowell's characteristic stress of the test is F / d^2. Needs no YADE."""
import math

import numpy as np

# the criterion's stress per unit F / d^2 for a sphere between platens: sigma = FACTOR F / d^2
STRESS_PER_F_OVER_D2 = {'vonMises': 6 / math.pi, 'majorPrincipal': 6 / math.pi, 'maxContactForce': 1.0}


def criterionStress(criterion, force, d):
    """The criterion's stress [Pa] of a sphere of diameter d [m] squeezed by `force` [N] between platens."""
    return STRESS_PER_F_OVER_D2[criterion] * np.asarray(force, dtype=float) / np.asarray(d, dtype=float) ** 2


def crushingForce(criterion, r, ft0, m):
    """The force [N] at which the criterion's stress of a sphere of radius r [m] reaches ft0 / r^m."""
    d = 2 * np.asarray(r, dtype=float)
    return ft0 / (d / 2) ** m * d ** 2 / STRESS_PER_F_OVER_D2[criterion]
