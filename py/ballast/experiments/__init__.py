"""The experiments of the package, one folder each (``ballast.experiments.<name>``), all on the base
:class:`ballast.experiments.base.Experiment`. Each folder has a ``declaration`` module that needs no
YADE: what a study needs to know of the experiment (its parameters and their check, which runs share a
prepared sample, its command line, which files its records thin). A new experiment is a new folder; it
is found here by its name, so nothing else is edited.
"""
import importlib
import os

from .declaration import Declaration

__all__ = ['Declaration', 'declaration', 'names']


def names():
    """The experiments in this folder (those with a declaration module)."""
    here = os.path.dirname(__file__)
    return sorted(n for n in os.listdir(here)
                  if os.path.isfile(os.path.join(here, n, 'declaration.py')))


def declaration(name):
    """The :class:`Declaration` of the experiment `name` ('oedometer', ...); ValueError naming the known ones."""
    if name not in names():
        raise ValueError('experiment = %r is not allowed: expected one of %s' % (name, ', '.join(names())))
    return importlib.import_module('%s.%s.declaration' % (__name__, name)).DECLARATION
