"""ballast.experiments.phases: a phase ends at its simulated end time or when its test says so, at a
step fixed by the test's period (never by the machine's speed), with steps counted per phase."""
import time

import pytest

pytest.importorskip('yade')
from yade import O, utils  # noqa: E402
from yade.wrapper import ForceResetter, NewtonIntegrator  # noqa: E402

from ballast.experiments.phases import Phases  # noqa: E402


class Live:
    def __init__(self):
        self.phases = Phases(progressSeconds=1e9, name='test')


def falling():
    O.reset()
    O.bodies.append(utils.sphere((0, 0, 0), 0.01))
    O.engines = [ForceResetter(), NewtonIntegrator(gravity=(0, 0, -10), damping=0)]
    O.dt = 1e-4


def test_phase_ends_at_its_time():
    falling()
    exp = Live()
    exp.phases.run('fall', tEnd=0.25)
    assert abs(O.time - 0.25) <= 0.5 * O.dt
    assert exp.phases.steps['fall'] == O.iter == 2500


def test_phase_ends_when_done_at_a_checked_step():
    falling()
    exp = Live()
    # v = g (k + 1) dt after step k: |v| > 1 m/s from step 1000; checked every 300 steps, the test is
    # true at step 1200, whose end is where the run stops
    exp.phases.run('fall', lambda: -O.bodies[0].state.vel[2] > 1.0, tEnd=10.0, checkEvery=300)
    assert O.iter == 1201 and exp.phases.steps['fall'] == 1201
    assert not [e for e in O.engines if e.label == Phases.LABEL]  # the checker is gone
    exp.phases.run('more', tEnd=O.time + 0.01)
    assert exp.phases.steps == {'fall': 1201, 'more': 100}


class SlowEnd(Phases):
    """The phase's test ends a step that then goes on for a while (a loaded machine's descheduled worker)."""

    def check(self):
        super().check()
        if self.finished:
            time.sleep(0.3)
            self.stepWhole = O.iter  # the step's iteration, still unincremented


def test_a_phase_returns_only_once_its_last_step_is_whole():
    """The audit: with O.pause() the run returned while the worker still ran the step, and the next run
    could let that worker step once more (a packing built under load ended its press one step later)."""
    falling()
    exp = Live()
    exp.phases = SlowEnd(progressSeconds=1e9, name='test')
    exp.phases.stepWhole = None
    exp.phases.run('fall', lambda: O.iter >= 400, tEnd=10.0, checkEvery=100)
    assert exp.phases.stepWhole == 400 and O.iter == 401  # returned after the step, not during it
    exp.phases.run('more', tEnd=O.time + 0.01)
    assert exp.phases.steps == {'fall': 401, 'more': 100}


def test_a_state_saved_mid_phase_counts_its_steps_so_far():
    """The audit: a run resumed from a state saved mid-loading counted only the steps after the resume."""
    falling()
    exp = Live()
    seen = []
    exp.phases.run('fall', tEnd=0.05, afterChunk=lambda: seen.append((O.iter, exp.phases.state()['steps']['fall'])))
    assert seen and all(steps == it for it, steps in seen)
    resumed = Phases.fromState(dict(exp.phases.state(), steps={'fall': 300}))  # as if saved at step 300
    resumed.run('fall', tEnd=O.time + 0.01)
    assert resumed.steps['fall'] == 300 + 100


def test_the_time_left_uses_the_whole_phase_rate():
    """The ETA swung from 5 s to 11 min (a 30 s window); it is the phase's simulated time over its wall time."""
    falling()
    line = Live().phases._line('load', 0.01, simSpan=1.0, simStart=0.0, extra=None)  # 0.01 s simulated per second
    assert 'ETA 1m40s' in line, line
