"""Does an option change the answer? Two studies of a cyclic experiment run on the same realizations (a seed is one
bed or specimen), one with the option (a quasi-static time scaling, say) and one without, compared seed by seed on
what cycles.csv says after chosen cycles (settlement, resilient, tilt, ...; any column of the shared schema or an
experiment's own).

Per quantity and cycle N, over the seeds both reached, with d_s = option - reference on seed s:
- the bias: the paired t test of mean(d) = 0 (two-sided, at alpha);
- the seed scatter: s_seed, the standard deviation of the reference's values across seeds (ddof 1), what one bed
  differs from another;
- within the scatter: the two one-sided tests of equivalence (TOST) with the margin s_seed: the 1 - 2 alpha interval
  of mean(d), mean(d) +- t(1 - alpha, n - 1) sd(d) / sqrt(n), lies inside (-s_seed, +s_seed). Then the option moves
  the answer less than a change of bed does. Neither a bias nor that shown: the seeds are too few to say.
The margin is itself estimated from the seeds (with 5 seeds it is uncertain by about a third); the verdict says
what these seeds show, not more. NumPy, pandas, scipy; no YADE."""
import math

import numpy as np
import pandas as pd

from .effects import meanInterval
from .pairs import common, oneRunPerSeed, parseSelection
from .settlement import realizationRuns, total, variantLabel

VERDICTS = ('changed', 'within the seed scatter', 'not shown either way')


def selection(text):
    """A study's runs as the command line names them: 'PATH', or 'PATH[NAME=VALUE ...]' for its runs with those
    parameter values (a study whose table holds both the option's rows and the reference's). Returns (path, the
    label values() gives those runs: settlement.variantLabel's spelling, a number as %g: 1e-3 is 0.001), the
    names. ValueError for a selection that is not NAME=VALUE pairs."""
    path, chosen = parseSelection(text, 'agreement')
    if not chosen:
        return text, text, ()
    names = tuple(sorted(chosen))
    return path, variantLabel(path, chosen, names), names


def values(paths, quantities, at, by=()):
    """A DataFrame, a row per realization of the studies at `paths` and cycle of `at` it reached: study (the path,
    or with `by` the path and the run's values of those parameters, settlement.variantLabel), runId, seed, cycle and
    each of `quantities` from its cycles.csv (a realization run in slices read from its last slice; settlement with
    the jumped cycles' share when cycle jumping ran). ValueError naming a quantity no run has."""
    rows = []
    for label, run, c in realizationRuns(paths, by):
        missing = [q for q in quantities if q != 'settlement' and q not in c]
        if missing:
            raise ValueError('agreement: %s wrote no %s in cycles.csv; it has %s' % (
                run.runId, ', '.join(missing), ', '.join(c.columns)))
        c = c.assign(settlement=total(c))
        for r in c[c['cycle'].isin(list(at))].itertuples(index=False):
            rows.append(dict({'study': label, 'runId': run.runId, 'seed': run.params.get('seed'), 'cycle': int(r.cycle)},
                             **{q: float(getattr(r, q)) for q in quantities}))
    if not rows:
        raise ValueError('agreement: no run of %s reached the cycles %s' % (', '.join(paths), ' '.join(map(str, at))))
    return pd.DataFrame(rows)


def test(differences, reference, alpha=0.05):
    """The verdict on paired differences `differences` (option - reference, one per seed) given the reference's
    values on the same seeds: a dict with seeds, the reference's mean and seed standard deviation, the mean
    difference, its standard deviation, the relative difference (mean difference / reference mean), the paired t
    and its p, the 1 - 2 alpha interval's half-width, the margin (the seed standard deviation) and the verdict
    (VERDICTS; 'changed' when p < alpha, 'within the seed scatter' when the interval lies inside the margin).
    Fewer than 2 seeds: the means only, verdict None."""
    from scipy import stats
    d = np.asarray(differences, float)
    ref = np.asarray(reference, float)
    n = len(d)
    out = {'seeds': n, 'referenceMean': float(ref.mean()) if n else math.nan,
           'meanDifference': float(d.mean()) if n else math.nan}
    out['relativeDifference'] = out['meanDifference'] / out['referenceMean'] if out['referenceMean'] else math.nan
    if n < 2:
        return dict(out, verdict=None)
    sd = float(np.std(d, ddof=1))
    margin = float(np.std(ref, ddof=1))
    _, half = meanInterval(d, level=1 - 2 * alpha)
    if sd == 0:   # identical differences: a sure bias unless they are all zero
        t, p = (0.0, 1.0) if d[0] == 0 else (math.copysign(math.inf, d[0]), 0.0)
    else:
        t, p = stats.ttest_1samp(d, 0.0)
    inside = abs(out['meanDifference']) + half < margin
    verdict = VERDICTS[0] if p < alpha else VERDICTS[1] if inside else VERDICTS[2]
    return dict(out, differenceStd=sd, seedStd=margin, scatterRatio=sd / margin if margin else math.inf,
                t=float(t), p=float(p), alpha=alpha, interval=half, verdict=verdict)


def compare(frame, study, reference, quantities, at, alpha=0.05):
    """The runs of `study` against those of `reference` in `frame` (values()), seed by seed, at the cycles `at`:
    (pairs, verdicts). pairs: a row per seed, cycle and quantity with both values and their difference; verdicts:
    a list of dicts, one per cycle and quantity, test() and its cycle and quantity. ValueError if a study holds two
    realizations of one seed (the pair would be ambiguous) or the two share no seed."""
    runs = {}
    for name in (study, reference):
        g = frame[frame.study == name]
        if g.empty:
            raise ValueError('agreement: no run of %s; there are %s' % (name, ', '.join(frame.study.unique())))
        runs[name] = oneRunPerSeed(g, 'agreement: ' + name, run='runId').set_index(['seed', 'cycle'])
    mine, ref = runs[study], runs[reference]
    keys = [k for k in common(mine.index, ref.index) if k[1] in set(at)]
    if not keys:
        raise ValueError('agreement: %s and %s share no seed at the cycles %s' % (
            study, reference, ' '.join(map(str, at))))
    pairs, verdicts = [], []
    for q in quantities:
        for N in sorted({k[1] for k in keys}):
            seeds = [k for k in keys if k[1] == N]
            a, b = mine.loc[seeds, q].to_numpy(), ref.loc[seeds, q].to_numpy()
            pairs.append(pd.DataFrame({'quantity': q, 'cycle': N, 'seed': [k[0] for k in seeds],
                                       'runId': mine.loc[seeds, 'runId'].to_numpy(),
                                       'reference': ref.loc[seeds, 'runId'].to_numpy(),
                                       'value': a, 'referenceValue': b, 'difference': a - b}))
            verdicts.append(dict({'quantity': q, 'cycle': int(N)}, **test(a - b, b, alpha)))
    return pd.concat(pairs, ignore_index=True), verdicts
