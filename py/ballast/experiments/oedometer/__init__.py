"""The oedometric test of the paper (sections 4-5), on the experiment base.

    from ballast.oedometer import Oedometer      # in a yade session (ballast.oedometer is this package)
    run = Oedometer(seed=2, f=4, pattern=14)
    run.prepare(); run.load(); run.summary()

Modules: :mod:`.declaration` (what a study needs), :mod:`.parameters` (every parameter, declared once)
and :mod:`.loadcurve` (eq. 8 and its cycles), all without YADE; :mod:`.rig` (the cylinder and the
materials the loading uses), :mod:`.packing` (the sample, on the shared builder :mod:`..sample`), :mod:`.loading` (the load on a
plate), :mod:`.probe` (what the outputs read), :mod:`.outputs` (files, VTK, yade.plot),
:mod:`.experiment` (Oedometer), :mod:`.commandline` (``yade scripts/oedometer.py``).
"""
from .loadcurve import eq8, loadCurve
from .parameters import PARAMS, check, packingKey

_YADE = {'Oedometer': 'experiment', 'StoredPacking': 'packing', 'PlateLoad': 'loading', 'ServoLoad': 'loading',
         'DisplacementLoad': 'loading', 'Outputs': 'outputs', 'Probe': 'probe', 'Rig': 'rig'}

__all__ = ['PARAMS', 'check', 'eq8', 'loadCurve', 'packingKey'] + list(_YADE)


def __getattr__(name):
    """The classes that need YADE, imported on first use: the parameters are readable without it."""
    if name in _YADE:
        import importlib
        return getattr(importlib.import_module('.' + _YADE[name], __name__), name)
    raise AttributeError('module %r has no attribute %r' % (__name__, name))
