"""``yade -n -x scripts/box_test.py [--name value ...]``: one box test, every parameter by name (or a
yade-batch row), checked before any work."""
from .. import commandline
from .declaration import DECLARATION

SCRIPT = commandline.Script(DECLARATION, 'box_test.py', (
    'The box test: a sleeper section on a crushable ballast bed in a steel box under repeated loads '
    '(docs/box.md). Every parameter can also be a yade-batch table column.'), 'ballast.experiments.box.experiment:BoxTest')
PROG, parser, readParams, main = SCRIPT.prog, SCRIPT.parser, SCRIPT.readParams, SCRIPT.main
