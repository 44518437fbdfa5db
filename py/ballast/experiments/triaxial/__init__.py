"""The large-scale cyclic triaxial test (docs/triaxial.md): a cylindrical ballast specimen under a flexible membrane
at the confining pressure, consolidated, then the deviator cycled, on the experiment base.

    from ballast.experiments.triaxial import TriaxialTest
    TriaxialTest(cycles=3).run()

Modules: :mod:`.declaration`, :mod:`.parameters` and :mod:`.strains` (strains from the boundary, the measured curves'
reader), all without YADE; :mod:`.specimen` (the specimen in its mould), :mod:`.membrane` (the membrane's load),
:mod:`.recorder`, :mod:`.experiment` (TriaxialTest), :mod:`.outputs`, :mod:`.commandline`
(``yade -n -x scripts/triaxial.py``).
"""
from .parameters import PARAMS, check

__all__ = ['PARAMS', 'check', 'TriaxialTest']


def __getattr__(name):
    """The experiment needs YADE, imported on first use: the rest is readable without it."""
    if name == 'TriaxialTest':
        from .experiment import TriaxialTest
        return TriaxialTest
    raise AttributeError('module %r has no attribute %r' % (__name__, name))
