"""The box test (docs/box.md): a sleeper section on a crushable ballast bed in a steel box under
repeated train loads, on the experiment base.

    from ballast.experiments.box import BoxTest
    BoxTest(cycles=3).run()

Modules: :mod:`.declaration`, :mod:`.parameters`, :mod:`.loadhistory` (the sine or a CSV history) and
:mod:`.zones` (where the grains broke), all without YADE; :mod:`.bed` (the bed in layers),
:mod:`.experiment` (BoxTest), :mod:`.outputs`, :mod:`.commandline` (``yade -n -x scripts/box_test.py``).
"""
from .parameters import PARAMS, check

__all__ = ['PARAMS', 'check', 'BoxTest']


def __getattr__(name):
    """The experiment needs YADE, imported on first use: the rest is readable without it."""
    if name == 'BoxTest':
        from .experiment import BoxTest
        return BoxTest
    raise AttributeError('module %r has no attribute %r' % (__name__, name))
