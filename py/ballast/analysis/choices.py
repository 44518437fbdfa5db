"""What the model options of issue 13 do at the paper's size (docs/strength.md, "Crushing criterion"
and "What each choice does at the paper's size"): the strength that gives each crushing criterion the
paper's onset of crushing, and the comparison of the choices (criterion, Weibull modulus, what a
replacement keeps) against the paper's model, seed by seed. The paper's model is the oedometer's
defaults (its declaration). Reads study directories or their records (ballast.study.data); NumPy, no
YADE.

Onset calibration. The three criteria measure different stresses (for one grain squeezed along a
diameter F/d^2 is pi/6 of the von Mises stress; in a packing, where von Mises discounts the
confinement, the ratios differ), so ft0 calibrated for one is not calibrated for another. The
sample is loaded without crushing (ft0 far above any stress), the per-check log giving the largest
stress x r over the grains for each criterion (checks.csv: maxStressRatio = stress / f_t). The first
grain of the paper's model crushes when the running maximum of sigma_e r reaches the calibrated
ft0; the same applied force (the same check: the runs are identical without crushing) gives each
other criterion's running maximum, which is the ft0 that starts its crushing at that force.
"""
import numpy as np

from ..experiments import declaration
from ..runfiles import column
from ..study.data import StudyRuns
from .figures import writeFigure
from .pairs import keyed

PARAMS = declaration('oedometer').params
# the paper's criterion and its calibrated ft0 [Pa m] (docs/oedometer.md, "Choice of the defaults")
REFERENCE = (PARAMS['criterion'].default, PARAMS['ft0'].default)


def runs(study):
    """The finished runs (ballast.study.data.Run) of a study directory or record folder, in table order."""
    return StudyRuns(study, 'oedometer').runs


def strengthCurve(run, ft0):
    """(t [s], running maximum of stress x r [Pa m], applied force [N]) at the checks of a run loaded
    without crushing with reference strength ft0."""
    t, fd = column(run.checks, 't'), run.fd
    force = column(fd, 'Fapplied' if 'Fapplied' in fd else 'F')
    return t, np.maximum.accumulate(column(run.checks, 'maxStressRatio')) * ft0, np.interp(t, column(fd, 't'), force)


def onsetStrengths(study, reference=REFERENCE):
    """Per seed and criterion of an onset study (rows seed x criterion, no crushing): {'seeds': {seed:
    {'onsetForce': N, 'onsetTime': s, criterion: ft0 [Pa m]}}, 'mean': {criterion: ft0}, 'std': {...}}.
    A seed whose reference never reaches its ft0 is reported with onsetForce None and left out."""
    refName, refFt0 = reference
    finished = runs(study)
    for run in finished:
        if run.summary.get('nCrushed', 0):
            raise ValueError('%s: %d grains crushed; the onset study loads without crushing (raise ft0)' % (
                run.dir, run.summary['nCrushed']))
    # each criterion's run against the reference's of its seed
    curves = keyed((((r.params['seed'], r.params['criterion']), strengthCurve(r, r.params['ft0'])) for r in finished),
                   '%s at one criterion' % study)
    bySeed = {}
    for (seed, criterion), curve in curves.items():
        bySeed.setdefault(seed, {})[criterion] = curve
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


# the options of issue 13, each against the paper's value (the default): (parameter, the paper's value, group title)
OPTIONS = tuple((k, PARAMS[k].default, title) for k, title in (
    ('keep', 'what a replacement keeps'), ('weibullModulus', 'strength scatter (Weibull modulus)'),
    ('criterion', 'crushing criterion')))


def variant(params):
    """(the option a run changes or None for the paper's model, its label)."""
    changed = [(k, params.get(k, paper)) for k, paper, _ in OPTIONS if params.get(k, paper) != paper]
    if not changed:
        return None, "paper's model"
    if len(changed) > 1:
        raise ValueError('a comparison run changes one option of the paper at a time, not %s' % changed)
    k, v = changed[0]
    if k == 'weibullModulus':
        return k, 'Weibull k = %g' % v
    if k == 'criterion':
        return k, '%s (ft0 = %.3g Pa m)' % (v, params['ft0'])
    return k, 'keep = %s' % v


COMPARISON_COLUMNS = ('option', 'variant', 'seed', 'deltaAtAppliedPeak_mm', 'deltaMax_mm', 'nCrushed', 'Bg', 'massLost_kg',
                      'cpuSeconds')


def comparison(study):
    """One dict per run (COMPARISON_COLUMNS), the paper's runs first, then by option, variant and seed."""
    rows = []
    for run in runs(study):
        s = run.summary
        option, name = variant(run.params)
        rows.append({'option': option or 'paper', 'variant': name, 'seed': run.params['seed'],
                     'deltaAtAppliedPeak_mm': 1e3 * s['deltaAtAppliedPeak'], 'deltaMax_mm': 1e3 * s['deltaMax'],
                     'nCrushed': s['nCrushed'], 'Bg': s.get('Bg'), 'massLost_kg': s.get('massLost'),
                     'cpuSeconds': s.get('cpuSeconds'), 'run': run})
    order = ['paper'] + [k for k, _, _ in OPTIONS]
    return sorted(rows, key=lambda r: (order.index(r['option']), r['variant'], r['seed']))


def figure(study, out):
    """choices.png: per option a row of two panels: the F-delta curves (applied force) of the paper's
    runs and of the option's variants, a colour per variant and a line style per seed; and delta at
    the peak of the applied force per variant, a point per seed and the mean as a bar."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    rows = comparison(study)
    seeds = sorted(set(r['seed'] for r in rows))
    styles = dict(zip(seeds, ['-', '--', ':', '-.'] * 5))
    fig, axes = plt.subplots(len(OPTIONS), 2, figsize=(11, 3.6 * len(OPTIONS)), gridspec_kw={'width_ratios': [1.6, 1]})
    for (key, _, title), (a1, a2) in zip(OPTIONS, axes):
        mine = [r for r in rows if r['option'] in ('paper', key)]
        names = list(dict.fromkeys(r['variant'] for r in mine))
        for r in mine:
            fd = r['run'].fd
            a1.plot(1e3 * column(fd, 'delta'), 1e-3 * column(fd, 'Fapplied'), color='C%d' % names.index(r['variant']),
                    ls=styles[r['seed']], lw=1)
        for i, n in enumerate(names):
            d = [r['deltaAtAppliedPeak_mm'] for r in mine if r['variant'] == n]
            a2.bar(i, np.mean(d), color='C%d' % i, alpha=0.35)
            a2.plot([i] * len(d), d, 'o', color='C%d' % i)
            a1.plot([], [], color='C%d' % i, label=n)
        for s in seeds:
            a1.plot([], [], color='k', ls=styles[s], label='seed %d' % s)
        a1.set_title(title, fontsize=10)
        a1.set_xlabel(r'plate displacement $\delta$ [mm]')
        a1.set_ylabel('applied force F [kN]')
        a1.legend(fontsize=7, loc='lower right')
        a2.set_xticks(range(len(names)))
        a2.set_xticklabels(names, rotation=15, fontsize=7)
        a2.set_ylabel(r'$\delta$ at the peak of F [mm]')
        for a in (a1, a2):
            a.grid(alpha=0.3)
    fig.suptitle('issue 13 options at the paper\'s size (300 x 150 mm, 1500 kN, 8 Hz): %d runs, seeds %s' % (
        len(rows), ', '.join(map(str, seeds))), fontsize=10)
    return writeFigure(fig, out, dpi=110)
