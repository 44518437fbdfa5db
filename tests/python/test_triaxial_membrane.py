"""The triaxial cell's membrane in YADE (ballast.experiments.triaxial.membrane): a loose cloud of grains pressed by
the membrane and a top platen at the same pressure p comes to rest carrying p on every side, as the grains' own
contact forces across a vertical and a horizontal plane through the specimen say (no gravity: a half-specimen's
equilibrium makes the force across a diametral plane equal p times its area, 2 R_m H, R_m the membrane's mean
radius, and across a horizontal plane p pi R_m^2); taken off, no grain keeps a force."""
import math

import numpy as np
import pytest

pytest.importorskip('yade')
from yade import O, Vector3, pack, utils  # noqa: E402
from yade.wrapper import FrictMat, PyRunner  # noqa: E402

from ballast import runtime  # noqa: E402
from ballast.experiments import grains, scene  # noqa: E402
from ballast.experiments.triaxial.membrane import Membrane  # noqa: E402

P = 5e4          # [Pa] the cell pressure
R0, H0 = 0.09, 0.3   # [m] the cloud's cylinder


def platenForce():
    """The top platen pressed at P over the membrane's mean cross-section (a plain PyRunner's command)."""
    m = runtime.get(O.tags['testMembrane'])
    area = m.volume / m.height()
    O.forces.setPermF(m.top, Vector3(0, 0, -P * area))


def specimen():
    O.reset()
    grain = FrictMat(young=5e7, poisson=0.2, frictionAngle=0.5, density=2600, label='ballast')
    steel = FrictMat(young=5e8, poisson=0.3, frictionAngle=0.0, density=7800, label='steel')
    O.materials.append(grain)
    O.materials.append(steel)
    sp = pack.SpherePack()
    sp.makeCloud((-R0, -R0, 0.01), (R0, R0, H0), rMean=0.01, rRelFuzz=0.25, num=900, seed=3)
    for c, r in sp:
        if math.hypot(c[0], c[1]) < R0 - r:
            O.bodies.append(utils.sphere(c, r, material=grain, mask=scene.GRAIN_MASK))
    bottom = O.bodies.append(utils.wall(0.0, axis=2, sense=1, material=steel, mask=scene.STEEL_MASK))
    top = utils.wall(H0 + 0.02, axis=2, sense=-1, material=steel, mask=scene.STEEL_MASK)
    top.state.blockedDOFs, top.state.mass, top.state.inertia, top.dynamic = 'xyXYZ', 5.0, Vector3(1, 1, 1), True
    top = O.bodies.append(top)
    m = Membrane(bottom, top, P, cell=0.008, depth=0.004)
    m.update()
    O.tags['testMembrane'] = runtime.register(m)
    O.engines = scene.engines(0.4, 'linear')[:-1] + [
        runtime.callback(m, 'update', iterPeriod=10),
        PyRunner(command='import test_triaxial_membrane as t; t.platenForce()', iterPeriod=10),
        scene.engines(0.4, 'linear')[-1]]
    O.engines[-1].gravity = (0, 0, 0)
    O.dt = 0.5 * utils.PWaveTimeStep()
    return m


def crossing(axis, at):
    """The sum of the `axis` components of the contact forces between grains on either side of the plane
    x_axis = at, as the grain beyond it receives them [N] (positive: compression; YADE applies normalForce +
    shearForce to id2, the opposite to id1)."""
    total = 0.0
    for i in O.interactions:
        if not i.isReal:
            continue
        a, b = O.bodies[i.id1], O.bodies[i.id2]
        if not (grains.kind().isGrain(a) and grains.kind().isGrain(b)):
            continue
        xa, xb = a.state.pos[axis] - at, b.state.pos[axis] - at
        if xa * xb < 0:
            f = i.phys.normalForce + i.phys.shearForce   # the force on id2 (YADE: on id1 it is minus this)
            total += f[axis] if xb > 0 else -f[axis]
    return total


def test_the_specimen_at_rest_carries_the_cell_pressure_on_every_side():
    m = specimen()
    for _ in range(60):
        O.run(500, True)
        if O.iter > 4000 and utils.unbalancedForce() < 0.005:
            break
    assert utils.unbalancedForce() < 0.005, 'the specimen did not come to rest'
    H = m.height()
    Rm = math.sqrt(m.volume / (math.pi * H))
    assert Rm < 0.7 * R0   # the cloud pressed into a column
    cells = m.area / (m.cell ** 2)
    assert m.empty < 0.01 * cells   # the membrane rests on grains all round
    # the lateral stress across the diametral planes x = 0 and y = 0, and the axial across mid-height
    for axis in (0, 1):
        sigma = crossing(axis, 0.0) / (2 * Rm * H)
        assert sigma == pytest.approx(P, rel=0.05), (axis, sigma)
    zMid = O.bodies[m.bottom].state.pos[2] + H / 2
    assert crossing(2, zMid) / (math.pi * Rm ** 2) == pytest.approx(P, rel=0.05)
    # the membrane's forces add up to p times its area, horizontal
    F = np.array([list(O.forces.permF(i)) for i in m.loaded])
    assert np.all(F[:, 2] == 0)
    rho = np.hypot(*np.array([list(O.bodies[i].state.pos)[:2] for i in m.loaded]).T)
    inward = -np.sum((F[:, 0] * np.array([O.bodies[i].state.pos[0] for i in m.loaded])
                      + F[:, 1] * np.array([O.bodies[i].state.pos[1] for i in m.loaded])) / rho)
    assert inward == pytest.approx(P * m.area, rel=0.02)
    loaded = list(m.loaded)
    m.release()
    assert m.loaded == [] and all(O.forces.permF(i).norm() == 0 for i in loaded)
