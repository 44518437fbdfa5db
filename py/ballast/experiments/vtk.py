"""VTK XML files for ParaView, written atomically, that every experiment writes: the grains as vertices with
their state (ParaView: Glyph, sphere, scaled by radius), the contact force network (a line per contact), any
unstructured grid of an experiment's walls, and the .pvd time series that lists the frames. YADE's own
``export.VTKExporter`` writes no contact network of this form and no atomic files, so these are ours."""
import numpy as np
from yade import O
from yade.wrapper import Sphere

from .. import harvest
from ..runfiles import writeAtomic


def dataArray(name, data, ncomp=1, kind='Float64'):
    fmt = '%d' if kind.startswith(('Int', 'UInt')) else '%.9g'
    body = ' '.join(fmt % v for v in np.asarray(data).ravel())
    return '<DataArray type="%s" Name="%s" NumberOfComponents="%d" format="ascii">%s</DataArray>\n' % (
        kind, name, ncomp, body)


def unstructuredGrid(path, points, connectivity, offsets, types, pointData='', cellData=''):
    writeAtomic(path, ''.join([
        '<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">\n'
        '<UnstructuredGrid>\n<Piece NumberOfPoints="%d" NumberOfCells="%d">\n' % (len(points), len(offsets)),
        '<Points>\n' + dataArray('Points', points, 3) + '</Points>\n',
        '<Cells>\n' + dataArray('connectivity', connectivity, 1, 'Int64') + dataArray('offsets', offsets, 1, 'Int64') +
        dataArray('types', types, 1, 'UInt8') + '</Cells>\n',
        '<PointData>\n%s</PointData>\n<CellData>\n%s</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n'
        % (pointData, cellData)]))


def writeGrainsVtu(path, table):
    """The grains as vertices with their state (ParaView: Glyph, sphere, scaled by radius)."""
    n = len(table['id'])
    data = ''.join(dataArray(c, table[c], 1, 'Int64' if c in ('id', 'generation', 'parent', 'nAbraded') else 'Float64')
                   for c in ('id', 'r', 'mass', 'generation', 'parent', 'nAbraded', 'stressRatio', 'damage'))
    data += dataArray('velocity', table['velocity'], 3)
    points = np.column_stack([table['x'], table['y'], table['z']]) if n else np.zeros((0, 3))
    unstructuredGrid(path, points, np.arange(n), np.arange(1, n + 1), np.ones(n, dtype=int), data)


def contactNetwork():
    """The real contacts as a force network: (points (n, 2, 3) [m], id1, id2, Fn [N], uN [m]). A sphere-sphere
    contact is the line between the two centres; one with a wall or a facet runs from the sphere's centre to
    the contact point. Read in one pass (harvest.contacts), the few wall contacts' points after it."""
    id1, id2, Fn, uN = harvest.contacts()
    pos, sphere = np.zeros((len(O.bodies), 3)), np.zeros(len(O.bodies), dtype=bool)
    for b in O.bodies:
        if b is not None:
            pos[b.id], sphere[b.id] = tuple(b.state.pos), isinstance(b.shape, Sphere)
    points = np.stack([pos[id1], pos[id2]], axis=1) if len(id1) else np.zeros((0, 2, 3))
    for k in np.flatnonzero(~(sphere[id1] & sphere[id2])):
        a, b = int(id1[k]), int(id2[k])
        c = tuple(O.interactions[a, b].geom.contactPoint)
        points[k] = (pos[a], c) if sphere[a] else (c, pos[b])
    return points, id1, id2, Fn, uN


def writeContactsVtu(path):
    """The contact force network: a line (VTK_LINE) per real contact with Fn, uN, id1, id2 as cell data
    (ParaView: Tube, radius and colour by Fn)."""
    points, id1, id2, Fn, uN = contactNetwork()
    n = len(id1)
    cells = (dataArray('Fn', Fn) + dataArray('uN', uN) + dataArray('id1', id1, 1, 'Int64') + dataArray('id2', id2, 1, 'Int64'))
    unstructuredGrid(path, points.reshape(-1, 3), np.arange(2 * n), np.arange(2, 2 * n + 1, 2), np.full(n, 3), '', cells)


def writePvd(path, frames):
    """ParaView's time series: each frame at its loading time [s], a part per file of the frame (grains, walls,
    contacts; frames of older states have no contacts)."""
    writeAtomic(path, '<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n<Collection>\n' + ''.join(
        '<DataSet timestep="%.9g" part="%d" file="%s"/>\n' % (frame[0], part, name)
        for frame in frames for part, name in enumerate(frame[1:])) + '</Collection>\n</VTKFile>\n')
