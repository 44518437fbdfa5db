"""Reading a run with pandas: the files of one oedometer run as DataFrames.

    /usr/bin/python3 examples/read_run_with_pandas.py RUNDIR

RUNDIR is a run directory of scripts/oedometer.py (results/<run id>/). The columns are those of the
README's output table: fd.csv (t, F, delta, ...), events.csv (one row per crush or abrasion),
grains.csv (every grain at the end: id, position, r, mass, generation, parent, nAbraded, ...), and
summary.json. No YADE needed: Debian's /usr/bin/python3 with python3-pandas.
"""
import json
import os
import sys

import pandas as pd


def read(run):
    """(fd, events, grains, summary) of the run directory `run`: three DataFrames and a dict."""
    fd = pd.read_csv(os.path.join(run, 'fd.csv'))
    events = pd.read_csv(os.path.join(run, 'events.csv'))
    grains = pd.read_csv(os.path.join(run, 'grains.csv'), index_col='id')
    with open(os.path.join(run, 'summary.json')) as f:
        summary = json.load(f)
    return fd, events, grains, summary


def main(run):
    fd, events, grains, summary = read(run)
    peak = fd.loc[fd['F'].idxmax()]
    print('peak grain force %.4g N at delta %.4g mm, t = %.4g s' % (peak['F'], 1e3 * peak['delta'], peak['t']))
    print('events by kind: %s' % events['kind'].value_counts().to_dict())
    crushes = events[events['kind'] == 'crush']
    if len(crushes):
        print('first crush at t = %.4g s: grain %d, r = %.4g m, sigma_e / f_t = %.3f' % (
            crushes['t'].iloc[0], crushes['id'].iloc[0], crushes['radius'].iloc[0],
            (crushes['value'] / crushes['strength']).iloc[0]))
    print('grains by generation: %s' % grains.groupby('generation').size().to_dict())
    print('mass by generation [kg]: %s' % grains.groupby('generation')['mass'].sum().round(6).to_dict())
    print('abraded grains: %d, most often grain %d (%d times)' % (
        (grains['nAbraded'] > 0).sum(), grains['nAbraded'].idxmax(), grains['nAbraded'].max()))
    print('mass lost %.4g kg of %.4g kg (summary.json)' % (summary['massLost'], summary['massInitial']))
    return fd, events, grains, summary


if __name__ == '__main__':
    if len(sys.argv) != 2:
        sys.exit('usage: /usr/bin/python3 examples/read_run_with_pandas.py RUNDIR')
    main(sys.argv[1])
