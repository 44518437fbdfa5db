"""The numbers docs/studies.md quotes for the paper-size studies are the committed records' numbers:
each table row of the Fig. 5 section is read back and compared with the study's stats.csv (written by
scripts/aggregate.py from the records), to the digits the table prints."""
import csv
import os
import re

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DOC = os.path.join(ROOT, 'docs', 'studies.md')


def section(heading):
    """The text of docs/studies.md from the line `heading` to the next heading of any level."""
    with open(DOC) as fh:
        text = fh.read()
    start = text.index('\n' + heading + '\n')
    end = re.search(r'\n#+ ', text[start + len(heading) + 2:])
    return text[start:start + len(heading) + 2 + (end.start() if end else len(text))]


def tableRow(text, label, n):
    """The n cells after the label of the markdown table row starting with `| label |`."""
    for line in text.splitlines():
        cells = [c.strip() for c in line.strip().strip('|').split('|')]
        if cells[0] == label:
            assert len(cells) == n + 1, line
            return cells[1:]
    raise AssertionError('no table row %r' % label)


def stats(study, param):
    with open(os.path.join(ROOT, 'docs', 'studies', study, 'stats.csv'), newline='') as fh:
        return sorted(csv.DictReader(fh), key=lambda r: float(r[param]))


def numbers(cell):
    return [float(x) for x in re.findall(r'-?\d+(?:\.\d+)?', cell)]


def checkStatsRows(text, study, param, ncols):
    """The rows of a study's table in the docs that quote its stats.csv, one column per value of param."""
    st = stats(study, param)
    assert len(st) == ncols
    for cell, r in zip(tableRow(text, 'δ at the applied peak, mean ± sd [mm]', ncols), st):
        values = numbers(cell)
        assert values[0] == pytest.approx(1e3 * float(r['deltaAtAppliedPeak_mean [m]']), abs=0.051)
        if r['deltaAtAppliedPeak_std [m]']:  # one run: no standard deviation
            assert values[1] == pytest.approx(1e3 * float(r['deltaAtAppliedPeak_std [m]']), abs=0.051)
    for cell, r in zip(tableRow(text, 'δ_max, mean [mm]', ncols), st):
        assert numbers(cell)[0] == pytest.approx(1e3 * float(r['deltaMax_mean [m]']), abs=0.051)
    for cell, r in zip(tableRow(text, 'grains crushed, mean', ncols), st):
        assert numbers(cell)[0] == pytest.approx(float(r['nCrushed_mean [-]']), abs=0.51)
    for cell, r in zip(tableRow(text, 'CPU per run, mean', ncols), st):
        assert numbers(cell)[0] == pytest.approx(float(r['cpuSeconds_mean [s]']), abs=0.51)
    return st


def test_fig5_table_is_the_records():
    st = checkStatsRows(section('### Fig. 5 at 4 Hz'), 'Tc-4Hz', 'Tc', 6)
    assert all(r['n'] == '20' for r in st)


def readCsv(study, name):
    with open(os.path.join(ROOT, 'docs', 'studies', study, name), newline='') as fh:
        return list(csv.DictReader(fh))


def test_variants_tables_are_the_records():
    text = section('### Why δ depends on T_c: the variants')
    mech = {(r['variant'], float(r['Tc'])): r for r in readCsv('Tc-variants', 'mechanisms.csv')}
    for label, variant in (('damped (`damping 0.6`)', 'damped (0.6)'), ('servo (`loadMode servo`)', 'servo')):
        for cell, tc in zip(tableRow(text, label, 3), (0.0, 6.25e-4, 0.04)):
            mean, sd, crushed = numbers(cell)
            r = mech[variant, tc]
            assert mean == pytest.approx(1e3 * float(r['delta_mean']), abs=0.051)
            assert sd == pytest.approx(1e3 * float(r['delta_std']), abs=0.051)
            assert crushed == pytest.approx(float(r['nCrushed_mean']), abs=0.51)
    # the effects: "| variant | Tc0 -> Tc1 s | change ± sem | baseline's ± sem | effect ± sem |"
    trends = {(r['variant'], float(r['Tc0']), float(r['Tc1'])): r for r in readCsv('Tc-variants', 'trends.csv')}
    rows = [l for l in text.splitlines() if re.match(r'\| (damped|sequential|servo) \| (every step|[\d.e-]+) -> ', l)]
    assert len(rows) == 5
    for line in rows:
        cells = [c.strip() for c in line.strip().strip('|').split('|')]
        tc0, tc1 = [0.0 if x == 'every step' else float(x) for x in re.findall(r'every step|\d[\d.e-]*', cells[1])]
        variant = {'damped': 'damped (0.6)'}.get(cells[0], cells[0])
        r = trends[variant, tc0, tc1]
        for cell, key in zip(cells[2:], ('change', 'baselineChange', 'effect')):
            value, sem = numbers(cell)
            assert value == pytest.approx(1e3 * float(r[key]), abs=0.051)
            assert sem == pytest.approx(1e3 * float(r[{'change': 'sem', 'baselineChange': 'baselineSem', 'effect': 'effectSem'}[key]]),
                                        abs=0.051)


def test_fig4_table_is_the_records():
    text = section('### Fig. 4 at the paper\'s size')
    st = checkStatsRows(text, 'frequency', 'f', 6)
    assert [int(numbers(c)[0]) for c in tableRow(text, 'runs recorded', 6)] == [int(r['n']) for r in st]
    for cell, r in zip(tableRow(text, 'applied force at the first crush, mean [kN]', 6), st):
        assert numbers(cell)[0] == pytest.approx(1e-3 * float(r['forceAtFirstCrush_mean [N]']), abs=0.51)
    for cell, r in zip(tableRow(text, 'largest σ/f_t at F_max/2 before any crush, mean', 6), st):
        assert numbers(cell)[0] == pytest.approx(float(r['stressRatioAtHalfLoad_mean [-]']), abs=5e-4)
    # the per-seed table: delta at the applied peak of every run
    with open(os.path.join(ROOT, 'docs', 'studies', 'frequency', 'runs.csv'), newline='') as fh:
        runs = list(csv.DictReader(fh))
    fs = sorted(set(float(r['f']) for r in runs))
    for seed in sorted(set(r['seed'] for r in runs)):
        for cell, f in zip(tableRow(text, seed, 6), fs):
            (r,) = [r for r in runs if r['seed'] == seed and float(r['f']) == f]
            assert float(cell) == pytest.approx(1e3 * float(r['deltaAtAppliedPeak [m]']), abs=0.051), (seed, f)


def test_half_load_table_is_the_sweep():
    import json
    text = section('#### The force network before the first crush, against f')
    with open(os.path.join(ROOT, 'docs', 'studies', 'halfload', 'test.json')) as fh:
        tests = json.load(fh)
    t = tests['0.2']
    assert [numbers(c)[0] for c in tableRow(text, 'f [Hz]', 3)] == t['f']
    for damping, prefix in (('0.2', ''), ('0.6', 'damping 0.6: ')):
        t = tests[damping]
        assert [numbers(c)[0] for c in tableRow(text, prefix + 'largest σ/f_t at F_max/2, mean', 3)] == \
            pytest.approx(t['ratioMean'], abs=5e-4)
        for label, key in (('unbalanced force at F_max/2, median [-]', 'unbalancedMedian'),
                           ('rms speed of the grains, median [m/s]', 'vRmsMedian')):
            if damping == '0.2' or label.startswith('unbalanced'):
                for cell, value in zip(tableRow(text, prefix + label, 3), t[key]):
                    assert float(cell) == pytest.approx(value, rel=0.05 / 1.9)  # two significant digits
    rise = tests['0.6']['riseAgainstBase']
    assert '%.3f ± %.3f larger at damping 0.2 than at 0.6 (Wilcoxon p = %.3f' % (
        rise['meanDifference'], rise['sem'], rise['pWilcoxon']) in ' '.join(text.split())


def test_half_load_sweep_is_the_first_quarter_of_the_fig4_runs():
    # the same packing, engines and steps up to Fmax/2: the sweep's ratio is the Fig. 4 record's
    from ballast.study import StudyData
    with open(os.path.join(ROOT, 'docs', 'studies', 'halfload', 'runs.csv'), newline='') as fh:
        sweep = {(int(r['seed [-]']), float(r['f [Hz]'])): r['stressRatioAtHalfLoad [-]'] for r in csv.DictReader(fh)
                 if r['stressRatioAtHalfLoad [-]'] and r['damping [-]'] == '0.2'}
    fig4 = {(r.seed, r.value): r.summary['stressRatioAtHalfLoad']
            for r in StudyData(os.path.join(ROOT, 'docs', 'studies', 'frequency')).runs}
    both = [k for k in sweep if fig4.get(k) is not None]
    assert len(both) >= 12
    for k in both:
        assert float(sweep[k]) == pytest.approx(fig4[k], abs=1e-6), k
