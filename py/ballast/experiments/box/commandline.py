"""``yade -n -x scripts/box_test.py [--name value ...]``: one box test, every parameter by name (or a
yade-batch row), checked before any work."""
import sys

from .. import commandline
from .declaration import DECLARATION

PROG = 'yade -n -x scripts/box_test.py'


def parser():
    ap = commandline.OneLineParser('box_test.py', DECLARATION.params, prog=PROG, description=(
        'The box test: a sleeper section on a crushable ballast bed in a steel box under repeated loads '
        '(docs/box.md). Every parameter can also be a yade-batch table column.'))
    return commandline.addParameters(ap, DECLARATION.params)


def readParams(argv):
    """defaults <- yade-batch table row <- command line, all checked (experiments.commandline.readParams)."""
    return commandline.readParams(parser(), argv, DECLARATION)


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    from yade import utils

    def cls():
        from .experiment import BoxTest
        return BoxTest
    commandline.experiment(parser(), argv, DECLARATION, cls).run()
    utils.waitIfBatch()
    return 0
