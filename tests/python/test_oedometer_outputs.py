"""ballast.oedometer.outputs: per-grain state from the engines' events, colours by state, and the VTK
files read back."""
import xml.etree.ElementTree as ET

import numpy as np
import pytest

pytest.importorskip('yade')
from yade import O  # noqa: E402

from ballast.oedometer.outputs import (COLOR_ABRADED, COLOR_GENERATION, COLOR_ORIGINAL, GrainStates,  # noqa: E402
                                       writeGrainsVtu, writePvd)


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


def test_vtu_and_pvd_read_back(tmp_path):
    n = 3
    table = {'id': np.array([4, 7, 9]), 'x': np.array([0.1, 0.2, 0.3]), 'y': np.zeros(n), 'z': np.array([1., 2., 3.]),
             'r': np.array([0.01, 0.02, 0.03]), 'mass': np.ones(n), 'generation': np.array([0, 1, 2]),
             'parent': np.array([-1, 4, 7]), 'nAbraded': np.zeros(n, dtype=int), 'stressRatio': np.array([0.5, 1.5, 0.1]),
             'damage': np.array([0.0, 0.25, 0.125]), 'velocity': np.arange(9.).reshape(3, 3)}
    writeGrainsVtu(str(tmp_path / 'g.vtu'), table)
    piece = ET.parse(str(tmp_path / 'g.vtu')).getroot().find('./UnstructuredGrid/Piece')
    assert piece.get('NumberOfPoints') == '3' and piece.get('NumberOfCells') == '3'
    pts = np.array(piece.find('./Points/DataArray').text.split(), dtype=float).reshape(-1, 3)
    np.testing.assert_array_equal(pts[:, 2], table['z'])

    def field(name):
        return np.array(piece.find("./PointData/DataArray[@Name='%s']" % name).text.split(), dtype=float)
    np.testing.assert_array_equal(field('parent'), table['parent'])
    np.testing.assert_array_equal(field('stressRatio'), table['stressRatio'])
    np.testing.assert_array_equal(field('damage'), table['damage'])
    np.testing.assert_array_equal(field('velocity'), table['velocity'].ravel())
    writePvd(str(tmp_path / 'o.pvd'), [(0.0, 'g.vtu', 'w0.vtu'), (0.5, 'g1.vtu', 'w1.vtu')])
    ds = ET.parse(str(tmp_path / 'o.pvd')).getroot().findall('./Collection/DataSet')
    assert [(d.get('timestep'), d.get('part'), d.get('file')) for d in ds] == [
        ('0', '0', 'g.vtu'), ('0', '1', 'w0.vtu'), ('0.5', '0', 'g1.vtu'), ('0.5', '1', 'w1.vtu')]
