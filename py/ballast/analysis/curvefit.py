"""How far a study's runs lie from a measured curve: each run's cycles.csv column (axialStrain, volumetricStrain, or
any other) against a measured curve of the same quantity (a CSV `N,<name>`, as ../shared/data's files and the
triaxial test's `reference` read them), at chosen cycles. What a calibration scores its candidates with
(docs/triaxial.md, "Calibration").

A digitised curve carries noise of a few tenths of a percent of strain, its points not monotone where they crowd
(../shared/data/README.md): it is read as a curve, a running median of three points in N order, then interpolated
linearly in log N. Per run and cycle N: simulated, measured, their difference; per run the root mean square of the
differences over the cycles and quantities (in strain, a fraction) and per quantity. NumPy, pandas; no YADE."""
import math

import numpy as np
import pandas as pd

from ..experiments.triaxial.strains import atCycles, readReference
from ..settlementlaws import cyclesChanged as changed, settlementJumped
from .settlement import realizationRuns


def smoothed(N, strain):
    """A running median of three points (the ends kept): the curve, not single digitised points."""
    s = np.asarray(strain, float)
    if len(s) < 3:
        return s.copy()
    out = s.copy()
    out[1:-1] = np.median(np.stack([s[:-2], s[1:-1], s[2:]]), axis=0)
    return out


def total(cycles, q):
    """A run's quantity q per row of its cycles.csv: with cycle jumping, the simulated value plus its extrapolation
    over the jumped cycles (<q>Jumped, as the triaxial test writes for its strains), what a measured curve at that
    cycle count compares with."""
    v = cycles[q].to_numpy(float)
    if q + 'Jumped' in cycles:
        return v + cycles[q + 'Jumped'].to_numpy(float)
    if 'jumped' in cycles and cycles.jumped.any():   # records of before those columns: the same law, here
        return v + settlementJumped(cycles.cycle, v, changed(cycles))
    return v


def measured(curves, at):
    """{column: measured values at the cycles `at`} of `curves` {column of cycles.csv: measured curve's path}
    (readReference refuses a malformed file naming its line)."""
    out = {}
    for column, path in curves.items():
        _, N, strain = readReference(path)
        out[column] = atCycles(N, smoothed(N, strain), at)
    return out


def table(paths, curves, at, params=()):
    """A DataFrame, a row per run of the studies at `paths` (their records), quantity of `curves` and cycle of `at`
    the run reached: study, runId, seed, the run's `params`, quantity, cycle, simulated, measured, difference
    (simulated - measured). ValueError naming a quantity a run did not write or when no run reached a cycle."""
    reference = measured(curves, at)
    rows = []
    for label, run, c in realizationRuns(paths):
        for q in curves:
            if q not in c:
                raise ValueError('curvefit: %s wrote no %s in cycles.csv; it has %s' % (
                    run.runId, q, ', '.join(c.columns)))
            byCycle = dict(zip(c.cycle.astype(int), total(c, q)))
            for k, n in enumerate(at):
                if n in byCycle and math.isfinite(reference[q][k]):
                    rows.append(dict({'study': label, 'runId': run.runId, 'seed': run.params.get('seed')},
                                     **{p: run.params.get(p) for p in params},
                                     quantity=q, cycle=int(n), simulated=byCycle[n], measured=float(reference[q][k]),
                                     difference=byCycle[n] - float(reference[q][k])))
    if not rows:
        raise ValueError('curvefit: no run of %s reached the cycles %s within the measured curves' % (
            ', '.join(paths), ' '.join(map(str, at))))
    return pd.DataFrame(rows)


def scores(frame, params=()):
    """Per run: the cycles compared, the root mean square of the differences over all of them (rms) and per
    quantity (rms_<quantity>), and the mean difference per quantity (bias_<quantity>: its sign says above or below
    the measured curve); sorted by rms, the closest first."""
    out = []
    for runId, g in frame.groupby('runId', sort=False):
        row = {'runId': runId, 'seed': g.seed.iloc[0], **{p: g[p].iloc[0] for p in params},
               'cycles': ' '.join(str(n) for n in sorted(set(g.cycle))),
               'rms': float(np.sqrt(np.mean(g.difference ** 2)))}
        for q, h in g.groupby('quantity', sort=False):
            row['rms_' + q] = float(np.sqrt(np.mean(h.difference ** 2)))
            row['bias_' + q] = float(h.difference.mean())
        out.append(row)
    return pd.DataFrame(out).sort_values('rms', kind='stable').reset_index(drop=True)


def figure(paths, curves, path, title=''):
    """A PNG: per quantity of `curves`, every run's curve against log N (a line each, labelled by run) and the
    measured curve's points and its smoothed line over them."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    from ..runfiles import plainLogTicks
    qs = list(curves)
    fig, axes = plt.subplots(1, len(qs), figsize=(5.2 * len(qs), 4.2), squeeze=False)
    runs = list(realizationRuns(paths))
    for ax, q in zip(axes[0], qs):
        _, N, strain = readReference(curves[q])
        ax.semilogx(N, 100 * strain, 'ko', ms=3, label='measured')
        ax.semilogx(N, 100 * smoothed(N, strain), 'k-', lw=1, label='measured, running median of 3')
        for _, run, c in runs:
            if q in c:
                ax.semilogx(c.cycle, 100 * total(c, q), '-', lw=1.2, label=run.runId)
        ax.set_xlabel('cycles N')
        ax.set_ylabel('%s [%%]' % q)
        plainLogTicks(ax)
        ax.grid(True, which='both', alpha=0.3)
    axes[0][0].legend(fontsize=7, loc='upper left')
    if title:
        fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path
