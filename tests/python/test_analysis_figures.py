"""Tests of ballast.analysis.figures on fabricated studies (study_fakes.fabricateStudy; no yade): the
axis of Fig. 5, a value's label with its declared unit, and the three figures drawn where the runs'
files have what they show."""
import math
import os

import pytest

from ballast.analysis.figures import axisPositions, plots, valueLabel
from ballast.study.data import StudyData
from study_fakes import fabricateStudy


def test_axis_of_fig5(tmp_path):
    data = StudyData(fabricateStudy(tmp_path / 'a'))
    x, ticks, scale = axisPositions(data, 'auto')  # four decades with Tc = 0: log, 0 one step left
    assert scale == 'log' and ticks[0] == 'every step' and 0 < x[0] < x[1e-4] < x[0.01] < x[0.04]
    # one mean step of the three positive values, (0.04 / 1e-4)^(1/2), left of 1e-4
    assert math.log(x[1e-4] / x[0]) == pytest.approx(math.log(0.04 / 1e-4) / 2)
    assert axisPositions(data, 'no')[2] == 'linear'
    data.numeric, data.values = False, [4, 'planar4']
    assert axisPositions(data, 'auto') == ({4: 0, 'planar4': 1}, ['4', 'planar4'], 'linear')


def test_a_value_is_labelled_with_its_declared_unit(tmp_path):
    data = StudyData(fabricateStudy(tmp_path / 'a'))
    assert valueLabel(data, 0.01) == 'Tc = 0.01 s'
    data.param = 'pattern'  # a parameter without a unit
    assert valueLabel(data, 'planar4') == 'pattern = planar4'


def test_the_figures_are_drawn_from_the_runs_files(tmp_path):
    d = fabricateStudy(tmp_path / 's')
    for run in sorted(os.listdir(os.path.join(d, 'runs')))[:4]:
        with open(os.path.join(d, 'runs', run, 'fd.csv'), 'w') as fh:
            fh.write('t,F,delta,nCrushed,nAbraded,Fapplied\n0,0,0,0,0,0\n0.05,7e5,0.01,1,0,7.5e5\n0.1,1.4e6,0.02,3,0,1.5e6\n')
        with open(os.path.join(d, 'runs', run, 'checks.csv'), 'w') as fh:
            fh.write('t,iter,nCrushed,maxStressRatio\n0.05,5,0,0.5\n0.1,10,2,1.2\n')
    out = tmp_path / 'out'
    out.mkdir()
    paths = plots(StudyData(d), str(out))
    assert [os.path.basename(p) for p in paths] == ['fd_curves.png', 'response.png', 'checks.png']
    assert all(os.path.getsize(p) > 10000 for p in paths)
    # without an F-delta curve and a per-check log there is neither fd_curves.png nor checks.png
    bare = tmp_path / 'bare'
    bare.mkdir()
    assert [os.path.basename(p) for p in plots(StudyData(fabricateStudy(tmp_path / 'b')), str(bare))] == ['response.png']
