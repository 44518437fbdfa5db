"""Tests of ballast.analysis.report (what scripts/aggregate.py writes) on fabricated studies
(study_fakes.fabricateStudy; no yade): the report names the runs not finished and the code versions,
test.json holds the tests worked out by hand in test_analysis_effects.py, and --out is checked."""
import json
import os

import pytest

from ballast.analysis.report import aggregate
from ballast.study.options import StudyError
from study_fakes import fabricateStudy


def test_report_names_missing_runs_and_code_versions(tmp_path, capsys):
    d = fabricateStudy(tmp_path / 's', code=('a' * 40, 'b' * 40))
    aggregate(d, figures=False)
    said = capsys.readouterr().out
    assert 'studied parameter Tc (4 values), 3 realizations' in said and 'not finished (left out): 3' in said
    assert 'made by 2 versions of the code (sha1 aaaaaaaaaa, bbbbbbbbbb' in said
    assert os.path.exists(os.path.join(d, 'aggregate', 'stats.csv')) and not os.path.exists(os.path.join(d, 'aggregate', 'fd_curves.png'))
    (tmp_path / 'file').write_text('')
    with pytest.raises(StudyError, match='--out: .* not a directory'):
        aggregate(d, outDir=str(tmp_path / 'file'), figures=False)


def test_test_json_holds_the_tests_across_and_within_seeds(tmp_path, capsys):
    # seeds 1-3 at Tc = 0, 0.01, 0.04: 5 (s - 1) + 10 j mm with residuals +-1 mm on seeds 1 and 2 (test_analysis_effects):
    # Kruskal-Wallis on ranks; every seed rises along Tc: Friedman chi2 = 6, Page's L = 42, two-sided p = 2/216
    e = {(1, 0): 1, (1, 0.01): -1, (2, 0): -1, (2, 0.01): 1}
    runs = [(s, tc, 1e-3 * (5 * (s - 1) + 10 * j + e.get((s, tc), 0)), 0) for s in (1, 2, 3) for j, tc in enumerate((0, 0.01, 0.04))]
    aggregate(fabricateStudy(tmp_path / 's', runs=runs, missing=[]), outDir=str(tmp_path / 'agg'), figures=False)
    with open(str(tmp_path / 'agg' / 'test.json')) as fh:
        t = json.load(fh)
    assert t['test'] == 'Kruskal-Wallis' and (t['groups'], t['runs']) == (3, 9)
    assert t['blocked']['chi2'] == pytest.approx(6.0) and t['blocked']['pTrend'] == pytest.approx(2 / 216)
    assert t['onset'] is None and t['network'] is None  # no per-check logs
    assert 'Friedman across Tc within seeds: chi2 = 6, ' in capsys.readouterr().out
    # one run per value: no test, no test.json
    aggregate(fabricateStudy(tmp_path / 'one', runs=runs[::4], missing=[]), outDir=str(tmp_path / 'agg1'), figures=False)
    assert not os.path.exists(str(tmp_path / 'agg1' / 'test.json'))
