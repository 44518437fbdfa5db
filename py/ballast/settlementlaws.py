"""The laws permanent settlement follows against the number of load cycles N in box tests, fitted by least
squares: logarithmic s = a + b ln N and power s = c N^d (both pass through N = 1 with a's and c's share). Used
by the analyses of cyclic studies (ballast.analysis.settlement) and by cycle jumping, which extrapolates the
settlement of the cycles it does not simulate (docs/cycles.md: settlementLaw, settlementJumped), and the rule of which cycles changed the bed (bedChanged). NumPy,
no YADE."""
import math

import numpy as np


def fitLaws(N, s):
    """Least-squares fits of s = a + b ln N and of s = c N^d (a straight line in log-log, s > 0) to the cycles
    N (>= 1) and settlements s [m]: {'log': {a, b, r2}, 'power': {c, d, r2}} (R^2 of each on s itself)."""
    N, s = np.asarray(N, float), np.asarray(s, float)
    if len(N) < 3 or np.any(N < 1):
        raise ValueError('fitLaws: at least 3 cycles N >= 1 are needed, got %d (smallest %r)' % (len(N), N.min()))
    x = np.log(N)
    b, a = np.polyfit(x, s, 1)
    out = {'log': {'a': float(a), 'b': float(b), 'r2': r2(s, a + b * x)}}
    if np.all(s > 0):
        d, lnc = np.polyfit(x, np.log(s), 1)
        out['power'] = {'c': float(math.exp(lnc)), 'd': float(d), 'r2': r2(s, math.exp(lnc) * N ** d)}
    return out


def r2(y, fitted):
    ss = float(np.sum((y - np.mean(y)) ** 2))
    return 1.0 - float(np.sum((y - fitted) ** 2)) / ss if ss > 0 else 1.0


def bedChanged(crushes, abrasions=0, totals=False):
    """Per cycle whether it changed the bed: a grain crushed or abraded in it (the rule cycle jumping and the analyses
    share: such a cycle is simulated, never jumped, and its settling step is no part of the law, withoutSteps).
    crushes, abrasions: the counts in each cycle, or with totals=True the running totals at each cycle's end (a cycle
    changed the bed when they grew since the one before; the first from 0; sequences only). Scalars or sequences; a
    bool array."""
    n = np.asarray(crushes) + np.asarray(abrasions)
    if totals:
        n = np.diff(n, prepend=0)
    return n > 0


def cyclesChanged(frame):
    """Whether a grain crushed or abraded in each cycle of a cycles.csv table (its crushes and abrasions columns):
    bedChanged, for the experiments and the analyses alike (no YADE needed to read a record)."""
    return bedChanged(frame.crushes.to_numpy(), frame.abrasions.to_numpy())


def recentHalf(n):
    """The first row (1-based) of the recent half of n simulated cycles, ceil(n / 2): the law the bed follows now
    (a bed that settled fast and then stopped has b = 0 there, not the b of its first cycles)."""
    return (n + 1) // 2


def withoutSteps(settlements, changed=None):
    """The settlements [m] of the simulated cycles less the steps of those in which the bed changed (a grain crushed
    or abraded: changed, one flag a row): s_n - sum over changed rows k = 2..n of (s_k - s_{k-1}). A jump holds no
    crush (the cycle a grain fails in is simulated), so the law it extrapolates is that of the cycles without one;
    an avalanche's settling is not carried over thousands of jumped cycles. Row 1 (the seating) is kept. Without
    changes the settlements themselves."""
    s = np.asarray(settlements, float)
    if changed is None:
        return s
    c = np.asarray(changed, bool)
    if c.shape != s.shape:
        raise ValueError('withoutSteps: %d flags for %d settlements' % (len(c), len(s)))
    step = np.zeros(len(s))
    step[1:] = np.where(c[1:], np.diff(s), 0.0)
    return s - np.cumsum(step)


def settlementLaw(settlements, changed=None):
    """The law s = a + b ln n fitted to the recent half of the simulated cycles' settlements [m] (the n-th simulated
    cycle's at n, rows recentHalf(n)..n), the steps of the cycles that changed the bed taken out (withoutSteps):
    {a, b, r2}, None below 3 rows."""
    n = len(settlements)
    m = recentHalf(n)
    if n - m + 1 < 3:
        return None
    return fitLaws(np.arange(m, n + 1), withoutSteps(settlements, changed)[m - 1:])['log']


def settlementJumped(cycles, settlements, changed=None):
    """The settlement [m] the jumped cycles add at each simulated cycle: the n-th simulated cycle is cycle N of the
    count (cycles), the bed saw n, so b_n ln(N / n) with b_n of settlementLaw over the first n simulated settlements
    (what was known then: a later crush does not move an earlier row), the steps of the rows flagged in changed
    taken out; 0 without a law."""
    s = withoutSteps(settlements, changed)
    n = np.arange(1, len(s) + 1)
    x = np.log(n.astype(float))
    # least squares of s = a + b x over rows m..n, m = recentHalf(n), from running sums
    zero = np.zeros(1)
    Sx, Sy, Sxx, Sxy = (np.concatenate([zero, np.cumsum(v)]) for v in (x, s, x * x, x * s))
    m = recentHalf(n)
    k = (n - m + 1).astype(float)
    sx, sy, sxx, sxy = (S[n] - S[m - 1] for S in (Sx, Sy, Sxx, Sxy))
    den = sxx - sx * sx / k
    with np.errstate(divide='ignore', invalid='ignore'):
        b = np.where((k >= 3) & (den > 0), (sxy - sx * sy / k) / den, 0.0)
    return b * np.log(np.asarray(cycles, float) / n)
