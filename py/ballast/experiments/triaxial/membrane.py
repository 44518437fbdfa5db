"""The triaxial cell's membrane in a YADE scene (docs/triaxial.md, "The membrane"): every `period` steps the load of
the cell pressure on the specimen's outermost grains is worked out in C++ (``_ballast.membraneLoad``: rays cast
radially through cells of about `cell` [m] between the platens, gaps deeper than `depth` [m] bridged) and set as
each grain's permanent force (``O.forces.setPermF``), which YADE then applies at every step without Python. The
specimen's volume and lateral area are those the membrane encloses. The grains are the scene's dynamic grains of its kind."""
import math

import numpy as np
from yade import O, Vector3

from ... import _ballast, harvest, runtime

ZERO = Vector3(0, 0, 0)


@runtime.persistent('TriaxialMembrane')
class Membrane:
    """The membrane between the faces of the platens `bottom` and `top` (body ids of YADE walls normal to z), around
    the z axis, under the pressure `pressure` [Pa]; cells of about `cell` [m], gaps deeper than `depth` [m] spanned.
    After each update: loaded (the grain ids it presses), area [m^2], volume [m^3], bridged and empty cells."""

    def __init__(self, bottom=None, top=None, pressure=0.0, cell=0.01, depth=0.005):
        self.bottom, self.top, self.pressure, self.cell, self.depth = bottom, top, pressure, cell, depth
        self.loaded = []
        self.forces = []   # the force [N] set on each loaded grain: YADE's permanent forces are not saved with a scene
        self.area = self.volume = math.nan
        self.bridged = self.empty = 0

    def state(self):
        return {k: getattr(self, k) for k in ('bottom', 'top', 'pressure', 'cell', 'depth', 'loaded', 'forces', 'area',
                                               'volume', 'bridged', 'empty')}

    @classmethod
    def fromState(cls, s, ref=None):
        return runtime.fromAttributes(cls, dict({'forces': None}, **s))   # states of before: worked out again

    def restore(self):
        """The permanent forces of the last update set again on a scene just loaded (O.load keeps no permanent force:
        until the next update the specimen would stand unconfined); a state of before they were kept: an update."""
        if self.forces is None or len(self.forces) != len(self.loaded):
            self.update()
            return
        for i, f in zip(self.loaded, self.forces):
            O.forces.setPermF(i, f)

    def height(self):
        """The distance between the platens' faces [m]."""
        return O.bodies[self.top].state.pos[2] - O.bodies[self.bottom].state.pos[2]

    def grid(self):
        """(grain ids, centres [m], radii [m], cells around, cells along) for the grains as they are: cells of about
        `cell` [m] over the outermost reach and between the platens. The grains are the scene's dynamic grains of
        its kind (harvest.grains: a table rebuilt only when the scene changed), their centres read in C++."""
        table, x = harvest.positions()
        r = table.radii
        reach = float(np.max(np.hypot(x[:, 0], x[:, 1]) + r)) if len(r) else self.cell
        return (table.ids, x, r, max(3, int(round(2 * math.pi * reach / self.cell))),
                max(1, int(round(self.height() / self.cell))))

    def surface(self):
        """The membrane's shape now: (radius [m] per cell (nZ, nTheta), the platens' faces z0, z1 [m])."""
        _, x, r, nT, nZ = self.grid()
        z0, z1 = O.bodies[self.bottom].state.pos[2], O.bodies[self.top].state.pos[2]
        return _ballast.membraneLoad(x, r, self.pressure, 0.0, 0.0, z0, z1, nT, nZ, self.depth)['radius'], z0, z1

    def update(self):
        """The pressure's load worked out for the grains as they are and set as their permanent forces; the grains
        it left since the last update get none."""
        ids, x, r, nT, nZ = self.grid()
        z0, z1 = O.bodies[self.bottom].state.pos[2], O.bodies[self.top].state.pos[2]
        out = _ballast.membraneLoad(x, r, self.pressure, 0.0, 0.0, z0, z1, nT, nZ, self.depth)
        force = out['force']
        carried = np.flatnonzero(force[:, 0] != 0.0)   # a carried cell always has a horizontal force
        now = ids[carried].tolist()
        for i in set(self.loaded) - set(now):
            if i < len(O.bodies) and O.bodies[i] is not None:
                O.forces.setPermF(i, ZERO)
        self.forces = force[carried].tolist()
        setPermF = O.forces.setPermF
        for i, f in zip(now, self.forces):   # a list of 3 floats, taken as YADE's Vector3: 7 times a Vector3's cost
            setPermF(i, f)
        self.loaded = now
        self.area, self.volume = float(out['area']), float(out['volume'])
        self.bridged, self.empty = int(out['bridged']), int(out['empty'])

    def release(self):
        """No pressure on any grain any more (the membrane taken off)."""
        for i in self.loaded:
            if i < len(O.bodies) and O.bodies[i] is not None:
                O.forces.setPermF(i, ZERO)
        self.loaded = []
