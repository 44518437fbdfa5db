"""The clump grain's shape declarations (issue 47, item 1): elongation, flatness, roundness and the number of
spheres of a clump grain, each a :class:`ballast.params.Param` declared once. The shape builder
(:mod:`ballast.grainkinds.clumpshapes`) takes its defaults and bounds from here, the experiments take the
declarations (:mod:`ballast.experiments.parameters`). Needs no YADE: the study runner reads it in plain Python.
"""
import numbers

from .params import Param, intBetween

MIN_SPHERES, MAX_SPHERES = 5, 200   # a core and four tips at least; more costs CPU for little shape


def ratio(v):
    """A check for an axis ratio in (0, 1]."""
    if isinstance(v, bool) or not isinstance(v, numbers.Real) or not 0 < v <= 1:
        raise ValueError
    return float(v)


# Defaults: choices (a moderately elongated and flat grain), see clumpshapes' doc
CLUMP_SHAPE = {
    'clumpElongation': Param(0.7, '-', "with grain 'clump': the grains' elongation I/L (intermediate over long axis; "
                             'docs/grains.md)', ratio,
                             'a number in (0, 1]'),
    'clumpFlatness': Param(0.6, '-', "with grain 'clump': the grains' flatness S/I (short over intermediate axis)",
                           ratio, 'a number in (0, 1]'),
    'clumpRoundness': Param(1.0, '-', "with grain 'clump': the tips' radius over the core's, t/S (1: as round as the "
                            'core; smaller: sharper tips on tapered arms and smaller random spheres, a more angular '
                            "grain; an upper bound on Wadell's roundness; docs/grains.md)", ratio,
                            'a number in (0, 1]'),
    'clumpSpheres': Param(8, '-', "with grain 'clump': spheres in each grain (a core, four tips and random ones; the "
                          'CPU per grain-step follows their number)', intBetween(MIN_SPHERES, MAX_SPHERES),
                          'an integer in [%d, %d]' % (MIN_SPHERES, MAX_SPHERES)),
}
