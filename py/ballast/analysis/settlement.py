"""The sleeper's settlement against the number of load cycles over the runs of cyclic studies (the box
test, docs/box.md "The study"; any experiment whose runs write cycles.csv with cycle and settlement):
every run's curve, their mean per cycle, and the two laws box tests are read with fitted to each,
logarithmic s = a + b ln N and power s = c N^d, with their R^2 (the first cycle's settlement is a's and
c's share: both laws pass through N = 1). Reads the studies with ballast.study.data. NumPy, no YADE."""
import math
import os

import numpy as np
import pandas as pd

from ..settlementlaws import bedChanged, fitLaws, settlementJumped
from ..study.data import StudyRuns
from .effects import meanInterval
from .pairs import common, oneRunPerSeed


def continued(runs):
    """The runIds of the runs another of `runs` continued from (its continueFrom is a state in their folder): the
    slices of a realization run in slices, whose last slice's cycles.csv holds every cycle of the earlier ones."""
    return {os.path.basename(os.path.dirname(os.path.normpath(r.params['continueFrom'])))
            for r in runs if r.params.get('continueFrom')}


def tippingOnset(cycle, settlement, rise):
    """The first cycle whose settlement [m] at the seating load stands more than `rise` [m] above the deepest one
    before it, None if none: under a load that only presses, the sleeper's centre rises back only when the
    sleeper pivots on its bed (it tips or rocks) instead of settling."""
    s = np.asarray(settlement, float)
    up = np.maximum.accumulate(s) - s > rise
    return int(np.asarray(cycle)[up.argmax()]) if up.any() else None


def variantLabel(path, params, by):
    """The name of a study's group of runs that share the values of the parameters `by`: 'path[name=value ...]'
    in the table's spelling (fatigue=1, keep=none, ft0=363000), or the path alone without `by`."""
    def text(v):
        return str(int(v)) if isinstance(v, bool) else '%g' % v if isinstance(v, float) else str(v)
    missing = [k for k in by if k not in params]
    if missing:
        raise ValueError('curves: by = %s, but the runs of %s have no parameter %s' % (
            ' '.join(by), path, ', '.join(missing)))
    return '%s[%s]' % (path, ' '.join('%s=%s' % (k, text(params[k])) for k in by)) if by else path


def curves(paths, apart=(), tipping=None, by=(), join=False):
    """The settlement curves of the finished runs of the studies (or records) at `paths`, a realization run in
    slices once, as its last slice: a DataFrame with study, runId, seed, cycle, settlement [m], resilient [m]
    (NaN where a run has none), apart (its seed or runId is one of `apart`: a realization read apart by choice) and
    tippedAt (with `tipping`, a rise [m]: the cycle from which the sleeper rose back more than that,
    tippingOnset; NaN where it did not). A realization apart or tipped is left out of the mean (readApart).
    With `by` (parameter names) the runs of a study that differ in those (its variants, fatigue on and off for
    example) are studies of their own, named by variantLabel: each has its mean, and they pair seed by seed. With
    `join` a realization run in slices belongs to the study it began in (realizationRuns)."""
    if tipping is not None and not (isinstance(tipping, (int, float)) and math.isfinite(tipping) and tipping > 0):
        raise ValueError('curves: tipping = %r m; allowed: a rise above 0 m, or None (no detection)' % (tipping,))
    rows = []
    for label, run, c in realizationRuns(paths, by, join):
        seed = run.params.get('seed')
        s = total(c)
        onset = tippingOnset(c['cycle'], s, tipping) if tipping is not None else None
        rows.append(pd.DataFrame({'study': label, 'runId': run.runId, 'seed': seed,
                                  'cycle': c['cycle'].astype(int), 'settlement': s,
                                  'resilient': c['resilient'] if 'resilient' in c else math.nan,
                                  'apart': seed in apart or run.runId in apart,
                                  'tippedAt': math.nan if onset is None else float(onset)}))
    if not rows:
        raise ValueError('curves: no run with a cycles.csv (cycle, settlement) in %s' % ', '.join(paths))
    return pd.concat(rows, ignore_index=True)


def slicedFrom(run):
    """(study folder name, runId) of the run whose recorded state `run` goes on from (its continueFrom is
    .../<study>/runs/<runId>/<state file>), None where it began itself or goes on from a state kept elsewhere."""
    parts = os.path.normpath(run.params.get('continueFrom') or '.').split(os.sep)
    return (parts[-4], parts[-2]) if len(parts) >= 4 and parts[-3] == 'runs' else None


def continuedElsewhere(study, others):
    """The runIds of `study`'s runs a run of another study (`others`) continued from: a state in
    <that study's folder name>/runs/<runId>/ (a study whose slices go on in a study of their own)."""
    name = os.path.basename(os.path.normpath(study.dir))
    ids = set()
    for other in others:
        for r in other.runs:
            before = slicedFrom(r)
            if before and before[0] == name:
                ids.add(before[1])
    return ids


def began(studies):
    """origin(path, run): the path of the study of `studies` ((path, StudyRuns) pairs) whose run the realization of
    `run` began with, following its continueFrom through the slices before it (in its study or another of them);
    its own path where it began itself or goes on from a state outside them."""
    runs = {(os.path.basename(os.path.normpath(s.dir)), r.runId): (path, r) for path, s in studies for r in s.runs}

    def origin(path, run):
        seen = set()
        while (path, run.runId) not in seen:   # a loop of states ends
            seen.add((path, run.runId))
            before = runs.get(slicedFrom(run))
            if before is None:
                break
            path, run = before
        return path
    return origin


def realizationRuns(paths, by=(), join=False):
    """(study or variant label, run, its cycles.csv) of every finished realization of the studies at `paths` that
    wrote cycles.csv with cycle and settlement, a realization run in slices once: as its last slice (its slices in
    one study, or going on in another study of `paths`). With `join` a realization whose slices go on in another
    study is labelled by the study it began in (a table of slices read with the table whose rows they carry on:
    their seeds' mean together); without, by the study of its last slice."""
    studies = [(path, StudyRuns(path)) for path in paths]
    origin = began(studies) if join else (lambda path, run: path)
    for path, study in studies:
        earlier = continued(study.runs) | continuedElsewhere(study, [s for _, s in studies if s is not study])
        for run in study.runs:
            c = None if run.runId in earlier else run.cycles
            if c is not None and 'settlement' in c:
                yield variantLabel(origin(path, run), run.params, by), run, c


def realizations(paths, by=(), join=False):
    """What each realization of the studies at `paths` cost and broke, a row each (realizationRuns): study, runId,
    seed, cycles; over all its cycles (the last slice's cycles.csv holds the earlier ones) the crushes and
    abrasions, the largest fatigue damage and stress ratio, the grains after cycle 1 and at the end, and the CPU
    seconds per cycle (over the cycles that have it: a continued slice's first has none) and per realization (that
    mean times its cycles); the cycle in which the most grains crushed (avalancheCycle, the first of equals) and how
    many (avalancheCrushes), NaN when none crushed: where a bed collapses, the cycle variants move; the sleeper's
    largest |tilt| and its tilt after the last cycle (tiltMax, tiltLast [rad]: how far it tipped); from its last
    slice's summary.json the step (timeStep, its dt [s]) and the steps per cycle. NaN where the records have no such
    column (records of before a column was written). `join` as in realizationRuns."""
    rows = []
    for label, run, c in realizationRuns(paths, by, join):
        def over(name, how):
            return float(how(c[name].to_numpy())) if name in c else math.nan
        s = run.summary or {}
        most = int(c['crushes'].to_numpy().argmax()) if 'crushes' in c and c['crushes'].max() > 0 else None
        rows.append({'study': label, 'runId': run.runId, 'seed': run.params.get('seed'), 'cycles': int(c['cycle'].max()),
                     'crushes': over('crushes', np.sum), 'abrasions': over('abrasions', np.sum),
                     'maxDamage': over('maxDamage', np.max), 'maxStressRatio': over('maxStressRatio', np.max),
                     'grainsCycle1': over('nGrains', lambda v: v[0]), 'grainsLast': over('nGrains', lambda v: v[-1]),
                     'cpuPerCycle': over('cpuSeconds', np.nanmean),
                     'avalancheCycle': math.nan if most is None else int(c['cycle'].iloc[most]),
                     'avalancheCrushes': math.nan if most is None else int(c['crushes'].iloc[most]),
                     'tiltMax': over('tilt', lambda v: np.max(np.abs(v))), 'tiltLast': over('tilt', lambda v: v[-1]),
                     'timeStep': float(s.get('dt', math.nan)),
                     'stepsPerCycle': float(s.get('stepsPerCycle', math.nan))})
    frame = pd.DataFrame(rows)
    if len(frame):
        frame['cpuPerRealization'] = frame.cpuPerCycle * frame.cycles   # [s], its cycles at the mean cost
    return frame


def upTo(frame, last):
    """A curves() frame cut to the cycles up to `last`, a sleeper tipping only after them standing again."""
    cut = frame[frame.cycle <= last].copy()
    cut.loc[cut.tippedAt > last, 'tippedAt'] = math.nan
    return cut


def readApart(frame):
    """Per row of a curves() frame whether its realization is left out of the mean: read apart by choice, or its
    sleeper tipped at some cycle (the mean is over one set of realizations at every cycle)."""
    return frame.apart | frame.tippedAt.notna()


def changed(cycles):
    """Per row of cycles.csv whether a grain crushed or abraded in that cycle (settlementlaws.bedChanged of its
    crushes and abrasions, counts in that cycle; records of before 2026-12 read through ballast.study.data get these
    names: LEGACY_COUNTS); None where the file has neither."""
    if 'crushes' not in cycles:
        return None
    return bedChanged(cycles['crushes'], cycles['abrasions'] if 'abrasions' in cycles else 0)


def total(cycles):
    """The settlement [m] of each row of cycles.csv; with cycle jumping, the jumped cycles' extrapolation added."""
    if 'jumped' not in cycles:
        return cycles['settlement']
    # the jumped cycles' share worked out again from the rows, as the code of today extrapolates it
    return cycles['settlement'] + settlementJumped(cycles['cycle'], cycles['settlement'], changed(cycles))


def summary(frame):
    """Per study: the mean and standard deviation of the settlement at every cycle all its runs reached (those read
    apart left out), the laws fitted to the mean and to each run (those apart too); a study whose every run is read
    apart has runs 0 and no mean (settlementFirst, settlementLast and mean None, cycles its longest run's)."""
    out = {}
    for study, every in frame.groupby('study', sort=False):
        g = every[~readApart(every)]
        tipped = every.dropna(subset=['tippedAt']).groupby('runId').tippedAt.first()
        out[study] = {'runs': int(g.runId.nunique()), 'apart': sorted(set(every.runId) - set(g.runId)),
                      'tippedAt': {rid: int(n) for rid, n in dict(tipped).items()},
                      'perRun': {rid: fitLaws(r.cycle, r.settlement) for rid, r in every.groupby('runId') if len(r) >= 3}}
        if g.empty:   # every run tips (a clump box's one sleeper): drawn and fitted each, no mean
            out[study].update(cycles=int(every.cycle.max()), settlementFirst=None, settlementLast=None, mean=None)
            continue
        last = int(g.groupby('runId').cycle.max().min())
        common = g[g.cycle <= last]
        mean = common.groupby('cycle').settlement.agg(['mean', 'std', 'count']).reset_index()
        out[study].update(cycles=last, settlementFirst=float(mean['mean'].iloc[0]),
                          settlementLast=float(mean['mean'].iloc[-1]),
                          mean=fitLaws(mean.cycle, mean['mean']) if last >= 3 else None)
    return out


def paired(frame, study, reference, at):
    """The runs of `study` against those of `reference` with the same seed (the same bed: the pair differs by what
    the studies change, for example the frequency), at the cycles `at` both reached: a DataFrame per seed and cycle
    with both settlements [m], their difference (study - reference) and ratio; and per cycle over the seeds the
    mean difference with its 95 % interval (Student's t, two seeds or more) and the mean ratio, the pairs where
    either is read apart or has tipped by that cycle left out (they stay in the rows, flagged apart or tipped: a
    pair compares one bed at one cycle, valid until a sleeper tips). A seed's realizations read apart by choice
    beside one that is not (a twin of the same bed, perturbed by a resumption) are left out of its pairs.
    ValueError if a study holds two realizations of one seed otherwise (the pair would be ambiguous)."""
    runs = {}
    for name in (study, reference):
        g = frame[frame.study == name]
        g = g[~g.apart | g.groupby('seed').apart.transform('all')]   # apart beside a run of its seed in the mean
        runs[name] = oneRunPerSeed(g, 'paired: ' + name, run='runId').set_index(['seed', 'cycle'])
    mine, ref = runs[study], runs[reference]
    both = pd.MultiIndex.from_tuples([k for k in common(mine.index, ref.index) if k[1] in set(at)],
                                     names=['seed', 'cycle'])
    rows = pd.DataFrame({'seed': both.get_level_values('seed'), 'cycle': both.get_level_values('cycle'),
                         'runId': mine.loc[both, 'runId'].to_numpy(), 'reference': ref.loc[both, 'runId'].to_numpy(),
                         'settlement': mine.loc[both, 'settlement'].to_numpy(),
                         'settlementReference': ref.loc[both, 'settlement'].to_numpy(),
                         'apart': mine.loc[both, 'apart'].to_numpy() | ref.loc[both, 'apart'].to_numpy()})
    cycle = rows.cycle.to_numpy()
    rows['tipped'] = (mine.loc[both, 'tippedAt'].to_numpy() <= cycle) | (ref.loc[both, 'tippedAt'].to_numpy() <= cycle)
    rows['difference'] = rows.settlement - rows.settlementReference
    rows['ratio'] = rows.settlement / rows.settlementReference
    per = []
    for N, g in rows[~(rows.apart | rows.tipped)].groupby('cycle'):
        mean, half = meanInterval(g.difference)
        per.append({'cycle': int(N), 'seeds': len(g), 'meanDifference': mean,
                    'interval95': half if math.isfinite(half) else None,   # one seed: none (JSON null)
                    'meanRatio': float(g.ratio.mean())})
    return rows.sort_values(['cycle', 'seed'], ignore_index=True), per


APART_STYLES = (':', '-.', '--', (0, (1, 3)))  # line styles of the runs read apart, in the order of fits' 'apart'


def figure(frame, fits, path, marks=None):
    """Settlement against log N: every run thin, the mean of each study thick, its logarithmic law dashed.
    The axes fit the data, not the laws (a law that fits badly runs off the panel). Runs read apart (a tipping
    sleeper swings by millimetres) get a panel of their own below, so that the
    settling runs keep the scale of the top panel; there they are drawn only up to their tipping cycle. When every
    run is read apart, they are drawn on one panel, without a mean.
    `marks` {runId: cycle}: a dot on that run's curve at that cycle, e.g. where most of its grains crushed (the
    mean of runs that collapse at different cycles climbs in steps no run has: the dots say where each did)."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    from ..runfiles import plainLogTicks, saveFigure
    apart = readApart(frame)
    split = bool(apart.any()) and not apart.all()   # every run apart: one panel of them, no mean
    if split:
        fig, (ax, low) = plt.subplots(2, 1, figsize=(6.6, 6.6), sharex=True, gridspec_kw={'height_ratios': (2, 1)})
    else:
        fig, ax = plt.subplots(figsize=(6.6, 4.4))
        low = ax
    laws = []
    dotted = False   # the dots' legend entry once
    for k, (study, g) in enumerate(frame.groupby('study', sort=False)):
        colour = 'C%d' % k
        f = fits[study]
        for rid, r in g.groupby('runId'):
            if rid in f['apart']:
                style = APART_STYLES[f['apart'].index(rid) % len(APART_STYLES)]
                label = '%s: tips from cycle %d' % (rid, f['tippedAt'][rid]) if rid in f['tippedAt'] else '%s: read apart' % rid
                low.semilogx(r.cycle, 1e3 * r.settlement, style, color=colour, lw=1, label=label)
                if split and rid in f['tippedAt']:  # before it tips it belongs on the top panel's scale
                    level = r[r.cycle < f['tippedAt'][rid]]
                    ax.semilogx(level.cycle, 1e3 * level.settlement, style, color='0.4', lw=0.9)
            else:
                ax.semilogx(r.cycle, 1e3 * r.settlement, '-', color=colour, lw=0.6, alpha=0.5)
            at = r[r.cycle == (marks or {}).get(rid)]
            if len(at):   # on the panel its run is drawn in
                (low if rid in f['apart'] else ax).semilogx(at.cycle, 1e3 * at.settlement, 'o', color=colour, ms=5,
                                                            mfc='none', label=None if dotted else 'cycle of most crushes')
                dotted = True
        if not f['runs']:
            continue
        inMean = g[~readApart(g)]
        mean = inMean[inMean.cycle <= f['cycles']].groupby('cycle').settlement.mean()
        ax.semilogx(mean.index, 1e3 * mean.values, '-', color=colour, lw=2.2,
                    label='%s: mean of %d runs' % (study.rstrip('/').split('/')[-1], f['runs']))
        if f['mean'] is not None:
            laws.append((colour, f['mean']['log'], np.array(mean.index, float)))
    ax.set_xlim(ax.get_xlim())   # the scale the data set, kept while the laws are drawn
    ax.set_ylim(ax.get_ylim())
    for colour, law, N in laws:
        ax.semilogx(N, 1e3 * (law['a'] + law['b'] * np.log(N)), '--', color=colour, lw=1,
                    label='a + b ln N: b = %.3g mm, R$^2$ = %.3f' % (1e3 * law['b'], law['r2']))
    ax.set_ylabel('permanent settlement [mm]')
    axes = (ax, low) if split else (ax,)
    if apart.all():
        ax.set_title('every run read apart: no mean', fontsize=8)
        ax.set_ylabel('settlement [mm]')
    if split:
        tipped = any(f['tippedAt'] for f in fits.values())
        ax.set_title('runs in the mean' + ('; grey: the tipping runs before they tip' if tipped else ''), fontsize=8)
        low.set_ylabel('settlement [mm]')
        low.set_title('runs read apart, whole history', fontsize=8)
    axes[-1].set_xlabel('load cycles N')
    for a in axes:
        a.grid(True, which='both', alpha=0.3)
        a.legend(fontsize=7)
    plainLogTicks(axes[-1])   # the axes share x
    saveFigure(fig, path)
    return path
