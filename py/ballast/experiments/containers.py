"""The containers a sample is built and loaded in, as YADE bodies of steel: the oedometer's cylinder of
facets with a flat bottom, and a box of five walls. Each is built with the steel material and the
group mask of :mod:`.scene`; a cell of a later experiment goes here too."""
import math

from yade import O, Vector3, geom, utils

from .scene import STEEL_COLOR, STEEL_MASK


class Cylinder:
    """The steel cylinder: the ids of its side facets and bottom wall and their rest positions, the inner
    radius Rin [m] (the flat faces) and the vertex radius Rv [m] (facetCylinder's radius, pushed out so
    the faces are at Rin)."""

    def __init__(self, p, steel, height=None):
        self.Rin = p['diameter'] / 2
        self.Rv = self.Rin / math.cos(math.pi / p['segments'])
        height = height or p['height']
        # the side (wallMask 4) of facets; the bottom a wall in the same plane: the facetCylinder's bottom triangles
        # reach from the axis to the rim, so their bounding boxes paired every bottom grain with many of them
        # (the preparation took twice the time)
        facets = geom.facetCylinder((0, 0, height / 2), self.Rv, height, segmentsNumber=p['segments'], wallMask=4,
                                    material=steel, color=STEEL_COLOR, mask=STEEL_MASK)
        self.ids = O.bodies.append(facets)
        self.bottom = O.bodies.append(utils.wall(0.0, axis=2, sense=1, material=steel, color=STEEL_COLOR,
                                                 mask=STEEL_MASK))
        self.ids.append(self.bottom)
        self.pos0 = [Vector3(O.bodies[i].state.pos) for i in self.ids]

    def state(self):
        return {'Rin': self.Rin, 'Rv': self.Rv, 'ids': list(self.ids), 'bottom': self.bottom,
                'pos0': [list(x) for x in self.pos0]}

    @classmethod
    def fromState(cls, s):
        c = cls.__new__(cls)
        c.Rin, c.Rv, c.ids, c.bottom = s['Rin'], s['Rv'], s['ids'], s['bottom']
        c.pos0 = [Vector3(*x) for x in s['pos0']]
        return c


def boxWalls(length, width, steel):
    """The floor at z = 0 and the four side walls of a box of inner length [m] (x) and width [m] (y) centred
    on the z axis: their ids (floor, x-, x+, y-, y+)."""
    L, W = length, width
    kw = dict(material=steel, color=STEEL_COLOR, mask=STEEL_MASK)
    return [O.bodies.append(utils.wall(0.0, axis=2, sense=1, **kw)),
            O.bodies.append(utils.wall(-L / 2, axis=0, sense=1, **kw)),
            O.bodies.append(utils.wall(L / 2, axis=0, sense=-1, **kw)),
            O.bodies.append(utils.wall(-W / 2, axis=1, sense=1, **kw)),
            O.bodies.append(utils.wall(W / 2, axis=1, sense=-1, **kw))]
