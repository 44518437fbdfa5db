"""What the model options of issue 13 do at the paper's size (docs/strength.md): the strength that
gives each crushing criterion the paper's onset of crushing, and the comparison of the choices
(criterion, Weibull modulus, what a replacement keeps) against the paper's model, seed by seed.
Reads study directories or their records (ballast.study.records); NumPy, no YADE.

Onset calibration. The three criteria measure different stresses (for one grain squeezed along a
diameter F/d^2 is pi/6 of the von Mises stress; in a packing, where von Mises discounts the
confinement, the ratios differ), so ft0 calibrated for one is not calibrated for another. The
sample is loaded without crushing (ft0 far above any stress), the per-check log giving the largest
stress x r over the grains for each criterion (checks.csv: maxStressRatio = stress / f_t). The first
grain of the paper's model crushes when the running maximum of sigma_e r reaches the calibrated
ft0; the same applied force (the same check: the runs are identical without crushing) gives each
other criterion's running maximum, which is the ft0 that starts its crushing at that force.
"""
import json
import os

import numpy as np

from .files import readSummary

REFERENCE = ('vonMises', 3.1e6)   # the paper's criterion and its calibrated ft0 [Pa m] (docs/oedometer.md)


def readColumns(path):
    """A CSV file by column name (NumPy)."""
    return np.atleast_1d(np.genfromtxt(path, delimiter=',', names=True))


def runs(study):
    """{run id: (summary, run folder)} of the finished runs of a study directory or record folder."""
    with open(os.path.join(study, 'study.json')) as fh:
        info = json.load(fh)
    out = {}
    for r in info['rows']:
        d = os.path.join(study, 'runs', r['runId'])
        s, _ = readSummary(d)
        if s is not None:
            out[r['runId']] = (s, d)
    return out


def strengthCurve(runDir, ft0):
    """(t [s], running maximum of stress x r [Pa m], applied force [N]) at the checks of a run loaded
    without crushing with reference strength ft0."""
    c = readColumns(os.path.join(runDir, 'checks.csv'))
    fd = readColumns(os.path.join(runDir, 'fd.csv'))
    force = fd['Fapplied'] if 'Fapplied' in fd.dtype.names else fd['F']
    return c['t'], np.maximum.accumulate(c['maxStressRatio']) * ft0, np.interp(c['t'], fd['t'], force)


def onsetStrengths(study, reference=REFERENCE):
    """Per seed and criterion of an onset study (rows seed x criterion, no crushing): {'seeds': {seed:
    {'onsetForce': N, 'onsetTime': s, criterion: ft0 [Pa m]}}, 'mean': {criterion: ft0}, 'std': {...}}.
    A seed whose reference never reaches its ft0 is reported with onsetForce None and left out."""
    refName, refFt0 = reference
    bySeed = {}
    for s, d in runs(study).values():
        p = s['params']
        if s.get('nCrushed', 0):
            raise ValueError('%s: %d grains crushed; the onset study loads without crushing (raise ft0)' % (d, s['nCrushed']))
        bySeed.setdefault(p['seed'], {})[p['criterion']] = strengthCurve(d, p['ft0'])
    seeds = {}
    for seed, curves in sorted(bySeed.items()):
        if refName not in curves:
            continue
        t, ref, force = curves[refName]
        reached = np.flatnonzero(ref >= refFt0)
        if not len(reached):
            seeds[seed] = {'onsetForce': None}
            continue
        i = reached[0]
        row = {'onsetTime': float(t[i]), 'onsetForce': float(force[i])}
        for name, (tc, runMax, _) in curves.items():
            row[name] = float(np.interp(t[i], tc, runMax))
        seeds[seed] = row
    names = sorted(set(k for r in seeds.values() for k in r if k not in ('onsetForce', 'onsetTime')))
    used = [r for r in seeds.values() if r['onsetForce'] is not None]
    return {'reference': {'criterion': refName, 'ft0': refFt0}, 'seeds': seeds,
            'mean': {n: float(np.mean([r[n] for r in used])) for n in names},
            'std': {n: float(np.std([r[n] for r in used], ddof=1)) if len(used) > 1 else float('nan') for n in names}}
