"""Tests of ballast.study.table: the grid a study writes, every combination of the values, refused like a table
to run."""
import pytest

from ballast.study.options import StudyError
from ballast.study.table import gridTable, gridValues
from ballast.tables import Table


def test_grid_writes_every_combination_the_first_slowest():
    text, n = gridTable(['seed!=1:2', 'f!=0.5,8'], ['Fmax=6.7e5'], ['a study'], 'study.py grid ...')
    assert n == 4 and text.startswith('# a study\n# written by: study.py grid ...\n')
    t = Table('grid', text)
    assert [r['seed'] + '/' + r['f'] for _, r in t.rows] == ['1/0.5', '1/8', '2/0.5', '2/8']
    assert {r['Fmax'] for _, r in t.rows} == {'6.7e5'} and t.runId(4) == 'seed=1,f=0.5'
    assert gridValues('Tc=0,1e-4') == ('Tc', ['0', '1e-4'])
    for axes, fixed, words in [(['seed=3:1'], [], 'empty range'), (['seed=1 2'], [], 'blank'), (['seed'], [], 'NAME=V1'),
                               (['seed=1:2'], ['f=1,2'], 'one value'), (['f=1:2', 'f!=3'], [], 'twice'),
                               (['seed=1:2', 'f=0,1'], [], 'column f, value 0')]:
        with pytest.raises(StudyError, match=words):
            gridTable(axes, fixed)
