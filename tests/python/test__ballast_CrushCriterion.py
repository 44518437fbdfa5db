"""Tests of pkg/python/bind_CrushCriterion.cpp: the names of the crushing criteria, the one list crushCheck and
ballast.params take. Each criterion's stress is worked out by hand for a grain under three orthogonal pairs of
compressive forces F_i on its surface: eq. 3 gives sigma_ii = -3 F_i / (2 pi r^2) = -k F_i."""
import math

import numpy as np
import pytest

import ballast._ballast as B
from ballast.engineparams import CRUSH
from ballast.params import ParamError, validate

R, F = 0.02, (3e4, 2e4, 1e4)
K = 3 / (2 * math.pi * R ** 2)
SIGMA = np.diag([-K * f for f in F])[None]


def test_the_names_the_paper_first():
    assert B.criterionNames() == ('vonMises', 'maxContactForce', 'majorPrincipal')


@pytest.mark.parametrize('criterion,stress', [
    ('vonMises', K * math.sqrt(3) * 1e4),   # eq. 2: k sqrt(((3-2)^2 + (2-1)^2 + (1-3)^2) / 2) 1e4
    ('majorPrincipal', K * 3e4),            # the largest principal compression
    ('maxContactForce', 3e4 / (4 * R ** 2)),  # de Bono & McDowell: F_max / d^2
])
def test_each_criterion_is_the_stress_worked_out_by_hand(criterion, stress):
    se, ft, crush = B.crushCheck(SIGMA, [R], 1e300, 0.0, 0.0, criterion, fMax=[3e4])
    assert se[0] == pytest.approx(stress, rel=1e-12)
    assert not crush[0]


def test_the_parameter_takes_exactly_the_cores_names():
    for name in B.criterionNames():
        assert validate('E', CRUSH, 'criterion', name) == name
    assert CRUSH['criterion'].allowed == "'vonMises', 'maxContactForce' or 'majorPrincipal'"
    for bad in ('tresca', 'VonMises', ''):
        with pytest.raises(ParamError, match="expected 'vonMises', 'maxContactForce' or 'majorPrincipal'"):
            validate('E', CRUSH, 'criterion', bad)
        with pytest.raises(ValueError) as e:
            B.crushCheck(SIGMA, [R], 2e5, 1.0, 0.0, bad)
        assert str(e.value) == "criterion: expected 'vonMises', 'maxContactForce' or 'majorPrincipal', got '%s'" % bad
