"""``yade -n -x scripts/triaxial.py [--name value ...]``: one triaxial test, every parameter by name (or a
yade-batch row), checked before any work."""
from .. import commandline
from .declaration import DECLARATION

SCRIPT = commandline.Script(DECLARATION, 'triaxial.py', (
    'The cyclic triaxial test: a crushable ballast specimen under a membrane at the confining pressure, the deviator '
    'cycled (docs/triaxial.md). Every parameter can also be a yade-batch table column.'),
    'ballast.experiments.triaxial.experiment:TriaxialTest')
PROG, parser, readParams, main = SCRIPT.prog, SCRIPT.parser, SCRIPT.readParams, SCRIPT.main
