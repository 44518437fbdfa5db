"""Crushable railway ballast for YADE: bulk crushing and abrasion of spherical grains
(R. Dubina and J. Eliáš, "Representation of bulk and surface crushing phenomenon in DEM model of
railway ballast").

The physics lives in the C++ core ``ballast._ballast`` (arrays in, arrays out); this package
re-exports it. The YADE engines ``BallastCrushEngine`` and ``BallastAbrasionEngine`` (module
:mod:`ballast.engines`) are attributes of the package too, imported on first use so that
``import ballast`` works in a plain Python without YADE; the oedometric test is
:mod:`ballast.oedometer`, the parameter studies :mod:`ballast.study` and their analyses
:mod:`ballast.analysis`.
"""
from ._ballast import (abrasionBound, abrasionCheck, contactModulus, crushCheck, effectiveRadius, fabricStress, fatigueCheck,
                       fragmentPattern, grainStresses, hertzPressure, hertzPressureFromForce, keptVolumeFraction,
                       matricesToArray, patternName, placeFragments, principalStresses, randomRotation,
                       sizeStrength, sphereContactBound, vonMises, weibullFactors)
from .geometry import sphereVolume

_ENGINES = ('BallastCrushEngine', 'BallastAbrasionEngine', 'restore')

__all__ = ['abrasionBound', 'abrasionCheck', 'contactModulus', 'crushCheck', 'effectiveRadius', 'fabricStress',
           'fragmentPattern', 'grainStresses', 'hertzPressure', 'hertzPressureFromForce', 'keptVolumeFraction',
           'matricesToArray', 'patternName', 'placeFragments', 'principalStresses', 'randomRotation',
           'sizeStrength', 'sphereContactBound', 'sphereVolume', 'vonMises', 'weibullFactors', 'fatigueCheck'] + list(_ENGINES)


def __getattr__(name):
    """The YADE engines on first use (PEP 562): they need a running YADE, the rest of the package does not."""
    if name in _ENGINES:
        from . import engines
        return getattr(engines, name)
    raise AttributeError('module %r has no attribute %r' % (__name__, name))
