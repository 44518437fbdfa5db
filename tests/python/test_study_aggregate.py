"""Tests of ballast.study.aggregate on fabricated study directories (study_fakes.fabricateStudy, no yade):
the mean and sample standard deviation of stats.csv by hand, the columns of runs.csv."""
import csv
import math

import pytest

from ballast.study.aggregate import fmt, stats, writeCsv
from ballast.study.data import StudyData
from study_fakes import RUNS, fabricateStudy


def byHand(xs):
    m = sum(xs) / len(xs)
    return m, math.sqrt(sum((x - m)**2 for x in xs) / (len(xs) - 1)) if len(xs) > 1 else None


def test_mean_and_sample_std_by_hand(tmp_path):
    data = StudyData(fabricateStudy(tmp_path))
    for st in stats(data):
        mine = [r for r in RUNS if r[1] == st['value']]
        assert st['n'] == len(mine)
        m, s = byHand([r[2] for r in mine])
        assert st['deltaAtPeak_mean'] == pytest.approx(m, rel=1e-12)
        assert math.isnan(st['deltaAtPeak_std']) if s is None else st['deltaAtPeak_std'] == pytest.approx(s, rel=1e-12)
        assert st['nCrushed_mean'] == pytest.approx(byHand([r[3] for r in mine])[0])
        assert math.isnan(st['massLost_mean'])  # not in these summaries


def test_csv_tables(tmp_path):
    data = StudyData(fabricateStudy(tmp_path / 's'))
    runsCsv, statsCsv = writeCsv(data, str(tmp_path))
    with open(statsCsv, newline='') as fh:
        rows = list(csv.DictReader(fh))
    assert [r['Tc'] for r in rows] == ['0', '0.0001', '0.01', '0.04'] and [r['n'] for r in rows] == ['3', '3', '2', '1']
    # Tc = 0.01: 22 and 25 mm, mean 23.5 mm, deviations +-1.5 mm: sample sd sqrt(2 * 1.5^2 / 1)
    assert float(rows[2]['deltaAtPeak_mean [m]']) == pytest.approx(0.0235, rel=1e-12)
    assert float(rows[2]['deltaAtPeak_std [m]']) == pytest.approx(math.sqrt(2 * 0.0015**2), rel=1e-12)
    assert rows[3]['deltaAtPeak_std [m]'] == ''  # one run: no standard deviation
    with open(runsCsv, newline='') as fh:
        runs = list(csv.DictReader(fh))
    assert [r['line'] for r in runs] == [str(n) for n in range(2, 11)] and runs[0]['deltaAtPeak [m]'] == '0.05'
    # the declaration's units head the columns
    assert 'peakForce [N]' in runs[0] and 'Bg [%]' in runs[0] and 'deltaMax_mean [m]' in rows[0]


def test_runs_csv_carries_every_parameter_of_every_run(tmp_path):
    data = StudyData(fabricateStudy(tmp_path / 's', more={'Fmax': lambda i: 1e6 + i}), 'Tc')
    runsCsv, _ = writeCsv(data, str(tmp_path))
    with open(runsCsv, newline='') as fh:
        runs = list(csv.DictReader(fh))
    assert [float(r['Fmax [N]']) for r in runs] == [1e6 + i for i in range(len(RUNS))]


def test_a_cell_is_the_value_in_full_and_missing_is_empty():
    assert fmt(0.1 + 0.2) == '0.30000000000000004' and fmt(3) == '3' and fmt(None) == '' and fmt(float('nan')) == ''
