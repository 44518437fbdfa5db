"""ballast.experiments.vtk: the grains' VTK file and the .pvd time series, read back as ParaView reads them."""
import xml.etree.ElementTree as ET

import numpy as np
import pytest

pytest.importorskip('yade')
from ballast.experiments.vtk import writeGrainsVtu, writePvd  # noqa: E402


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
