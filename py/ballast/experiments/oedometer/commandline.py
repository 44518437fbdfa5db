"""``yade scripts/oedometer.py``: the parameters from the command line (``--name value``) and from a
yade-batch table row (a column per name), every one checked before any work, then one realization."""
import argparse
import sys

from .. import commandline
from .declaration import DECLARATION
from .parameters import PARAMS

PROG = 'yade scripts/oedometer.py'
REBUILD = 'rebuild'


def parser():
    ap = commandline.OneLineParser('oedometer.py', PARAMS, prog=PROG, formatter_class=argparse.RawDescriptionHelpFormatter,
                                   description='One realization of the oedometric test of Dubina & Elias (sections 4-5). '
                                   'Every parameter can also be a yade-batch table column of the same name. Numbers are '
                                   'written in decimal (1e6, 0.5), flags as 0 or 1. See docs/oedometer.md.')
    commandline.addParameters(ap, PARAMS)
    ap.add_argument('--' + REBUILD, default=None, metavar='RUNDIR', action=commandline.Once,
                    help='instead of a run: the outputs of the killed run in RUNDIR (run.json "running", no summary.json) '
                    'up to its last state, into a new folder RUNDIR-2 (Oedometer.rebuild)')
    return ap


def readParams(argv):
    """defaults <- yade-batch table row <- command line, all checked (experiments.commandline.readParams)."""
    return commandline.readParams(parser(), argv, DECLARATION)


def main(argv=None):
    """The command line: exit status 2 and a message naming the parameter on a bad value."""
    from yade import utils
    argv = sys.argv[1:] if argv is None else argv
    given = commandline.parse(parser(), argv)
    rebuild = given[REBUILD]
    if rebuild is not None:
        others = sorted(k for k, v in given.items() if v is not None and k != REBUILD)
        if others:   # the saved run's parameters are its own: an option beside --rebuild would be ignored
            parser().refuse('--rebuild takes no other option (got --%s): it writes the saved run\'s outputs as the run '
                            'was, into RUNDIR-2' % ', --'.join(others))
        from .experiment import Oedometer
        try:
            run = Oedometer.rebuild(rebuild)
        except (OSError, RuntimeError) as e:
            sys.stderr.write('oedometer.py: --rebuild %s: %s\n' % (rebuild, e))
            sys.exit(2)
        return run, run.summary()

    def cls():
        from .experiment import Oedometer
        return Oedometer
    ap = parser()
    run = commandline.experiment(ap, argv, DECLARATION, cls)
    summary = commandline.run(ap, run)
    utils.waitIfBatch()
    return run, summary
