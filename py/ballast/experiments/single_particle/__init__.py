"""The single-particle crushing test (docs/calibration.md), on the experiment base: what strength the
model gives a grain between two platens, its Weibull statistics, and the calibration of ft0, m and the
Weibull modulus from measured strengths.

    from ballast.experiments.single_particle import SingleParticle
    SingleParticle(n=100, weibullModulus=3).run()

Modules: :mod:`.declaration`, :mod:`.parameters`, :mod:`.closedform` (each criterion's crushing force
by hand), :mod:`.strengths` (survival, Weibull fits, the size law, the calibration's fit) and
:mod:`.calibration`, all without YADE; :mod:`.experiment` (SingleParticle), :mod:`.outputs`,
:mod:`.commandline` (``yade -n -x scripts/single_particle.py``).
"""
from .parameters import PARAMS, check

__all__ = ['PARAMS', 'check', 'SingleParticle']


def __getattr__(name):
    """The experiment needs YADE, imported on first use: the rest is readable without it."""
    if name == 'SingleParticle':
        from .experiment import SingleParticle
        return SingleParticle
    raise AttributeError('module %r has no attribute %r' % (__name__, name))
