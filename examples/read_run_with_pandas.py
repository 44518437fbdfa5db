"""Reading a run with pandas: every CSV of a run's folder as a DataFrame, summary.json as a dict, whatever the
experiment (oedometer, box, single-particle, triaxial).

    /usr/bin/python3 examples/read_run_with_pandas.py RUNDIR

RUNDIR is a run directory (results/<run id>/, or a study record's docs/studies/<study>/runs/<run id>/). The
columns are those of each experiment's output table (README, docs/box.md, docs/calibration.md, docs/triaxial.md):
the oedometer's fd.csv, events.csv, grains.csv; the box's cycles.csv, samples.csv, crushes.csv, grading.csv,
zones.csv; the single-particle test's strengths.csv, curves.csv; the triaxial test's cycles.csv, samples.csv,
grading.csv (or monotonic.csv). No YADE needed: Debian's /usr/bin/python3 with python3-pandas.
"""
import glob
import json
import os
import sys

import pandas as pd


def read(run):
    """({file name without .csv: DataFrame}, summary.json as a dict) of the run directory `run`. ValueError in one
    line where `run` is not a run's folder."""
    if not os.path.isdir(run):
        raise ValueError('%s: no such folder (give a run directory, results/<run id>/)' % run)
    path = os.path.join(run, 'summary.json')
    if not os.path.isfile(path):
        raise ValueError('%s: no summary.json: not a finished run (a killed one is rebuilt or resumed first)' % run)
    with open(path) as f:
        summary = json.load(f)
    frames = {os.path.basename(f)[:-4]: pd.read_csv(f, index_col='id' if os.path.basename(f) == 'grains.csv' else None)
              for f in sorted(glob.glob(os.path.join(run, '*.csv')))}
    return frames, summary


def oedometer(f, summary):
    fd, events, grains = f['fd'], f['events'], f['grains']
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


def box(f, summary):
    c = f['cycles']
    print('%d cycles: settlement %.4g mm after the first, %.4g mm after the last (resilient %.4g mm)' % (
        len(c), 1e3 * c.settlement.iloc[0], 1e3 * c.settlement.iloc[-1], 1e3 * c.resilient.iloc[-1]))
    print('crushes by zone: %s' % f['crushes']['zone'].value_counts().to_dict())


def triaxial(f, summary):
    if 'monotonic' in f:
        m = f['monotonic']
        k = m.q.idxmax()
        print('monotonic: peak q %.4g kPa at %.3g %% axial strain' % (m.q[k] / 1e3, 100 * m.axialStrain[k]))
        return
    c = f['cycles']
    print('%d cycles: axial strain %.4g %%, volumetric %.4g %% after the last; resilient modulus %.4g MPa' % (
        len(c), 100 * c.axialStrain.iloc[-1], 100 * c.volumetricStrain.iloc[-1], c.resilientModulus.iloc[-1] / 1e6))


def singleParticle(f, summary):
    s = f['strengths']
    crushed = s[s.crushed.astype(bool)]
    print('%d grains, %d crushed; F/d^2 at the crush by size class [MPa]: %s' % (
        len(s), len(crushed), (crushed.groupby('sizeClass').forceOverD2.median() / 1e6).round(2).to_dict()))


SAY = {'oedometer': oedometer, 'box': box, 'triaxial': triaxial, 'single_particle': singleParticle}


def main(run):
    frames, summary = read(run)
    # records of before 2026-12 (the oedometer's, the single-particle test's) do not name their experiment
    kind = summary.get('experiment') or ('single_particle' if 'strengths' in frames else 'oedometer')
    print('%s run %s: %s' % (kind, summary.get('runId', os.path.basename(run.rstrip('/'))),
                            ', '.join('%s.csv (%d rows)' % (k, len(v)) for k, v in frames.items())))
    SAY.get(kind, lambda f, s: None)(frames, summary)
    if 'massLost' in summary and 'massInitial' in summary:
        print('mass lost %.4g kg of %.4g kg (summary.json)' % (summary['massLost'], summary['massInitial']))
    return frames, summary


if __name__ == '__main__':
    if len(sys.argv) != 2:
        sys.exit('usage: /usr/bin/python3 examples/read_run_with_pandas.py RUNDIR')
    try:
        main(sys.argv[1])
    except ValueError as e:
        sys.exit('read_run_with_pandas.py: %s' % e)
