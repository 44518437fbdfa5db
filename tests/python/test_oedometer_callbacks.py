"""ballast.oedometer.callbacks: PyRunners reach the live experiment, never __main__; a scene without a
saved experiment is refused with a message naming what is missing."""
import pytest

pytest.importorskip('yade')
from yade import O  # noqa: E402

from ballast.oedometer import callbacks  # noqa: E402


class Piece:
    def __init__(self):
        self.calls = 0

    def step(self):
        self.calls += 1


class Live:
    def __init__(self, owns=True):
        self.loading, self.owns = Piece(), owns

    def ownsScene(self):
        return self.owns


def test_command_calls_the_piece_of_the_live_experiment():
    exp = Live()
    callbacks.setLive(exp)
    exec(callbacks.command('loading', 'step'), {})  # as a PyRunner runs it, in a namespace of its own
    assert exp.loading.calls == 1
    callbacks.setLive(None)


def test_a_scene_without_an_experiment_is_refused():
    O.reset()
    callbacks.setLive(Live(owns=False))
    with pytest.raises(RuntimeError, match=r"no saved oedometer \(O.tags\['ballast.oedometer'\] is missing\)"):
        callbacks.fire('loading', 'step')
    callbacks.setLive(None)
