"""Single-particle strengths as statistics (docs/calibration.md), with scipy.stats; no YADE.

* survival probability of each grain of a class by its mean rank, P_s = 1 - i / (N + 1) for the i-th
  weakest of N (as Lim, McDowell & Collop 2004 plot ballast);
* the two-parameter Weibull distribution P_s = exp(-(sigma / sigma_0)^k) fitted by maximum likelihood
  (scipy.stats.weibull_min, location 0), with asymptotic 95 % intervals from the Fisher information:
  var(k) = 0.608 k^2 / N, var(ln sigma_0) = 1.109 / (k^2 N) (Thoman, Bain & Antle 1969);
* the size law sigma_0(r) = s0 r^-b and the modulus fitted jointly to every grain by maximum likelihood
  (each grain's stress Weibull with its own scale s0 r_i^-b), intervals from the inverse Hessian. With
  the criterion's stress at failure this recovers the model's ft0 (= s0), m (= b) and weibullModulus (= k):
  the calibration.
"""
import math

import numpy as np
from scipy import optimize, stats

Z95 = stats.norm.ppf(0.975)
# A fitted Weibull modulus above this is no scatter: the crushing engine's largest (params.CRUSH weibullModulus), where
# a fit of deterministic strengths lands on numerical noise (k of 2 000-13 000 with intervals of no width)
NO_SCATTER = 50.0
# asymptotic variances of the Weibull maximum-likelihood estimates, per grain (Fisher information)
VAR_K, VAR_LOG_SCALE = 6 / math.pi ** 2, 1 + 6 * (1 - np.euler_gamma) ** 2 / math.pi ** 2


def survival(sigma):
    """(sigma sorted, P_s by mean rank 1 - i / (N + 1))."""
    s = np.sort(np.asarray(sigma, dtype=float))
    return s, 1 - np.arange(1, len(s) + 1) / (len(s) + 1)


def weibullFit(sigma):
    """Maximum-likelihood Weibull fit of the stresses of one class: {n, modulus, modulusLow, modulusHigh,
    scale, scaleLow, scaleHigh} (95 % intervals), or None below 3 values."""
    s = np.asarray(sigma, dtype=float)
    if len(s) < 3:
        return None
    if np.ptp(s) <= 1e-12 * np.max(s):  # no scatter: the modulus is infinite, the scale the common value
        return {'n': len(s), 'modulus': math.inf, 'modulusLow': math.inf, 'modulusHigh': math.inf,
                'scale': float(s[0]), 'scaleLow': float(s[0]), 'scaleHigh': float(s[0])}
    k, _, scale = stats.weibull_min.fit(s, floc=0)
    if k > NO_SCATTER:   # the scatter of rounding, not of strength
        return {'n': len(s), 'modulus': math.inf, 'modulusLow': math.inf, 'modulusHigh': math.inf,
                'scale': float(scale), 'scaleLow': float(np.min(s)), 'scaleHigh': float(np.max(s))}
    dk = Z95 * k * math.sqrt(VAR_K / len(s))
    dl = Z95 * math.sqrt(VAR_LOG_SCALE / len(s)) / k
    return {'n': len(s), 'modulus': float(k), 'modulusLow': float(k - dk), 'modulusHigh': float(k + dk),
            'scale': float(scale), 'scaleLow': float(scale * math.exp(-dl)), 'scaleHigh': float(scale * math.exp(dl))}


def _negLogLikelihood(theta, logR, logS):
    """-ln L of sigma_i Weibull with scale lambda_i = s0 r_i^-b, modulus k: with z = ln(sigma_i / lambda_i) the
    log density is ln k + k z - ln sigma_i - exp(k z)."""
    logS0, b, logK = theta
    k = math.exp(logK)
    z = logS - (logS0 - b * logR)
    with np.errstate(over='ignore'):  # far from the optimum the likelihood is 0: -ln L = inf
        return -float(np.sum(logK + k * z - logS - np.exp(k * z)))


def _hessian(f, x, h=1e-4):
    """Central differences of f at x (the parameters are logs and an exponent: one step size serves)."""
    n = len(x)
    H = np.zeros((n, n))
    for i in range(n):
        for j in range(n):
            e_i, e_j = np.eye(n)[i] * h, np.eye(n)[j] * h
            H[i, j] = (f(x + e_i + e_j) - f(x + e_i - e_j) - f(x - e_i + e_j) + f(x - e_i - e_j)) / (4 * h * h)
    return H


def sizeLawFit(r, sigma):
    """sigma_i = s0 r_i^-b w_i with w Weibull of modulus k and scale 1, fitted to every grain by maximum
    likelihood: {s0, s0Low, s0High, b, bLow, bHigh, k, kLow, kHigh, n} (95 % intervals; r in m, sigma in
    Pa, s0 in Pa m^b). Without scatter (all on one power law) the fit is the closed form: b from the
    line through ln sigma against ln r, s0 from it, k infinite. ValueError below 3 grains or with one size."""
    r, s = np.asarray(r, dtype=float), np.asarray(sigma, dtype=float)
    if len(r) < 3 or np.ptp(np.log(r)) <= 1e-9:
        raise ValueError('a size law needs at least 3 grains of at least 2 sizes, got %d grains of %d sizes'
                         % (len(r), len(np.unique(r))))
    logR, logS = np.log(r), np.log(s)
    line = stats.linregress(logR, logS)
    b0 = -line.slope
    resid = logS - (line.intercept + line.slope * logR)
    if np.ptp(resid) <= 1e-9:
        s0 = float(math.exp(line.intercept))
        return {'n': len(r), 's0': s0, 's0Low': s0, 's0High': s0, 'b': float(b0), 'bLow': float(b0), 'bHigh': float(b0),
                'k': math.inf, 'kLow': math.inf, 'kHigh': math.inf}
    w = np.exp(resid)
    k0, _, scale0 = stats.weibull_min.fit(w, floc=0)
    x0 = np.array([line.intercept + math.log(scale0), b0, math.log(k0)])

    def nll(theta):
        return _negLogLikelihood(theta, logR, logS)
    with np.errstate(over='ignore', invalid='ignore'):  # trial points far from the optimum have -ln L = inf
        res = optimize.minimize(nll, x0, method='Nelder-Mead', options={'xatol': 1e-10, 'fatol': 1e-12, 'maxiter': 20000})
        res = optimize.minimize(nll, res.x, method='BFGS')
        cov = np.linalg.inv(_hessian(nll, res.x))
    se = np.sqrt(np.maximum(np.diag(cov), 0))
    logS0, b, logK = res.x
    if math.exp(logK) > NO_SCATTER:   # on one power law up to rounding: no scatter, as the closed form above
        return {'n': len(r), 's0': math.exp(logS0), 's0Low': math.exp(logS0 - Z95 * se[0]),
                's0High': math.exp(logS0 + Z95 * se[0]), 'b': float(b), 'bLow': float(b - Z95 * se[1]),
                'bHigh': float(b + Z95 * se[1]), 'k': math.inf, 'kLow': math.inf, 'kHigh': math.inf}
    return {'n': len(r), 's0': math.exp(logS0), 's0Low': math.exp(logS0 - Z95 * se[0]),
            's0High': math.exp(logS0 + Z95 * se[0]), 'b': float(b), 'bLow': float(b - Z95 * se[1]),
            'bHigh': float(b + Z95 * se[1]), 'k': math.exp(logK), 'kLow': math.exp(logK - Z95 * se[2]),
            'kHigh': math.exp(logK + Z95 * se[2])}


def classes(d, lo, hi, count):
    """The class index [0, count) of each diameter d in [lo, hi], classes of equal width."""
    edges = np.linspace(lo, hi, count + 1)
    return np.clip(np.searchsorted(edges, np.asarray(d, dtype=float), side='right') - 1, 0, count - 1), edges
