"""Parameter studies of any experiment of ballast.experiments (the oedometer unless named): one row of
a yade-batch table is one run of the experiment's command line (``yade -n -x scripts/oedometer.py``),
on the cores of this machine or through a Dask scheduler, skipping what already finished; then the
finished runs read back and aggregated into runs.csv and stats.csv. ``scripts/study.py`` is the
command line; see docs/studies.md. The experiment is known by its declaration
(:func:`ballast.experiments.declaration`); the analyses of the studies are :mod:`ballast.analysis`.

    from ballast.study import Study, LocalExecutor
    Study('studies/ci.table', script='scripts/oedometer.py', out='/tmp/ci').run(LocalExecutor(2))

Modules: :mod:`.table` (writing tables: a grid; the one reader of the yade-batch tables is
:mod:`ballast.tables`), :mod:`.runner` (one run: its work folder, its files, shipping to workers without
a shared file system), :mod:`.process` (a run's yade process, its watchdog, stopping it),
:mod:`.attempts` (the work directory: locks, logs, runs kept to resume), :mod:`.executors` (local,
Dask), :mod:`.study` (Study: checks, bookkeeping, restart), :mod:`.progress` (what a study says while
it runs and its status after), :mod:`.records` (the compact records kept in the repository),
:mod:`.data` (a run and a study read back as DataFrames: read_run, StudyData), :mod:`.aggregate`
(runs.csv, stats.csv), :mod:`.options` (the runner's options, StudyError); atomic writes and the code's
sha1 are :mod:`ballast.runfiles`'. Needs no running YADE: reading a table imports YADE's table reader,
the runs are yade processes.
"""
from .data import StudyData, StudyRuns, read_run
from .executors import DaskExecutor, LocalExecutor, makeExecutor
from .options import StudyError
from .progress import status
from .study import Study
from ..tables import Table, tableRow
from .table import gridTable

__all__ = ['DaskExecutor', 'LocalExecutor', 'Study', 'StudyData', 'StudyError', 'StudyRuns', 'Table', 'gridTable',
           'makeExecutor', 'read_run', 'status', 'tableRow']
