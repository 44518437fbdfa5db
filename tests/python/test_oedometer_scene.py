"""ballast.oedometer.scene: the cylinder's flat faces at the inner diameter, the steel materials."""
import math

import numpy as np
import pytest

pytest.importorskip('yade')
from yade import O  # noqa: E402

from ballast.oedometer import check, scene  # noqa: E402


def test_cylinder_faces_at_the_inner_radius_and_closed_bottom():
    O.reset()
    p = check({'segments': 24})
    _, steel = scene.materials(p, p['young'])
    cyl = scene.Cylinder(p, steel)
    assert cyl.Rin == p['diameter'] / 2 and cyl.Rv == pytest.approx(cyl.Rin / math.cos(math.pi / 24), rel=1e-14)
    side, bottom = [], []
    for i in cyl.ids:
        b = O.bodies[i]
        v = np.array([tuple(b.state.pos + b.state.ori * x) for x in b.shape.vertices])
        (bottom if np.allclose(v[:, 2], 0) else side).append(v)
    assert len(side) == 2 * 24 and len(bottom) == 24
    for v in side:  # a side facet's mid-point of its horizontal edge lies on the flat face, at Rin
        top = v[np.argsort(v[:, 2])][1:] if np.sum(np.isclose(v[:, 2], v[:, 2].max())) == 2 else v[np.argsort(v[:, 2])][:2]
        mid = top.mean(axis=0)
        assert math.hypot(mid[0], mid[1]) == pytest.approx(cyl.Rin, rel=1e-9)
    assert np.max(np.concatenate(side)[:, 2]) == pytest.approx(p['height'], rel=1e-12)


def test_materials_of_section_4():
    O.reset()
    p = check({})
    ballast, steel = scene.materials(p, 2e8)
    assert ballast.young == 2e8 and steel.young == p['steelYoungRatio'] * 2e8
    assert ballast.frictionAngle == p['friction'] and steel.density == p['steelDensity']
