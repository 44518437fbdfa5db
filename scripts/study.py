#!/usr/bin/python3
"""Parameter studies of an experiment, the oedometric test unless --experiment names another
(ballast.study): one row of a yade-batch table is one run.

    scripts/study.py run studies/frequency.table                      all cores of this machine
    scripts/study.py run studies/frequency.table --executor dask --scheduler tcp://HOST:8786
    scripts/study.py status results/studies/frequency                done, failed, how far started runs are
    scripts/study.py grid seed=1:5 f=0.25,0.5,1,2,4,8 -o studies/frequency.table
"""
import argparse
import contextlib
import os
import signal
import sys

from ballast.experiments import names
from ballast.study import Study, StudyError, gridTable, makeExecutor, status
from ballast.study.options import DEFAULT_EXPERIMENT, addArguments, experimentDeclaration
from ballast.study.study import __doc__ as STUDY_DOC

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)  # the repository: the declarations name their scripts relative to it


def addExperiment(parser):
    parser.add_argument('--experiment', choices=names(), default=DEFAULT_EXPERIMENT,
                        help='the experiment whose parameters the table holds (default %(default)s)')


def scriptOf(a):
    """--script, else the experiment's own command line (its declaration's script, in this repository)."""
    return a.script or os.path.join(ROOT, experimentDeclaration(a.experiment).script)


def main(argv=None):
    kw = dict(allow_abbrev=False, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap = argparse.ArgumentParser(prog='scripts/study.py', description=__doc__, epilog='See docs/studies.md.', **kw)
    sub = ap.add_subparsers(dest='command', metavar='COMMAND', required=True)
    ar = sub.add_parser('run', help='run (or carry on) a study table', description=STUDY_DOC, **kw)
    ar.add_argument('table', metavar='TABLE', help='yade-batch table, a run per row, columns named as the parameters of the experiment')
    addExperiment(ar)
    ar.add_argument('--executor', choices=('local', 'dask'), default='local', help='local: on this machine; dask: through a scheduler')
    where = ar.add_mutually_exclusive_group()
    where.add_argument('--scheduler', metavar='ADDRESS', help='dask: address of the scheduler, e.g. tcp://127.0.0.1:8786')
    where.add_argument('--scheduler-file', metavar='JSON', help='dask: instead, the file dask-scheduler --scheduler-file wrote')
    ar.add_argument('--out', metavar='DIR', help='study directory (default results/studies/<table name without .table>)')
    ar.add_argument('--packings', metavar='DIR', help='stored packings (default: "packings" next to --out, shared by the studies there)')
    ar.add_argument('--records', metavar='DIR', help='also keep a compact record of every finished run here (a folder in the '
                    'repository, e.g. docs/studies/NAME) and skip the rows recorded there: see docs/studies.md')
    ar.add_argument('--script', metavar='PY', help="the experiment's command line (default: its declaration's, "
                    '%s for the %s)' % (os.path.join(ROOT, experimentDeclaration().script), DEFAULT_EXPERIMENT))
    ar.add_argument('--yade', default='yade', metavar='EXE', help='YADE executable on the machines that run (default %(default)s)')
    addArguments(ar, 'jobs', 'connectTimeout', 'lines', 'timeout', 'nice', 'progress')
    ar.add_argument('--ship', action='store_true', help='dask: send script, table and packings with every task and the results back, '
                    'even to workers that see --out (as for machines without a shared file system)')
    ar.add_argument('--skip-failed', action='store_true', help='do not redo the runs that failed before')
    ar.add_argument('--verbose', '-v', action='store_true', help='a line also when a run starts')
    ar.add_argument('--dry-run', action='store_true', help='list what would run and stop')
    ag = sub.add_parser('grid', help='write a table: every combination of the values given', description='Write a yade-batch table with '
                        'every combination of the values; the first NAME varies slowest, e.g. grid seed=1:60 Tc=0,7.8125e-5,0.04', **kw)
    ag.add_argument('axes', nargs='+', metavar='NAME=VALUES', help='V1,V2,... or A:B (integers A to B); NAME! marks the run id columns')
    ag.add_argument('--fixed', action='append', default=[], metavar='NAME=V', help='a column with the same value in every row')
    ag.add_argument('--comment', action='append', default=[], help='a comment line at the top')
    ag.add_argument('--output', '-o', metavar='FILE', help='write here (default: standard output)')
    addExperiment(ag)
    sub.add_parser('status', help='what a study directory holds', **kw).add_argument('out', metavar='OUT', help='the study directory')
    a = ap.parse_args(argv)
    for sig in (signal.SIGTERM, signal.SIGHUP):  # a killed study (ssh hang-up, scancel) stops its runs as Ctrl-C does
        signal.signal(sig, signal.default_int_handler)
    try:
        if a.command == 'status':
            status(a.out)
        elif a.command == 'grid':
            text, n = gridTable(a.axes, a.fixed, a.comment, 'scripts/study.py grid ' + ' '.join(a.axes + ['--fixed ' + f for f in a.fixed]),
                                declaration=a.experiment)
            with open(a.output, 'w') if a.output else contextlib.nullcontext(sys.stdout) as fh:
                fh.write(text)
            sys.stderr.write('%s: %d rows\n' % (a.output, n) if a.output else '')
        elif a.dry_run:
            Study(a.table, scriptOf(a), a.out, a.packings, a.lines, records=a.records, experiment=a.experiment).dryRun()
        else:
            executor = makeExecutor(a.executor, a.jobs, a.scheduler, a.scheduler_file, a.connect_timeout, a.yade)
            study = Study(a.table, scriptOf(a), a.out, a.packings, a.lines, a.yade, a.nice, a.timeout, a.ship, a.skip_failed,
                          a.progress, a.verbose, a.records, a.experiment)
            rc = study.run(executor)
            if rc in (0, 1):  # finished
                print('tables and figures: %s %s' % tuple(min(p, os.path.relpath(p), key=len) for p in (HERE + '/aggregate.py', study.out)))
            return rc
        return 0
    except StudyError as e:
        print('study.py: %s' % e, file=sys.stderr)
        return 2


if __name__ == '__main__':
    try:
        sys.exit(main())
    except BrokenPipeError:  # output piped into head & co.
        sys.exit(0)
