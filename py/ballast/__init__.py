"""Crushable railway ballast for YADE: bulk crushing and abrasion of spherical grains
(R. Dubina and J. Eliáš, "Representation of bulk and surface crushing phenomenon in DEM model of
railway ballast").

The physics lives in the C++ core ``ballast._ballast`` (arrays in, arrays out); this package
re-exports it. The YADE engines are in :mod:`ballast.engines` and need a running YADE.
"""
from ._ballast import (abrasionBound, abrasionCheck, contactModulus, crushCheck, effectiveRadius, fabricStress,
                       fragmentPattern, grainStresses, hertzPressure, hertzPressureFromForce, keptVolumeFraction,
                       matricesToArray, patternName, placeFragments, principalStresses, randomRotation,
                       sizeStrength, sphereContactBound, vonMises)

__all__ = ['abrasionBound', 'abrasionCheck', 'contactModulus', 'crushCheck', 'effectiveRadius', 'fabricStress',
           'fragmentPattern', 'grainStresses', 'hertzPressure', 'hertzPressureFromForce', 'keptVolumeFraction',
           'matricesToArray', 'patternName', 'placeFragments', 'principalStresses', 'randomRotation',
           'sizeStrength', 'sphereContactBound', 'vonMises']
