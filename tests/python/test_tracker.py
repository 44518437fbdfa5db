"""ballast.experiments.tracker: per-grain state from the engines' events, colours by state."""
import pytest

pytest.importorskip('yade')
from yade import O  # noqa: E402

from ballast.experiments.tracker import COLOR_ABRADED, COLOR_GENERATION, COLOR_ORIGINAL, GrainStates  # noqa: E402


class Engine:
    def __init__(self, label, events):
        self.label, self.events = label, events


def crush(bid, newIds):
    return {'kind': 'crush', 'id': bid, 'newIds': newIds}


def abrasion(bid):
    return {'kind': 'abrasion', 'id': bid, 'newIds': []}


def test_generations_parents_and_abrasions():
    O.reset()
    c, a = Engine('crush', [crush(2, [5, 6]), crush(6, [7, 8])]), Engine('abrasion', [abrasion(3), abrasion(7), abrasion(3)])
    g = GrainStates()
    changed = g.update([c, a])
    assert sorted(changed) == [3, 3, 5, 6, 7, 7, 8]
    assert list(g.generation[[2, 5, 6, 7, 8]]) == [0, 1, 1, 2, 2]
    assert list(g.parent[[2, 5, 7, 8]]) == [-1, 2, 6, 6]
    assert list(g.nAbraded[[3, 7, 5]]) == [2, 1, 0]
    assert g.update([c, a]) == []  # events are taken in once
    c.events.append(crush(8, [9]))
    assert g.update([c, a]) == [9] and g.generation[9] == 3 and g.parent[9] == 8


def test_colours_by_state():
    g = GrainStates()
    g._grow(4)
    g.generation[1], g.generation[2], g.nAbraded[3] = 1, 2, 4
    assert g.color(0) == pytest.approx(COLOR_ORIGINAL)
    assert g.color(1) == pytest.approx(COLOR_GENERATION[0]) and g.color(2) == pytest.approx(COLOR_GENERATION[1])
    w = 0.75  # at most three quarters of the way to blue
    assert g.color(3) == pytest.approx(tuple((1 - w) * o + w * b for o, b in zip(COLOR_ORIGINAL, COLOR_ABRADED)))
