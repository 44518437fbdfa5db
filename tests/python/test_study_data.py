"""Tests of ballast.study.data, the one reader of what a study leaves: a run (read_run: its CSV files as
DataFrames, the crushes of events.csv or crushes.csv), a study folder (StudyRuns, StudyData: the
studied parameter, the runs not finished, the response, the experiment of study.json), on fabricated
folders (study_fakes.fabricateStudy; no yade)."""
import json
import os

import pytest

from ballast.study.data import StudyData, StudyRuns, read_run, readTable
from ballast.study.options import StudyError
from study_fakes import MISSING, RUNS, fabricateStudy, runId


def test_a_value_read_back_is_the_value_written(tmp_path):
    # 0.1 + 0.2 and 2/3 in repr, an integer column, an empty cell
    path = tmp_path / 'a.csv'
    path.write_text('x,n,y\n%r,3,\n%r,4,1.5\n' % (0.1 + 0.2, 2 / 3))
    t = readTable(str(path))
    assert list(t['x']) == [0.1 + 0.2, 2 / 3] and list(t['n']) == [3, 4]
    assert t['y'].isna().tolist() == [True, False]
    assert readTable(str(tmp_path / 'none.csv')) is None
    (tmp_path / 'empty.csv').write_text('')
    assert list(readTable(str(tmp_path / 'empty.csv')).columns) == []


def test_one_run_as_dataframes(tmp_path):
    run = tmp_path / 'run'
    run.mkdir()
    (run / 'summary.json').write_text(json.dumps({'params': {'seed': 4, 'f': 2.0}, 'nCrushed': 2}))
    (run / 'row.json').write_text(json.dumps({'codeSha1': 'c' * 40}))
    (run / 'fd.csv').write_text('t,F,delta,nCrushed,nAbraded,Fapplied\n0,0,0,0,0,0\n0.1,5e5,0.002,1,0,6e5\n')
    # two crushes (value / strength = 2.6e8 / 2e8 = 1.3 and 4.4e8 / 4e8 = 1.1) and an abrasion
    (run / 'events.csv').write_text('kind,t,iter,id,x,y,z,radius,value,strength,newIds\n'
                                    'crush,0.2,20,5,0,0,0,0.02,2.6e8,2e8,9 10\nabrasion,0.3,30,7,0,0,0,0.01,9e11,3e11,\n'
                                    'crush,0.4,40,8,0,0,0,0.01,4.4e8,4e8,11\n')
    r = read_run(str(run))
    assert r.params == {'seed': 4, 'f': 2.0} and r.row['codeSha1'] == 'c' * 40
    assert list(r.fd['Fapplied']) == [0, 6e5] and r.checks is None and r.cycles is None
    assert list(r.crushes['t']) == [0.2, 0.4] and list(r.crushes['radius']) == [0.02, 0.01]
    assert list(r.crushes['ratio']) == pytest.approx([1.3, 1.1], rel=1e-12)
    # a record's crushes.csv is read as it is, before events.csv
    (run / 'crushes.csv').write_text('t,radius,ratio\n0.25,0.03,1.05\n')
    assert list(read_run(str(run)).crushes['ratio']) == [1.05]
    os.remove(run / 'summary.json')
    with pytest.raises(StudyError, match=r'RUN: .*run is not a finished run: no summary.json'):
        read_run(str(run))


def test_the_studied_parameter_and_the_runs_not_finished(tmp_path):
    data = StudyData(fabricateStudy(tmp_path / 's'))
    assert data.param == 'Tc' and data.values == [0, 1e-4, 0.01, 0.04] and data.seeds == [1, 2, 3]
    assert sorted(data.missing) == sorted(runId(*m) for m in MISSING) and len(data.runs) == len(RUNS)
    assert [(r.seed, r.value) for r in data.runs] == [r[:2] for r in RUNS]
    assert StudyData(fabricateStudy(tmp_path / 'a', params=False)).values == [0, 1e-4, 0.01, 0.04]  # from the cells
    two = fabricateStudy(tmp_path / 'b', more={'f': lambda i: i % 2 + 1})
    with pytest.raises(StudyError, match='--param: the table varies Tc, f; say which'):
        StudyData(two)
    assert StudyData(two, 'f').values == [1, 2]
    with pytest.raises(StudyError, match=r"--param: 'gamma' is not a column .*columns: seed, Tc, f"):
        StudyData(two, 'gamma')
    one = fabricateStudy(tmp_path / 'c', runs=[r for r in RUNS if r[1] == 0], missing=[])
    with pytest.raises(StudyError, match='no column but the seed varies'):
        StudyData(one)
    with pytest.raises(StudyError, match='no finished run'):
        StudyData(fabricateStudy(tmp_path / 'd', runs=[], missing=MISSING))
    with pytest.raises(StudyError, match=r'STUDY: .* \(no study.json\)'):
        StudyData(str(tmp_path))
    # every run of a study with several varying columns, none singled out
    assert [r.runId for r in StudyRuns(two).runs] == [runId(s, tc, f=i % 2 + 1) for i, (s, tc, _, _) in enumerate(RUNS)]


def test_the_response_is_delta_at_the_applied_peak_when_every_run_has_it(tmp_path):
    """The oedometer's response: delta at the peak of the applied force (t = T/2) where every run records
    it; a study with a run that lacks it falls back to delta at the peak of the measured force."""
    d = fabricateStudy(tmp_path / 'a')
    assert StudyData(d).response == 'deltaAtPeak'
    for k, r in enumerate(RUNS):
        path = os.path.join(d, 'runs', runId(r[0], r[1]), 'summary.json')
        with open(path) as fh:
            s = json.load(fh)
        s['deltaAtAppliedPeak'] = 0.5 * r[2]
        with open(path, 'w') as fh:
            json.dump(s, fh)
        assert StudyData(d).response == ('deltaAtAppliedPeak' if k == len(RUNS) - 1 else 'deltaAtPeak')


def test_the_experiment_is_read_from_study_json(tmp_path):
    d = fabricateStudy(tmp_path / 's')
    assert StudyData(d).declaration.name == 'oedometer'  # a folder older than the key
    with open(os.path.join(d, 'study.json')) as fh:
        info = json.load(fh)
    with open(os.path.join(d, 'study.json'), 'w') as fh:
        json.dump(dict(info, experiment='sleeper'), fh)
    with pytest.raises(StudyError, match=r"--experiment: experiment = 'sleeper' is not allowed: expected one of .*oedometer"):
        StudyData(d)
    assert StudyData(d, experiment='oedometer').param == 'Tc'


def test_the_runs_as_one_frame_and_their_code_versions(tmp_path):
    data = StudyData(fabricateStudy(tmp_path / 's', code=('a' * 40, 'b' * 40)))
    f = data.frame()
    assert list(f['runId']) == [r.runId for r in data.runs] and list(f['value']) == [r[1] for r in RUNS]
    assert list(f['deltaMax']) == pytest.approx([2 * r[2] for r in RUNS]) and list(f['params.seed']) == [r[0] for r in RUNS]
    assert data.codeVersions() == {'a' * 40, 'b' * 40}
