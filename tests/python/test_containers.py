"""ballast.experiments.containers and .scene: the cylinder's flat faces at the inner diameter, the steel materials."""
import math

import numpy as np
import pytest

pytest.importorskip('yade')
from yade import O  # noqa: E402
from yade.wrapper import Wall  # noqa: E402

from ballast.experiments import scene  # noqa: E402
from ballast.experiments.containers import Cylinder  # noqa: E402
from ballast.oedometer import check  # noqa: E402


def test_cylinder_faces_at_the_inner_radius_and_closed_bottom():
    O.reset()
    p = check({'segments': 24})
    _, steel = scene.materials(p, p['young'])
    cyl = Cylinder(p, steel)
    assert cyl.Rin == p['diameter'] / 2 and cyl.Rv == pytest.approx(cyl.Rin / math.cos(math.pi / 24), rel=1e-14)
    side = []
    for i in cyl.ids:
        b = O.bodies[i]
        if i == cyl.bottom:
            assert isinstance(b.shape, Wall) and b.state.pos[2] == 0 and b.shape.axis == 2 and b.shape.sense == 1
            continue
        side.append(np.array([tuple(b.state.pos + b.state.ori * x) for x in b.shape.vertices]))
    assert len(side) == 2 * 24
    for v in side:  # the mid-point of a side facet's horizontal edge lies on the flat face, at Rin
        z = v[:, 2]
        edge = v[np.isclose(z, z.max())] if np.sum(np.isclose(z, z.max())) == 2 else v[np.isclose(z, z.min())]
        mid = edge.mean(axis=0)
        assert math.hypot(mid[0], mid[1]) == pytest.approx(cyl.Rin, rel=1e-9)
    allz = np.concatenate(side)[:, 2]
    assert allz.max() == pytest.approx(p['height'], rel=1e-12) and allz.min() == pytest.approx(0, abs=1e-12)
    assert all(O.bodies[i].groupMask == scene.STEEL_MASK for i in cyl.ids)


def test_materials_of_section_4():
    O.reset()
    p = check({})
    ballast, steel = scene.materials(p, 2e8)
    assert ballast.young == 2e8 and steel.young == p['steelYoungRatio'] * 2e8
    assert ballast.frictionAngle == p['friction'] and steel.density == p['steelDensity']
