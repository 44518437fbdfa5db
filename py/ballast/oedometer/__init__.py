"""``ballast.oedometer`` is the oedometer experiment, :mod:`ballast.experiments.oedometer`: users'
scripts import ``from ballast.oedometer import Oedometer``. This name and its modules
(``ballast.oedometer.parameters``, ...) are that package and its modules themselves, the same objects,
so every class exists once."""
import importlib
import importlib.abc
import importlib.util
import sys

_PREFIX, _TARGET = __name__ + '.', 'ballast.experiments.oedometer.'


class _Alias(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    """ballast.oedometer.X is ballast.experiments.oedometer.X (and ballast.oedometer.callbacks, the refusal
    of format-1 states, stays here)."""

    def find_spec(self, name, path, target=None):
        if name.startswith(_PREFIX) and name != _PREFIX + 'callbacks':
            return importlib.util.spec_from_loader(name, self)
        return None

    def create_module(self, spec):
        return importlib.import_module(_TARGET + spec.name[len(_PREFIX):])

    def exec_module(self, module):
        pass


if not any(isinstance(f, _Alias) for f in sys.meta_path):
    sys.meta_path.insert(0, _Alias())

from ..experiments.oedometer import PARAMS, __all__, __getattr__, check, eq8, loadCurve, packingKey  # noqa: E402,F401
