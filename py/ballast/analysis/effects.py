"""Does the studied parameter change a result? (docs/studies.md, "Aggregating" and "Fig. 5 at 4 Hz"):
the Kruskal-Wallis test across the parameter's values with the difference the runs could have
detected (:func:`effectTest`), and the same question within realizations, a seed being one packing run
at every value (:func:`blockedTest`, :func:`withinSeeds`: Friedman's test, Page's trend test). scipy,
no YADE; the runs come from ballast.study.data.StudyData.
"""
import math

import numpy as np

from .pairs import common, keyed


def unitOf(data, quantity):
    """The unit of a result, as the experiment declares it ('-' if it does not)."""
    return dict(data.declaration.results).get(quantity, '-')


def meanInterval(values, level=0.95):
    """The mean of `values` and the half-width of its two-sided Student t interval at `level` (NaN below two
    values): for paired differences, the interval of their mean."""
    from scipy import stats
    v = np.asarray(values, float)
    n = len(v)
    if n < 2:
        return float(np.mean(v)) if n else math.nan, math.nan
    return float(np.mean(v)), float(stats.t.ppf(0.5 + level / 2, n - 1) * np.std(v, ddof=1) / math.sqrt(n))


def detectable(alpha, power, dof):
    """The difference of two means, in standard errors, that a two-sided t test at `alpha` with `dof`
    degrees of freedom (those of the standard deviation) finds with probability `power`: the
    noncentrality d of the noncentral t distribution with P(|T| > t_(1-alpha/2, dof)) = power
    (scipy.stats.nct; at 5 and 5 runs 3.20, where the normal approximation z_(1-alpha/2) + z_power
    gives 2.80)."""
    from scipy import optimize, stats
    tc = stats.t.ppf(1 - alpha / 2, dof)

    def shortfall(d):
        return stats.nct.sf(tc, dof, d) + stats.nct.cdf(-tc, dof, d) - power
    with np.errstate(all='ignore'):
        hi = stats.norm.ppf(1 - alpha / 2) + stats.norm.ppf(power)
        while shortfall(hi) < 0:
            hi *= 2
        return float(optimize.brentq(shortfall, 0.0, hi, xtol=1e-12))


def effectTest(data, alpha=0.05, power=0.8):
    """Does the studied parameter change the response (StudyData.response: the oedometer's delta at the
    peak)? The Kruskal-Wallis H test across its values (scipy.stats.kruskal; ties corrected) and the
    smallest difference of two means the runs could have detected: a two-sided test at `alpha` finds it
    with probability `power` given the pooled standard deviation s and the smallest group n,
    d s sqrt(2/n), d by the t distribution of the pooled degrees of freedom (:func:`detectable`). None with fewer than two values of two runs each."""
    from scipy import stats
    groups = [np.array([r.summary[data.response] for r in data.runs if r.value == v]) for v in data.values]
    groups = [g for g in groups if len(g) >= 2]
    if len(groups) < 2:
        return None
    try:
        H, p = stats.kruskal(*groups)
    except ValueError:  # every value the same: no evidence of any effect
        H, p = 0.0, 1.0
    dof = sum(len(g) - 1 for g in groups)
    pooled = float(np.sqrt(sum((len(g) - 1) * np.var(g, ddof=1) for g in groups) / dof))
    n = min(len(g) for g in groups)
    unit = unitOf(data, data.response)
    return {'test': 'Kruskal-Wallis', 'quantity': data.response, 'parameter': data.param, 'groups': len(groups),
            'runs': int(sum(len(g) for g in groups)), 'H': float(H), 'p': float(p), 'alpha': alpha, 'power': power,
            'pooledStd [%s]' % unit: pooled, 'smallestGroup': n,
            'detectableDifference [%s]' % unit: float(detectable(alpha, power, dof) * pooled * np.sqrt(2 / n))}


def blockedTest(data, quantity=None, alpha=0.05, power=0.8):
    """The effect test within realizations: a seed is one packing run at every value of the parameter,
    so the seeds are blocks. For `quantity` (default the response; in its declared unit), over the
    values where a run has it and the seeds that have it at all of them: withinSeeds. None with fewer
    than 3 values or 2 complete seeds."""
    quantity = quantity or data.response
    got = keyed((((r.seed, r.value), r.summary[quantity]) for r in data.runs if r.summary.get(quantity) is not None),
                '%s at one value' % data.dir)
    values = [v for v in data.values if any(w == v for _, w in got)]
    seeds = common(*[[s for s, w in got if w == v] for v in values])   # a block: a seed at every value
    if len(values) < 3 or len(seeds) < 2:
        return None
    out = withinSeeds(np.array([[got[s, v] for v in values] for s in seeds], dtype=float), data.numeric,
                      unitOf(data, quantity), alpha, power)
    return dict({'test': 'Friedman', 'quantity': quantity, 'blocks': 'seed', 'valuesTested': values}, **out)


def withinSeeds(y, numeric, unit, alpha=0.05, power=0.8):
    """Friedman's chi-square test across the columns of y (a row per seed, a column per value of the
    parameter; scipy.stats.friedmanchisquare) and the difference of two means it could have detected:
    as effectTest's, with the residual standard deviation of the two-way layout (seed + value) in place
    of the pooled one, s_r = sqrt(sum r_ij^2 / ((b - 1)(k - 1))), r_ij = y_ij - row mean - column mean
    + grand mean, b seeds and (b - 1)(k - 1) degrees of freedom. For a numeric parameter (columns in its order) also Page's test of a
    monotonic trend along it (scipy.stats.page_trend_test, for a rise and for a fall; pTrend is twice the
    smaller p, the two-sided p)."""
    from scipy import stats
    b, k = y.shape
    if np.all(y == y[:, :1]):  # no seed tells its values apart: no evidence of any effect (scipy divides by 0)
        chi2, p = 0.0, 1.0
    else:
        chi2, p = stats.friedmanchisquare(*y.T)
    res = y - y.mean(axis=1, keepdims=True) - y.mean(axis=0, keepdims=True) + y.mean()
    sr = float(np.sqrt((res**2).sum() / ((b - 1) * (k - 1))))
    out = {'seeds': b, 'values': k, 'chi2': float(chi2), 'p': float(p), 'residualStd [%s]' % unit: sr,
           'detectableDifference [%s]' % unit: float(detectable(alpha, power, (b - 1) * (k - 1)) * sr * np.sqrt(2 / b))}
    if numeric:
        rise = stats.page_trend_test(y)
        fall = stats.page_trend_test(y, predicted_ranks=list(range(k, 0, -1)))
        out.update(trend='rise' if rise.pvalue <= fall.pvalue else 'fall', pageL=float(max(rise.statistic, fall.statistic)),
                   pTrend=float(min(1.0, 2 * min(rise.pvalue, fall.pvalue))))
    return out
