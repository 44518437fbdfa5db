"""ballast.experiments.base: an experiment of the family in a few lines (a falling grain): its parameters
checked once and frozen, runUntil a condition at a step fixed by the check period, its run directory
(never reused, read-only when reopened so), save and reopen through the runtime."""
import os

import pytest

pytest.importorskip('yade')
from yade import O, utils  # noqa: E402
from yade.wrapper import ForceResetter, NewtonIntegrator  # noqa: E402

from ballast import runtime  # noqa: E402
from ballast.experiments.base import Experiment  # noqa: E402
from ballast.experiments.rundir import RunDirectory  # noqa: E402
from ballast.params import Param, Parameters, ParamError, anyText, positive, text  # noqa: E402

G = 10.0   # [m/s^2] gravity of the test
DT = 1e-4  # [s]


class DropParameters(Parameters):
    OWNER = 'Drop'
    PARAMS = {'height': Param(1.0, 'm', 'height of the fall', positive, 'a number > 0'),
              'results': Param('results', 'path', 'results root', anyText, 'a path', text),
              'runId': Param('', '-', 'run id', anyText, 'a name', text),
              'progress': Param(1e9, 's', 'wall seconds between progress lines', positive, 'a number > 0')}

    def fallTime(self):
        """t = sqrt(2 h / g) [s]."""
        return (2 * self.height / G) ** 0.5


@runtime.persistent('test.Drop')
class Drop(Experiment):
    NAME, Parameters, REOPEN_PARAMS = 'drop', DropParameters, ('results', 'runId')

    def prepare(self):
        self.newScene()
        self.grain = O.bodies.append(utils.sphere((0, 0, self.p.height), 0.01))
        O.engines = [ForceResetter(), NewtonIntegrator(gravity=(0, 0, -G), damping=0)]
        O.dt = DT

    def state(self):
        return dict(self.baseState(), grain=self.grain)

    @classmethod
    def fromState(cls, s, ref):
        exp = cls.__new__(cls)
        exp.setBaseState(s, ref)
        exp.grain = s['grain']
        return exp


def test_parameters_are_checked_once_and_frozen(tmp_path):
    with pytest.raises(ParamError, match='Drop: height = -1 is not allowed: expected a number > 0'):
        Drop(height=-1)
    p = DropParameters.check({'height': 0.2, 'results': str(tmp_path)})
    assert Drop(parameters=p).p is p and p.fallTime() == pytest.approx(0.2, rel=1e-12)
    with pytest.raises(TypeError, match='not both'):
        Drop(parameters=p, height=2)


def test_run_until_a_condition_stops_at_the_checked_step(tmp_path):
    """z = h - g dt^2 k (k + 1) / 2 after k updates (YADE's leapfrog: v += g dt, then z += v dt): the grain is
    below h/2 once k (k + 1) > h / (g dt^2) = 1e7, k >= 3162. A check after Newton at step n sees n + 1 updates,
    so checked every 100 steps the condition is first true at step 3200, whose end is where the run stops."""
    exp = Drop(height=1.0, results=str(tmp_path))
    exp.prepare()
    exp.runUntil(lambda: O.bodies[exp.grain].state.pos[2] < 0.5, tEnd=10.0, phase='fall', checkEvery=100)
    assert O.iter == 3201 and exp.phases.steps == {'fall': 3201}
    with pytest.raises(ParamError, match='give a condition or tEnd'):
        exp.runUntil()


def test_run_directory_is_made_once_never_reused_and_read_only_when_asked(tmp_path):
    a, b = RunDirectory(str(tmp_path), 'run'), RunDirectory(str(tmp_path), 'run')
    assert a.path is None and not os.listdir(tmp_path)          # nothing until the first file
    assert os.path.basename(a.create()) == 'run' and os.path.basename(b.create()) == 'run-2'
    assert a.create() == a.path                                  # made once
    with pytest.raises(RuntimeError, match='read-only'):
        RunDirectory(str(tmp_path), 'other', readOnly=True).create()


def test_save_and_reopen_through_the_runtime(tmp_path):
    exp = Drop(height=1.0, results=str(tmp_path), runId='drop')
    exp.prepare()
    exp.dir.create()
    exp.runUntil(tEnd=0.01, phase='fall')
    f = str(tmp_path / 'drop.yade.gz')
    exp.save(f)
    again = Drop.reopen(f, readOnly=True)
    assert again is not exp and again.p == exp.p and again.phases.steps == {'fall': 100} and again.saved == [f]
    assert again.out is None and sorted(os.listdir(tmp_path)) == ['drop', 'drop.yade.gz']
    with pytest.raises(TypeError, match='height cannot be changed'):
        Drop.reopen(f, height=2.0)
    goes = Drop.reopen(f, results=str(tmp_path / 'more'))
    assert os.path.basename(goes.dir.create()) == 'drop'          # named after the run it continues


def test_a_state_is_a_level_1_gzip_stream_yade_reads_with_nothing_left_beside_it(tmp_path):
    """Experiment.save writes YADE's uncompressed archive through gzip at level 1 (XFL 4: the fastest
    compression) without a name or a time stamp (FLG 0, MTIME 0); YADE loads it; no temporary file stays."""
    exp = Drop(height=1.0, results=str(tmp_path), runId='drop')
    exp.prepare()
    exp.runUntil(tEnd=0.01, phase='fall')
    f = str(tmp_path / 'a.yade.gz')
    exp.save(f)
    with open(f, 'rb') as fh:
        head = fh.read(10)
    assert head[:4] == b'\x1f\x8b\x08\x00' and head[4:8] == b'\0\0\0\0' and head[8] == 4
    assert sorted(os.listdir(tmp_path)) == ['a.yade.gz']
    O.load(f)
    assert O.iter == 100 and len(O.bodies) == 1
