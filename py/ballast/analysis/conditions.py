"""What a study's realizations say at chosen cycles, condition by condition (issue 46, item 4: the prediction
table). A condition is the runs that share the values of the parameters named (`by`: confining, qMax, f, ...),
in whichever of the studies given they lie (named by those values: 'confining=10000 qMax=230000 f=5'),
its realizations their seeds, a realization run in slices read from its last slice (settlement.realizationRuns).
Per realization and cycle N: each quantity's total at N (a strain with its jumped cycles' share,
curvefit.total; at an N a jump went over, the straight line in ln N between the simulated cycles around it), the
breakage index BBI of the last grading taken at or before N, or, for a specimen that failed
(summary.json stoppedBy failure) before N, the cycle it failed in. Per condition and N: how many seeds reached N and
failed before it, and each quantity's mean, smallest and largest over those that reached it, beside a measured curve's
value at N where one is given (a calibration's fit). Any cyclic experiment (the shared cycles.csv); NumPy, pandas, no
YADE."""
import math

import numpy as np
import pandas as pd

from .curvefit import measured, total
from .settlement import realizationRuns


def atCycle(cycle, values, k, N):
    """The value at cycle N of a quantity given at `cycle` (row k the first at or after N): its row's, or for an N that
    a jump went over (between rows k-1 and k) the straight line in ln N between them, which is the jump's own law
    (a jumped cycle's share is b ln(N / n), the simulated part unchanged within the jump)."""
    if cycle[k] == N:
        return float(values[k])
    a, b = math.log(cycle[k - 1]), math.log(cycle[k])
    return float(values[k - 1] + (values[k] - values[k - 1]) * (math.log(N) - a) / (b - a))


def realizationTable(paths, by, quantities, at):
    """A row per realization and cycle of `at` it reached or failed before: condition, runId, seed, cycle, each of
    `quantities` (NaN where it failed), BBI (NaN without a grading by then), failedInCycle (NaN where it did not
    fail by then). ValueError naming a quantity a run did not write."""
    rows = []
    for path, run, c in realizationRuns(paths, by):
        # by the values alone: a condition's runs may lie in several studies
        label = path.partition('[')[2].rstrip(']') or path
        missing = [q for q in quantities if q not in c]
        if missing:
            raise ValueError('conditions: %s wrote no %s in cycles.csv; it has %s' % (
                run.runId, ', '.join(missing), ', '.join(c.columns)))
        totals = {q: total(c, q) for q in quantities}
        failed = (run.summary or {}).get('failedInCycle')
        grading = run.table('grading')
        cycle = c['cycle'].to_numpy()
        for N in at:
            lost = failed is not None and failed <= N
            k = int(np.searchsorted(cycle, N))   # the first row at or after N
            reached = k < len(cycle) and (cycle[k] == N or k > 0)
            if not reached and not lost:
                continue   # not reached (yet)
            row = {'condition': label, 'runId': run.runId, 'seed': run.params.get('seed'), 'cycle': int(N),
                   'failedInCycle': float(failed) if lost else math.nan}
            row.update({q: atCycle(cycle, totals[q], k, N) if reached and not lost else math.nan for q in quantities})
            graded = grading[grading['cycle'] <= N] if grading is not None and 'BBI' in grading else []
            row['BBI'] = float(graded['BBI'].iloc[-1]) if len(graded) else math.nan
            rows.append(row)
    if not rows:
        raise ValueError('conditions: no run of %s reached the cycles %s' % (', '.join(paths), ' '.join(map(str, at))))
    return pd.DataFrame(rows)


def conditionTable(frame, quantities):
    """A row per condition and cycle: seeds (how many reached it), failed (how many failed before it, with the
    cycles they failed in), and per quantity (and BBI) the mean, smallest and largest over the seeds that reached
    it."""
    rows = []
    order = {c: k for k, c in enumerate(dict.fromkeys(frame['condition']))}   # conditions as they first come
    frame = frame.assign(_order=frame['condition'].map(order)).sort_values(['_order', 'cycle'], kind='stable')
    for (label, N), g in frame.groupby(['condition', 'cycle'], sort=False):
        ok = g[g['failedInCycle'].isna()]
        lost = g[g['failedInCycle'].notna()]
        row = {'condition': label, 'cycle': int(N), 'seeds': len(ok), 'failed': len(lost),
               'failedInCycles': ' '.join('%d' % k for k in sorted(lost['failedInCycle'])) if len(lost) else ''}
        for q in list(quantities) + ['BBI']:
            v = ok[q].to_numpy(float)
            row.update({q + '_mean': float(np.mean(v)) if len(v) else math.nan,
                        q + '_min': float(np.min(v)) if len(v) else math.nan,
                        q + '_max': float(np.max(v)) if len(v) else math.nan})
        rows.append(row)
    return pd.DataFrame(rows)


def withMeasured(table, quantities, curves):
    """The condition table with <q>_measured, the measured curve of `curves` {quantity: path} read at each row's
    cycle as curvefit reads it (a running median in N, interpolated in log N). ValueError for a curve of a quantity
    the table does not hold; readReference's CurveError for a malformed file."""
    extra = sorted(set(curves) - set(quantities))
    if extra:
        raise ValueError('conditions: a measured curve is given for %s, not among the quantities (%s)' % (
            ', '.join(extra), ', '.join(quantities)))
    cycles = sorted(set(int(n) for n in table['cycle']))
    values = measured(curves, cycles)
    out = table.copy()
    for q, v in values.items():
        out[q + '_measured'] = out['cycle'].map(dict(zip(cycles, (float(x) for x in v))))
    return out


def markdown(table, quantities, scale=100.0, unit='%'):
    """The condition table as a Markdown table: a row per condition and cycle, each quantity as mean [min, max]
    times `scale` (in `unit`) and beside it its measured value where the table holds one (withMeasured), BBI as mean
    [min, max], and the seeds that failed before that cycle."""
    head = ['condition', 'N', 'seeds']
    for q in quantities:
        head += ['%s [%s]' % (q, unit)] + (['measured [%s]' % unit] if q + '_measured' in table else [])
    head += ['BBI', 'failed before N']
    lines = ['| ' + ' | '.join(head) + ' |', '|' + '---|' * len(head)]

    def cell(row, q, k):
        if not row['seeds']:
            return '-'
        m, lo, hi = (row[q + s] * k for s in ('_mean', '_min', '_max'))
        return '%.3g [%.3g, %.3g]' % (m, lo, hi) if row['seeds'] > 1 else '%.3g' % m
    for row in table.to_dict('records'):
        failed = '%d (in cycle %s)' % (row['failed'], row['failedInCycles'].replace(' ', ', ')) if row['failed'] else ''
        cells = [row['condition'], str(row['cycle']), str(row['seeds'])]
        for q in quantities:
            cells.append(cell(row, q, scale))
            if q + '_measured' in row:   # '-' where the curve does not reach N
                m = row[q + '_measured']
                cells.append('-' if math.isnan(m) else '%.3g' % (m * scale))
        lines.append('| ' + ' | '.join(cells + [cell(row, 'BBI', 1.0), failed]) + ' |')
    return '\n'.join(lines) + '\n'
