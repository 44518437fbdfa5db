"""ballast.analysis.settlement: the curves read from a study's records, the mean over runs and their laws
(ballast.settlementlaws, tested in test_settlementlaws.py) (no YADE)."""
import json
import math
import os

import numpy as np
import pytest

from ballast.analysis import settlement


def study(root, curves, continueFrom=None):
    """A records folder with one run per curve {runId: (seed, settlements[, more parameters])}; continueFrom
    {runId: the runId whose end state it continued from, in this study, or 'study/runId' in another}."""
    rows = []
    for k, (rid, (seed, s, *more)) in enumerate(curves.items()):
        d = os.path.join(root, 'runs', rid)
        os.makedirs(d)
        params = dict({'seed': seed, 'continueFrom': ''}, **(more[0] if more else {}))
        if continueFrom and rid in continueFrom:   # as a slice's row names it: a path through the records
            where, _, before = continueFrom[rid].rpartition('/')
            params['continueFrom'] = '/elsewhere/docs/studies/%s/runs/%s/state-end.yade.gz' % (
                where or os.path.basename(root), before)
        with open(os.path.join(d, 'summary.json'), 'w') as fh:
            json.dump({'settlement': s[-1], 'params': params}, fh)
        with open(os.path.join(d, 'cycles.csv'), 'w') as fh:
            fh.write('cycle,settlement,resilient\n' + ''.join('%d,%r,1e-6\n' % (n + 1, v) for n, v in enumerate(s)))
        rows.append({'line': k + 2, 'runId': rid, 'row': {'seed': str(seed)}})
    with open(os.path.join(root, 'study.json'), 'w') as fh:
        json.dump({'experiment': 'box', 'rows': rows}, fh)
    return root


def boxSettlement():
    """scripts/box_settlement.py's main()."""
    import runpy
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    return runpy.run_path(os.path.join(root, 'scripts', 'box_settlement.py'))['main']


def test_the_mean_over_runs_and_its_law(tmp_path):
    N = np.arange(1, 11)
    a = list(1e-4 + 4e-5 * np.log(N))
    b = list(1e-4 + 6e-5 * np.log(N)) + [9e-4]   # one cycle more: the mean stops at the common 10
    root = study(str(tmp_path / 'box'), {'s1': (1, a), 's2': (2, b)})
    frame = settlement.curves([root])
    assert len(frame) == 21 and set(frame.seed) == {1, 2}
    f = settlement.summary(frame)[root]
    assert f['runs'] == 2 and f['cycles'] == 10 and f['settlementFirst'] == pytest.approx(1e-4)
    assert f['mean']['log']['b'] == pytest.approx(5e-5, rel=1e-9) and f['perRun']['s2']['log']['r2'] < 1
    assert f['perRun']['s1']['log']['b'] == pytest.approx(4e-5, rel=1e-9)
    assert os.path.isfile(settlement.figure(frame, {root: f}, str(tmp_path / 'settlement.png')))
    assert math.isfinite(f['settlementLast'])
    with pytest.raises(ValueError, match='no run with a cycles.csv'):
        settlement.curves([])


def test_a_realization_run_in_slices_counts_once_as_its_last_slice(tmp_path):
    # seed 1 in two slices (cycles 1-4, then 1-8: a slice's cycles.csv holds the earlier ones), seed 2 in one of 8
    # cycles: two runs to cycle 8, the mean of 1 + n and 3 + n at cycle n
    one = [1e-4 * (1 + n) for n in range(1, 9)]
    two = [1e-4 * (3 + n) for n in range(1, 9)]
    root = study(str(tmp_path / 'box'), {'s1-c4': (1, one[:4]), 's1-c8': (1, one), 's2-c8': (2, two)},
                 continueFrom={'s1-c8': 's1-c4'})
    frame = settlement.curves([root])
    assert sorted(frame.runId.unique()) == ['s1-c8', 's2-c8']
    f = settlement.summary(frame)[root]
    assert f['runs'] == 2 and f['cycles'] == 8 and f['settlementLast'] == pytest.approx(1e-4 * (2 + 8), rel=1e-12)


def test_slices_in_a_study_of_their_own_join_the_study_they_began_in(tmp_path, capsys):
    # seeds 1 and 3 begin in 'level' (cycles 1-4); their slices go on in 'level-slices': seed 1 to 8, seed 3 to 8 and
    # then 12 (a slice of a slice); seed 5 in 'level-slices' goes on from a state outside both (its own)
    one = [1e-4 * n for n in range(1, 13)]
    three = [3e-4 * n for n in range(1, 13)]
    level = study(str(tmp_path / 'level'), {'s1-c4': (1, one[:4]), 's3-c4': (3, three[:4])})
    slices = study(str(tmp_path / 'level-slices'), {'s1-c8': (1, one[:8]), 's3-c8': (3, three[:8]),
                                                    's3-c12': (3, three), 's5-c8': (5, one[:8])},
                   continueFrom={'s1-c8': 'level/s1-c4', 's3-c8': 'level/s3-c4', 's3-c12': 's3-c8',
                                 's5-c8': 'elsewhere/s5-c4'})
    apart = settlement.curves([level, slices])
    assert set(apart.study) == {slices}   # read as they lie: every last slice is in the slices' study
    joined = settlement.curves([level, slices], join=True)
    assert sorted(joined.runId.unique()) == ['s1-c8', 's3-c12', 's5-c8']
    assert dict(joined.groupby('runId').study.first()) == {'s1-c8': level, 's3-c12': level, 's5-c8': slices}
    f = settlement.summary(joined)
    # seeds 1 and 3 to their common cycle 8: the mean of 1e-4 n and 3e-4 n is 2e-4 n
    assert f[level]['runs'] == 2 and f[level]['cycles'] == 8
    assert f[level]['settlementLast'] == pytest.approx(2e-4 * 8, rel=1e-12)
    assert f[slices]['runs'] == 1 and f[slices]['settlementLast'] == pytest.approx(8e-4, rel=1e-12)
    runs = settlement.realizations([level, slices], join=True)
    assert dict(zip(runs.runId, runs.study)) == {'s1-c8': level, 's3-c12': level, 's5-c8': slices}
    assert boxSettlement()([level, slices, '--join', '--out', str(tmp_path / 'out')]) == 0
    assert '%s: 2 runs to cycle 8' % level in capsys.readouterr().out


def caught(monkeypatch):
    """The figures settlement.figure draws from now on, caught where they would be saved."""
    import ballast.runfiles
    figures = []
    monkeypatch.setattr(ballast.runfiles, 'saveFigure', lambda fig, path: figures.append(fig))
    return figures


def drawn(monkeypatch, frame, fits, tmp_path, marks=None):
    """The panels settlement.figure draws."""
    figures = caught(monkeypatch)
    settlement.figure(frame, fits, str(tmp_path / 'caught.png'), marks=marks)
    return figures[0].axes


def dots(ax):
    """(cycle, settlement [mm]) of every dot drawn on the panel `ax`."""
    return [(x, y) for l in ax.get_lines() if l.get_marker() == 'o' for x, y in zip(l.get_xdata(), l.get_ydata())]


def test_a_realization_read_apart_is_fitted_and_drawn_but_left_out_of_the_mean(tmp_path, monkeypatch, capsys):
    # seeds 1 and 3 settle as 1e-4 (1 + ln N) and 1e-4 (3 + ln N); seed 2's sleeper tips (its centre rises):
    # apart, the mean is 1e-4 (2 + ln N) exactly and seed 2 keeps its own laws
    N = np.arange(1, 9)
    root = study(str(tmp_path / 'box'), {'s1': (1, list(1e-4 * (1 + np.log(N)))), 's2': (2, list(-1e-4 * N)),
                                         's3': (3, list(1e-4 * (3 + np.log(N))))})
    frame = settlement.curves([root], apart=[2])
    f = settlement.summary(frame)[root]
    assert f['runs'] == 2 and f['apart'] == ['s2'] and set(f['perRun']) == {'s1', 's2', 's3'}
    assert f['mean']['log']['a'] == pytest.approx(2e-4, rel=1e-9) and f['mean']['log']['b'] == pytest.approx(1e-4, rel=1e-9)
    assert settlement.summary(settlement.curves([root]))[root]['runs'] == 3   # none apart: all three
    assert os.path.isfile(settlement.figure(frame, {root: f}, str(tmp_path / 'settlement.png')))
    top, low = drawn(monkeypatch, frame, {root: f}, tmp_path)
    assert top.get_title() == 'runs in the mean'   # read apart by choice: none tipped, no grey runs to name
    # the top panel keeps the settling runs' scale: nothing of seed 2 (it sinks to -0.8 mm, is never level)
    assert min(min(l.get_ydata()) for l in top.get_lines()) == pytest.approx(0.1, rel=1e-9)
    assert [list(l.get_ydata()) for l in low.get_lines()] == [pytest.approx(list(-0.1 * N), rel=1e-12)]
    (alone,) = drawn(monkeypatch, settlement.curves([root]), settlement.summary(settlement.curves([root])), tmp_path)
    assert min(min(l.get_ydata()) for l in alone.get_lines()) == pytest.approx(-0.8, rel=1e-9)  # none apart: one panel
    # every run apart (a clump box's one tipping sleeper): each fitted and drawn, no mean, and the script still
    # writes its files (it wrote nothing before)
    everyApart = settlement.curves([root], apart=[1, 2, 3])
    f = settlement.summary(everyApart)[root]
    assert f['runs'] == 0 and f['apart'] == ['s1', 's2', 's3'] and f['mean'] is None and f['cycles'] == 8
    assert f['settlementFirst'] is None and set(f['perRun']) == {'s1', 's2', 's3'}
    (one,) = drawn(monkeypatch, everyApart, {root: f}, tmp_path)   # one panel: the three runs, no mean
    assert len(one.get_lines()) == 3 and not [l for l in one.get_lines() if l.get_linewidth() == 2.2]
    assert one.get_title() == 'every run read apart: no mean'
    out = str(tmp_path / 'out')
    assert boxSettlement()([root, '--apart', '1', '2', '3', '--out', out]) == 0
    assert sorted(os.listdir(out)) == ['runs.csv', 'settlement.csv', 'settlement.json']   # the figure: caught above
    assert json.load(open(os.path.join(out, 'settlement.json')))[root]['runs'] == 0
    assert '%s: every run read apart (s1, s2, s3): no mean' % root in capsys.readouterr().out


def test_two_studies_are_compared_seed_by_seed_at_the_cycles_asked(tmp_path, capsys):
    # reference: seed k settles 1e-4 k (1 + ln N); the study: 1.1 times that for seeds 1-3 (differences 1e-5 k
    # (1 + ln N), mean over k = 1..3 is 2e-5 (1 + ln N), standard deviation 1e-5 (1 + ln N), t(0.975, 2) = 4.303)
    # and seed 4 tipping (read apart: flagged, out of the mean); seed 5 only in the reference: no pair
    N = np.arange(1, 31)
    ref = study(str(tmp_path / 'ref'), {'r%d' % k: (k, list(1e-4 * k * (1 + np.log(N)))) for k in range(1, 6)})
    runs = {'s%d' % k: (k, list(1.1e-4 * k * (1 + np.log(N[:25])))) for k in range(1, 4)}
    runs['s4'] = (4, list(-1e-4 * N[:25]))
    mine = study(str(tmp_path / 'mine'), runs)
    rows, per = settlement.paired(settlement.curves([mine, ref], apart=[4]), mine, ref, [1, 10, 25, 30])
    assert sorted(set(rows.cycle)) == [1, 10, 25] and set(rows.seed) == {1, 2, 3, 4}   # cycle 30: the study stops
    assert list(rows[rows.seed == 4].apart) == [True] * 3
    np.testing.assert_allclose(rows[~rows.apart].ratio, 1.1, rtol=1e-12)
    for c in per:
        g = 1 + math.log(c['cycle'])
        assert c['seeds'] == 3 and c['meanDifference'] == pytest.approx(2e-5 * g, rel=1e-9)
        assert c['interval95'] == pytest.approx(4.302653 * 1e-5 * g / math.sqrt(3), rel=1e-6)
        assert c['meanRatio'] == pytest.approx(1.1, rel=1e-12)
    # two realizations of one seed in a study: refused, named
    twice = study(str(tmp_path / 'twice'), {'a': (1, [1e-4, 2e-4]), 'b': (1, [1e-4, 3e-4])})
    with pytest.raises(ValueError, match=r'holds 2 runs of seed 1 \(a, b\)'):
        settlement.paired(settlement.curves([twice, ref]), twice, ref, [1])
    # the command line: the reference read though not listed, its files written
    main = boxSettlement()
    out = str(tmp_path / 'out')
    assert main([mine, '--reference', ref, '--at', '1', '10', '--apart', '4', '--out', out]) == 0
    with open(os.path.join(out, 'settlement-paired.json')) as fh:
        assert [c['cycle'] for c in json.load(fh)[mine]['perCycle']] == [1, 10]
    with open(os.path.join(out, 'settlement.json')) as fh:   # the reference's 30 cycles cut to the study's 25
        assert json.load(fh)[ref]['cycles'] == 25
    assert len(open(os.path.join(out, 'settlement-paired.csv')).read().splitlines()) == 1 + 2 * 4
    assert 'cycle 10 (3 seeds): difference +%.4f mm' % (2e-2 * (1 + math.log(10))) in capsys.readouterr().out


def test_a_sleeper_that_rises_back_is_found_and_read_apart_from_its_onset(tmp_path, capsys, monkeypatch):
    # seeds 1 and 3 settle as 1e-4 (k + ln N); seed 2 settles so to cycle 5 and then rises back 1e-5 m a cycle:
    # 2e-5 m above its deepest at cycle 7, 3e-5 at 8. With a rise of 2.5e-5 m it tips from cycle 8; 1e-3 m: never
    N = np.arange(1, 11)
    two = list(1e-4 * (2 + np.log(N[:5]))) + [1e-4 * (2 + math.log(5)) - 1e-5 * k for k in range(1, 6)]
    assert settlement.tippingOnset(N, two, 2.5e-5) == 8 and settlement.tippingOnset(N, two, 1e-3) is None
    assert settlement.tippingOnset(N, list(1e-4 * np.log(N)), 1e-12) is None   # a settling sleeper never tips
    ref = study(str(tmp_path / 'ref'), {'s%d' % k: (k, list(1e-4 * (k + np.log(N)))) for k in (1, 3)} | {'s2': (2, two)})
    frame = settlement.curves([ref], tipping=2.5e-5)
    f = settlement.summary(frame)[ref]
    assert f['tippedAt'] == {'s2': 8} and f['apart'] == ['s2'] and f['runs'] == 2
    assert f['mean']['log']['a'] == pytest.approx(2e-4, rel=1e-9)   # the mean of seeds 1 and 3
    top, low = drawn(monkeypatch, frame, {ref: f}, tmp_path)   # seed 2 on the top panel only before it tips
    assert [list(l.get_xdata()) for l in top.get_lines() if l.get_color() == '0.4'] == [list(range(1, 8))]
    assert 'grey: the tipping runs before they tip' in top.get_title()
    assert [len(l.get_xdata()) for l in low.get_lines()] == [10]
    assert settlement.summary(settlement.curves([ref], tipping=1e-3))[ref]['runs'] == 3
    # paired with itself scaled 1.1: seed 2's pair counts until cycle 7, not from 8 on
    mine = study(str(tmp_path / 'mine'), {'m%d' % k: (k, list(1.1e-4 * (k + np.log(N)))) for k in (1, 2, 3)})
    rows, per = settlement.paired(settlement.curves([mine, ref], tipping=2.5e-5), mine, ref, [5, 7, 8, 10])
    assert list(rows[rows.seed == 2].tipped) == [False, False, True, True]
    assert [c['seeds'] for c in per] == [3, 3, 2, 2]
    # cut to the first 7 cycles, seed 2 has not tipped there: in the mean again
    cut = settlement.upTo(frame, 7)
    assert cut.cycle.max() == 7 and settlement.summary(cut)[ref]['tippedAt'] == {}
    assert settlement.summary(cut)[ref]['runs'] == 3
    # one seed left in a pair: no interval (JSON null), said so on the command line
    one = study(str(tmp_path / 'one'), {'o2': (2, list(1.1e-4 * (2 + np.log(N))))})
    _, per = settlement.paired(settlement.curves([one, ref]), one, ref, [3])
    assert per[0]['seeds'] == 1 and per[0]['interval95'] is None
    for bad in (0, -1e-5, math.nan, math.inf, '0.02'):
        with pytest.raises(ValueError, match='tipping = .* allowed: a rise above 0 m'):
            settlement.curves([ref], tipping=bad)
    main = boxSettlement()
    assert main([ref, '--tipping', '0.025', '--out', str(tmp_path / 'out')]) == 0
    assert 's2 tips from cycle 8 (read apart)' in capsys.readouterr().out
    assert main([one, '--reference', ref, '--at', '3', '--out', str(tmp_path / 'out')]) == 0
    assert 'cycle 3 (1 seeds): difference +%.4f mm (95 %%: none with one seed)' % (
        1e-2 * (2 + math.log(3))) in capsys.readouterr().out
    for bad in ('0', '-1', 'nan', 'inf', 'x'):
        with pytest.raises(SystemExit):
            main([ref, '--tipping', bad, '--out', str(tmp_path / 'out')])
        assert "--tipping: '%s' mm; allowed: a rise above 0 mm" % bad in capsys.readouterr().err


def test_the_variants_of_one_study_are_studies_of_their_own(tmp_path, capsys):
    # one study, seeds 1-3 each with fatigue on (1e-4 k (1 + ln N)) and off (0.9 times that) and keep none: by
    # fatigue (and keep) two variants, the mean of each, paired: ratio 0.9, difference -1e-5 k (1 + ln N)
    N = np.arange(1, 21)
    runs = {}
    for k in (1, 2, 3):
        runs['on%d' % k] = (k, list(1e-4 * k * (1 + np.log(N))), {'fatigue': True, 'keep': 'none'})
        runs['off%d' % k] = (k, list(0.9e-4 * k * (1 + np.log(N))), {'fatigue': False, 'keep': 'none'})
    root = study(str(tmp_path / 'sg'), runs)
    on, off = root + '[fatigue=1 keep=none]', root + '[fatigue=0 keep=none]'
    frame = settlement.curves([root], by=['fatigue', 'keep'])
    assert set(frame.study) == {on, off}
    f = settlement.summary(frame)
    assert f[on]['runs'] == 3 and f[on]['mean']['log']['b'] == pytest.approx(2e-4, rel=1e-9)
    assert f[off]['mean']['log']['b'] == pytest.approx(1.8e-4, rel=1e-9)
    _, per = settlement.paired(frame, off, on, [10])
    assert per[0]['meanRatio'] == pytest.approx(0.9, rel=1e-12)
    assert per[0]['meanDifference'] == pytest.approx(-2e-5 * (1 + math.log(10)), rel=1e-9)
    with pytest.raises(ValueError, match=r'by = fatigue ft0, but the runs of .* have no parameter ft0'):
        settlement.curves([root], by=['fatigue', 'ft0'])
    with pytest.raises(ValueError, match='holds 2 runs of seed 1'):   # without by the variants are ambiguous
        settlement.paired(settlement.curves([root]), root, root, [10])
    # a twin of seed 1 with fatigue off (a resumed run: another realization of its bed) read apart by its run id:
    # out of the mean and the pairs, which stay those above; not read apart, the pair is ambiguous
    twin = study(str(tmp_path / 'twin'), dict(runs, twin1=(1, list(5e-4 * N), {'fatigue': False, 'keep': 'none'})))
    apart = settlement.curves([twin], by=['fatigue', 'keep'], apart=['twin1'])
    assert set(apart[apart.apart].runId) == {'twin1'}
    assert settlement.summary(apart)[twin + '[fatigue=0 keep=none]']['apart'] == ['twin1']
    rows, per = settlement.paired(apart, twin + '[fatigue=0 keep=none]', twin + '[fatigue=1 keep=none]', [10])
    assert list(rows.runId) == ['off1', 'off2', 'off3'] and per[0]['meanRatio'] == pytest.approx(0.9, rel=1e-12)
    for apartToo in ([], ['twin1', 'off1']):   # none apart, or both: which of seed 1's to pair is ambiguous
        with pytest.raises(ValueError, match='holds 2 runs of seed 1'):
            settlement.paired(settlement.curves([twin], by=['fatigue', 'keep'], apart=apartToo),
                              twin + '[fatigue=0 keep=none]', twin + '[fatigue=1 keep=none]', [10])
    main = boxSettlement()
    out = str(tmp_path / 'out')
    assert main([root, '--by', 'fatigue', 'keep', '--reference', on, '--at', '10', '--out', out]) == 0
    assert main([twin, '--by', 'fatigue', 'keep', '--reference', twin + '[fatigue=1 keep=none]', '--apart', 'twin1',
                 '--out', str(tmp_path / 'twinOut')]) == 0
    assert 'read apart: twin1' in capsys.readouterr().out
    with open(os.path.join(out, 'settlement-paired.json')) as fh:
        assert json.load(fh)[off]['perCycle'][0]['meanRatio'] == pytest.approx(0.9, rel=1e-9)
    assert main([root, '--by', 'fatigue', '--reference', root + '[fatigue=2]', '--out', out]) == 2
    assert '--reference %s[fatigue=2]: no such study or variant; there are' % root in capsys.readouterr().err
    # the variants study under way, its reference variant alone: read, nothing paired, said so
    first = study(str(tmp_path / 'first'), {k: v for k, v in runs.items() if k.startswith('on')})
    alone = str(tmp_path / 'alone')
    assert main([first, '--by', 'fatigue', 'keep', '--reference', first + '[fatigue=1 keep=none]', '--out', alone]) == 0
    assert 'nothing paired' in capsys.readouterr().err and not os.path.exists(os.path.join(alone, 'settlement-paired.csv'))
    with open(os.path.join(alone, 'settlement.json')) as fh:
        assert json.load(fh)[first + '[fatigue=1 keep=none]']['cycles'] == 20   # not cut to nothing


def test_each_realization_reports_what_it_broke_and_cost_over_all_its_slices(tmp_path, capsys, monkeypatch):
    # seed 1 in two slices (the second's cycles.csv holds cycles 1-8, its cycle 5 without CPU as a resumed slice's
    # first), seed 2 in one; crushes 1 in cycles 2 and 6 of seed 1: 2 in all, grains 10 -> 14
    root = study(str(tmp_path / 'box'), {'s1-c4': (1, [1e-4] * 4), 's1-c8': (1, [1e-4] * 8), 's2-c8': (2, [2e-4] * 8)},
                 continueFrom={'s1-c8': 's1-c4'})
    for rid, crushes, cpu in (('s1-c8', [0, 1, 0, 0, 0, 1, 0, 0], [2, 2, 2, 2, math.nan, 4, 4, 4]),
                              ('s2-c8', [0] * 8, [3] * 8)):
        grains = 10 + 2 * np.cumsum(crushes)
        damage = np.linspace(0, 0.5, 8)
        tilt = -0.01 * np.sin(np.arange(8))   # |tilt| largest at cycle 6 (n = 5): 0.00959; the last -0.00657
        with open(os.path.join(root, 'runs', rid, 'cycles.csv'), 'w') as fh:
            fh.write('cycle,settlement,crushes,abrasions,maxDamage,maxStressRatio,nGrains,cpuSeconds,tilt\n' + ''.join(
                '%d,1e-4,%d,0,%r,0.6,%d,%r,%r\n' % (n + 1, crushes[n], damage[n], grains[n], cpu[n], tilt[n])
                for n in range(8)))
        with open(os.path.join(root, 'runs', rid, 'summary.json'), 'w') as fh:
            json.dump({'params': {'seed': int(rid[1]), 'continueFrom': '/x/runs/s1-c4/state-end.yade.gz' if rid == 's1-c8'
                                  else ''}, 'dt': 1e-6, 'stepsPerCycle': 4e4}, fh)
    r = settlement.realizations([root]).set_index('runId')
    assert sorted(r.index) == ['s1-c8', 's2-c8']   # a realization once, as its last slice
    one = r.loc['s1-c8']
    assert (one.cycles, one.crushes, one.grainsCycle1, one.grainsLast) == (8, 2, 10, 14)
    assert one.cpuPerCycle == pytest.approx((4 * 2 + 3 * 4) / 7, rel=1e-12)   # over the 7 cycles with a CPU time
    assert one.cpuPerRealization == pytest.approx(8 * (4 * 2 + 3 * 4) / 7, rel=1e-12)
    assert one.maxDamage == pytest.approx(0.5) and one.timeStep == 1e-6 and r.loc['s2-c8'].crushes == 0
    assert (one.avalancheCycle, one.avalancheCrushes) == (2, 1)   # the first of the two cycles with one crush each
    assert math.isnan(r.loc['s2-c8'].avalancheCycle) and math.isnan(r.loc['s2-c8'].avalancheCrushes)
    assert one.tiltMax == pytest.approx(0.01 * abs(math.sin(5)), rel=1e-12)
    assert one.tiltLast == pytest.approx(-0.01 * math.sin(7), rel=1e-12)
    figures = caught(monkeypatch)
    assert boxSettlement()([root, '--out', str(tmp_path / 'out')]) == 0
    assert dots(figures[0].axes[0]) == [(2, pytest.approx(0.1, rel=1e-12))]   # seed 1's cycle of most crushes only
    written = __import__('pandas').read_csv(str(tmp_path / 'out' / 'runs.csv'))
    assert list(written.runId) == ['s1-c8', 's2-c8'] and 'tippedAt' in written
    said = capsys.readouterr().out
    assert 'crushes 0-2, abrasions 0, largest fatigue damage 0.5' in said and 's1-c8, most crushes in cycle 2 (1)' in said
    assert 'largest tilt 0.00959 rad' in said
    assert 's2-c8, most crushes' not in said


def test_the_axes_fit_the_data_not_a_law_that_fits_it_badly(tmp_path, monkeypatch):
    # a collapse: 0.3 mm for 49 cycles, then 80 mm; a + b ln N runs far below 0 at N = 1, the panel must not follow it
    s = [3e-4] * 49 + [8e-2] * 51
    root = study(str(tmp_path / 'sg'), {'c': (1, s)})
    frame = settlement.curves([root])
    fits = settlement.summary(frame)
    law = fits[root]['mean']['log']
    assert law['a'] < -0.05 and law['r2'] < 0.8   # the law's own value at N = 1: below -50 mm
    (ax,) = drawn(monkeypatch, frame, fits, tmp_path)
    low, high = ax.get_ylim()
    assert -0.1 * 80 < low < 0.3 and 80 < high < 1.1 * 80   # [mm] the data's range and matplotlib's margin
    assert len(ax.get_lines()) == 3   # the run, the mean and the law, drawn all the same
    assert dots(ax) == []
    (ax,) = drawn(monkeypatch, frame, fits, tmp_path, marks={'c': 50, 'elsewhere': 3})
    assert dots(ax) == [(50, pytest.approx(80, rel=1e-12))]   # the collapse's cycle on its run; no run 'elsewhere'
