"""A study's finished runs as two tables (docs/studies.md, "Aggregating"):

    runs.csv         one line per finished run: the studied parameter, seed, the results the experiment
                     declares (its summary.json and what its files give) and every parameter of the run
    stats.csv        one line per value of the studied parameter: number of runs, mean and standard
                     deviation (sample, n-1) of each result the experiment declares a statistic

The tests and figures that go with them are ballast.analysis.report's (scripts/aggregate.py).
"""
import csv
import math
import os

import numpy as np


def label(v):
    """A parameter's value as a table cell and a figure label: floats by %g."""
    return '%g' % v if isinstance(v, float) else str(v)


def count(n, noun):
    """'1 run', '3 runs'."""
    return '%d %s%s' % (n, noun, '' if n == 1 else 's')


def fmt(v):
    """A CSV cell: floats in full (repr), missing and NaN empty."""
    if v is None or (isinstance(v, float) and math.isnan(v)):
        return ''
    return repr(v) if isinstance(v, float) else str(v)


def meanStd(xs):
    """Mean and sample standard deviation (n-1) of xs; NaN where undefined (std of one run)."""
    mean = float(np.mean(xs)) if xs else float('nan')
    return mean, float(np.std(xs, ddof=1)) if len(xs) > 1 else float('nan')


def stats(data):
    """[{value, n, <result>_mean, <result>_std}] per value of the studied parameter of `data` (a
    ballast.study.data.StudyData), for the results its declaration makes statistics; a run without a
    result is left out of that result's."""
    out = []
    for v in data.values:
        rs = [r for r in data.runs if r.value == v]
        st = {'value': v, 'n': len(rs)}
        for k in data.declaration.statistics:
            st[k + '_mean'], st[k + '_std'] = meanStd([float(r.summary[k]) for r in rs if r.summary.get(k) is not None])
        out.append(st)
    return out


def writeCsv(data, outDir):
    """runs.csv and stats.csv of `data` (StudyData) in outDir; returns their paths."""
    d = data.declaration
    runsCsv = os.path.join(outDir, 'runs.csv')
    with open(runsCsv, 'w', newline='') as fh:
        w = csv.writer(fh)
        # every parameter of every run, as the run read it, after the results
        names = sorted(set(k for r in data.runs for k in r.params) - {data.param, 'seed'})
        w.writerow(['line', 'runId', data.param, 'seed'] + ['%s [%s]' % kv for kv in d.results] + [
            '%s [%s]' % (k, d.params[k].unit if k in d.params else '-') for k in names])
        for r in sorted(data.runs, key=lambda r: r.line):
            w.writerow([r.line, r.runId, label(r.value), r.seed] + [fmt(r.summary.get(k)) for k, _ in d.results] +
                       [fmt(r.params.get(k)) for k in names])
    statsCsv = os.path.join(outDir, 'stats.csv')
    units = dict(d.results)
    with open(statsCsv, 'w', newline='') as fh:
        w = csv.writer(fh)
        w.writerow([data.param, 'n'] + sum([['%s_mean [%s]' % (k, units[k]), '%s_std [%s]' % (k, units[k])]
                                            for k in d.statistics], []))
        for st in stats(data):
            w.writerow([label(st['value']), st['n']] + sum([[fmt(st[k + '_mean']), fmt(st[k + '_std'])]
                                                            for k in d.statistics], []))
    return runsCsv, statsCsv
