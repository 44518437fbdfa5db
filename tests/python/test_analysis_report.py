"""Tests of ballast.analysis.report (what scripts/aggregate.py writes) on fabricated studies of every
experiment (study_fakes; no yade): the report names the runs not finished and the code versions, test.json
holds the tests worked out by hand in test_analysis_effects.py and those the declaration's `tested` names,
--out is checked, and a box and a single-particle study aggregate by their declarations; then one real tiny
study of each, run by scripts/study.py and aggregated by scripts/aggregate.py (yade, about a minute)."""
import copy
import csv
import json
import math
import os
import shutil
import subprocess
import sys

import pytest

from ballast.analysis.report import aggregate
from ballast.experiments import declaration
from ballast.study.options import StudyError
from study_fakes import fabricateBox, fabricateSingleParticle, fabricateStudy

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def readCsv(path):
    with open(path, newline='') as fh:
        rows = list(csv.reader(fh))
    return rows[0], [dict(zip(rows[0], r)) for r in rows[1:]]


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
    # Kruskal-Wallis on ranks; every seed rises along Tc: Friedman chi2 = 6, Page's L = 42, two-sided p = 2/216;
    # the crushes fall along Tc in every seed (10 - j): chi2 = 6 again, a fall
    e = {(1, 0): 1, (1, 0.01): -1, (2, 0): -1, (2, 0.01): 1}
    runs = [(s, tc, 1e-3 * (5 * (s - 1) + 10 * j + e.get((s, tc), 0)), 10 - j) for s in (1, 2, 3)
            for j, tc in enumerate((0, 0.01, 0.04))]
    oedometer = copy.copy(declaration('oedometer'))
    oedometer.tested = {'crushes': ('nCrushed', 'grains crushed'), 'onset': ('forceAtFirstCrush', 'the onset')}
    aggregate(fabricateStudy(tmp_path / 's', runs=runs, missing=[]), outDir=str(tmp_path / 'agg'), figures=False,
              experiment=oedometer)
    with open(str(tmp_path / 'agg' / 'test.json')) as fh:
        t = json.load(fh)
    assert t['test'] == 'Kruskal-Wallis' and (t['groups'], t['runs']) == (3, 9)
    assert t['blocked']['chi2'] == pytest.approx(6.0) and t['blocked']['pTrend'] == pytest.approx(2 / 216)
    assert t['crushes']['quantity'] == 'nCrushed' and t['crushes']['chi2'] == pytest.approx(6.0)
    assert t['crushes']['trend'] == 'fall' and t['onset'] is None   # no per-check logs: no onset
    said = capsys.readouterr().out
    assert 'Friedman across Tc within seeds: chi2 = 6, ' in said
    assert 'grains crushed, within seeds: Friedman p = 0.0498 (3 seeds); Page trend: fall, p = 0.00926' in said
    # a declaration that names no further test: the response's alone
    bare = copy.copy(declaration('oedometer'))
    bare.tested = {}
    aggregate(fabricateStudy(tmp_path / 's2', runs=runs, missing=[]), outDir=str(tmp_path / 'agg2'), figures=False,
              experiment=bare)
    with open(str(tmp_path / 'agg2' / 'test.json')) as fh:
        t2 = json.load(fh)
    assert t2['blocked']['chi2'] == pytest.approx(6.0) and 'crushes' not in t2 and 'onset' not in t2
    # one run per value: no test, no test.json
    aggregate(fabricateStudy(tmp_path / 'one', runs=runs[::4], missing=[]), outDir=str(tmp_path / 'agg1'), figures=False)
    assert not os.path.exists(str(tmp_path / 'agg1' / 'test.json'))


def aggregated(study, experiment, param, response, out):
    """aggregate() of a fabricated study of one value of `param`: its runs.csv rows and stats.csv rows, after
    checking the experiment, its response, the files written and that runs.csv's columns are its declared results
    after the run's line, id, parameter and seed."""
    data = aggregate(study, param=param, outDir=str(out))
    assert data.declaration.name == experiment and data.response == response
    assert sorted(os.listdir(str(out))) == ['response.png', 'runs.csv', 'stats.csv']   # one value: no test
    head, runs = readCsv(str(out / 'runs.csv'))
    assert head == ['line', 'runId', param, 'seed'] + ['%s [%s]' % r for r in declaration(experiment).results]
    return runs, readCsv(str(out / 'stats.csv'))[1]


def test_a_box_study_aggregates_by_its_declaration(tmp_path, capsys):
    runs, stats = aggregated(fabricateBox(tmp_path / 'box'), 'box', 'ft0', 'settlement', tmp_path / 'agg')
    assert [r['settlement [m]'] for r in runs] == ['0.0021', '0.0035'] and [r['nAbraded [-]'] for r in runs] == ['2', '0']
    # settlement 2.1 and 3.5 mm: mean 2.8 mm, sample sd 1.4 / sqrt(2) mm; crushes 7 and 11: 9, 4 / sqrt(2)
    assert [r['n'] for r in stats] == ['2'] and stats[0]['ft0'] == '35000'
    assert float(stats[0]['settlement_mean [m]']) == pytest.approx(0.0028, rel=1e-12)
    assert float(stats[0]['settlement_std [m]']) == pytest.approx(0.0014 / math.sqrt(2), rel=1e-12)
    assert float(stats[0]['nCrushed_std [-]']) == pytest.approx(4 / math.sqrt(2), rel=1e-12)
    said = capsys.readouterr().out
    assert 'settlement [mm]' in said and '2.8 +- 0.99 ' in said and '9 +- 2.83 ' in said
    # two values of two seeds each: the Kruskal-Wallis test of the settlement, ranks 1 2 | 3 4:
    # H = 12 / (4 5) (3^2 / 2 + 7^2 / 2) - 3 5 = 2.4, p = P(chi2_1 > 2.4) = 0.1213
    runs4 = [(1, 3e4, 0.001, 0, 0, 0), (2, 3e4, 0.002, 0, 0, 0), (1, 6e4, 0.003, 0, 0, 0), (2, 6e4, 0.004, 0, 0, 0)]
    aggregate(fabricateBox(tmp_path / 'box4', runs4), outDir=str(tmp_path / 'agg4'), figures=False)
    with open(str(tmp_path / 'agg4' / 'test.json')) as fh:
        t = json.load(fh)
    assert t['quantity'] == 'settlement' and t['parameter'] == 'ft0' and 'detectableDifference [m]' in t
    assert t['H'] == pytest.approx(2.4) and t['p'] == pytest.approx(0.12133, abs=1e-5) and t['blocked'] is None


def test_a_single_particle_study_aggregates_by_its_declaration(tmp_path, capsys):
    runs, stats = aggregated(fabricateSingleParticle(tmp_path / 'sp'), 'single_particle', 'n', 'forceOverD2Max',
                             tmp_path / 'agg')
    assert [r['forceOverD2Max [Pa]'] for r in runs] == ['130000000.0', '160000000.0']
    # F/d^2 at the last crush 130 and 160 MPa: mean 145 MPa, sample sd 30 / sqrt(2) MPa; crushed 4 and 3
    assert float(stats[0]['forceOverD2Max_mean [Pa]']) == pytest.approx(1.45e8, rel=1e-12)
    assert float(stats[0]['forceOverD2Max_std [Pa]']) == pytest.approx(3e7 / math.sqrt(2), rel=1e-12)
    assert float(stats[0]['nCrushed_mean [-]']) == pytest.approx(3.5, rel=1e-12)
    said = capsys.readouterr().out
    assert 'forceOverD2Max [MPa]' in said and '145 +- 21.2 ' in said


def runStudy(tmp_path, experiment, table, script):
    """A real study of `experiment` (its table's text) run by scripts/study.py, one yade at a time."""
    path = tmp_path / (experiment + '.table')
    path.write_text(table)
    env = dict(os.environ, OMP_NUM_THREADS='1')
    p = subprocess.run([sys.executable, os.path.join(ROOT, 'scripts', 'study.py'), 'run', str(path), '--experiment',
                        experiment, '--out', str(tmp_path / experiment), '-j', '1', '--progress', '600',
                        '--script', os.path.join(ROOT, 'scripts', script)],
                       capture_output=True, text=True, timeout=600, env=env, cwd=str(tmp_path))
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    return str(tmp_path / experiment)


def aggregateScript(study, param):
    p = subprocess.run([sys.executable, os.path.join(ROOT, 'scripts', 'aggregate.py'), study, '--param', param],
                       capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    return p.stdout


def summaries(study):
    runs = os.path.join(study, 'runs')
    out = []
    for rid in sorted(os.listdir(runs), key=lambda r: r.split(',')[0]):   # seed=1 first: the table's order
        with open(os.path.join(runs, rid, 'summary.json')) as fh:
            out.append(json.load(fh))
    return out


@pytest.mark.skipif(shutil.which('yade') is None, reason='needs yade')
def test_a_real_tiny_box_study_and_single_particle_study_aggregate(tmp_path):
    """Two realizations each: the box of test_box_experiment's small bed for one cycle (about 30 s), the
    single-particle test of two grains (about 10 s)."""
    box = runStudy(tmp_path, 'box', 'seed boxLength boxWidth bedDepth layers sleeperWidth sleeperHeight sleeperMass dMin '
                   'dMax young prepYoung f seatLoad peakLoad cycles ft0 rMin strength\n' + ''.join(
                       '%d 0.3 0.12 0.1 2 0.1 0.05 5 0.02 0.03 3e9 3e8 40 300 4000 1 3.5e4 0.008 1.5e10\n' % s
                       for s in (1, 2)), 'box_test.py')
    sp = runStudy(tmp_path, 'single_particle', 'seed n\n1 2\n2 2\n', 'single_particle.py')
    for study, param, response in ((box, 'ft0', 'settlement'), (sp, 'n', 'forceOverD2Max')):
        said = aggregateScript(study, param)
        assert '2 finished runs of 2 rows' in said, said
        s = summaries(study)
        _, runs = readCsv(os.path.join(study, 'aggregate', 'runs.csv'))
        unit = dict(declaration(os.path.basename(study)).results)[response]
        assert [float(r['%s [%s]' % (response, unit)]) for r in runs] == [x[response] for x in s]
        _, stats = readCsv(os.path.join(study, 'aggregate', 'stats.csv'))
        assert float(stats[0]['%s_mean [%s]' % (response, unit)]) == pytest.approx((s[0][response] + s[1][response]) / 2,
                                                                                   rel=1e-12)
        assert os.path.getsize(os.path.join(study, 'aggregate', 'response.png')) > 10000


def test_a_study_whose_other_parameters_vary_too_reports_without_the_blocked_test(tmp_path, capsys):
    # the box study of the variants (docs/studies/box-sg): seed 1 runs with fatigue on and keep none and volume, so
    # within seeds there are no blocks of one run per value; the test across values is made, the blocked one is not
    records = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'docs', 'studies', 'box-sg')
    aggregate(records, 'fatigue', str(tmp_path), figures=False)
    test = json.load(open(tmp_path / 'test.json'))
    assert test['test'] == 'Kruskal-Wallis' and test['runs'] == 11
    assert 'holds 2 runs of seed 1' in test['blocked']['skipped']
    assert 'Friedman across fatigue within seeds: not made' in capsys.readouterr().out
