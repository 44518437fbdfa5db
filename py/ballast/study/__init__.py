"""Parameter studies of the oedometric test: one row of a yade-batch table is one run of the
oedometer's command line (``yade -n -x scripts/oedometer.py``), on the cores of this machine or
through a Dask scheduler, skipping what already finished; then the finished runs aggregated into
the tables and figures of the paper. ``scripts/study.py`` and ``scripts/aggregate.py`` are the
command lines; see docs/studies.md.

    from ballast.study import Study, LocalExecutor
    Study('studies/ci.table', script='scripts/oedometer.py', out='/tmp/ci').run(LocalExecutor(2))

Modules: :mod:`.table` (reading, checking and writing tables), :mod:`.runner` (one run: the yade
process, its files, shipping to workers without a shared file system), :mod:`.executors` (local,
Dask), :mod:`.study` (Study: bookkeeping, restart, status), :mod:`.aggregate` (StudyData, CSV,
figures), :mod:`.options` (the runner's options, StudyError), :mod:`.files` (atomic writes, the
code's sha1). Needs no running YADE: reading a table imports YADE's table reader, the runs are
yade processes.
"""
from .aggregate import StudyData
from .executors import DaskExecutor, LocalExecutor, makeExecutor
from .options import StudyError
from .study import Study, status
from .table import Table, gridTable

__all__ = ['DaskExecutor', 'LocalExecutor', 'Study', 'StudyData', 'StudyError', 'Table', 'gridTable', 'makeExecutor',
           'status']
