"""ballast.contacts: after a grain shrinks, each of its contacts is the contact YADE creates at the
new radius (compared field by field with a scene built at that radius), its tangential force kept."""
import numpy as np
import pytest
from yade import O, utils
from yade.wrapper import (Bo1_Facet_Aabb, Bo1_Sphere_Aabb, Bo1_Wall_Aabb, ForceResetter, Ig2_Facet_Sphere_ScGeom,
                          Ig2_Sphere_Sphere_ScGeom, Ig2_Wall_Sphere_ScGeom, InsertionSortCollider,
                          InteractionLoop, Ip2_FrictMat_FrictMat_FrictPhys, Ip2_FrictMat_FrictMat_MindlinPhys,
                          Ip2_FrictMat_FrictMat_ViscoFrictPhys, Law2_ScGeom_FrictPhys_CundallStrack,
                          Law2_ScGeom_MindlinPhys_Mindlin, Law2_ScGeom_ViscoFrictPhys_CundallStrack,
                          NewtonIntegrator)

from ballast import contacts
from ballast.scenes import ballastMaterial, steelMaterial

R, R_OTHER, OVERLAP, GAMMA = 0.02, 0.015, 2e-3, 0.95  # [m], [m], [m] (still touching after the shrink), [-]
LAWS = {'linear': (Ip2_FrictMat_FrictMat_FrictPhys, Law2_ScGeom_FrictPhys_CundallStrack, ('kn', 'ks')),
        'hertz': (Ip2_FrictMat_FrictMat_MindlinPhys, Law2_ScGeom_MindlinPhys_Mindlin, ('kno', 'kso')),
        'other': (Ip2_FrictMat_FrictMat_ViscoFrictPhys, Law2_ScGeom_ViscoFrictPhys_CundallStrack, ('kn', 'ks'))}


def scene(law, r):
    """A grain of radius r at the origin touching (for r = R by OVERLAP) a ballast sphere above it, a
    steel wall below it and a steel facet beside it, after one step. Returns the grain's id and its
    partners' ids (sphere, wall, facet)."""
    O.reset()
    O.materials.append(ballastMaterial())
    O.materials.append(steelMaterial())
    ballast, steel = O.materials[0], O.materials[1]
    g = O.bodies.append(utils.sphere((0, 0, 0), r, material=ballast))
    s = O.bodies.append(utils.sphere((0, 0, R + R_OTHER - OVERLAP), R_OTHER, material=ballast))
    w = O.bodies.append(utils.wall(-(R - OVERLAP), axis=2, sense=1, material=steel))
    x = R - OVERLAP
    f = O.bodies.append(utils.facet([(x, -1, -1), (x, 1, -1), (x, 0, 1)], material=steel))
    ip2, law2, _ = LAWS[law]
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb(), Bo1_Facet_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()],
                                 [ip2()], [law2()]),
                 NewtonIntegrator(gravity=(0, 0, 0))]
    O.dt = 1e-10
    O.run(1, True)
    return g, (s, w, f)


def fields(law, g, partners):
    names = LAWS[law][2]
    out = []
    for b in partners:
        i = O.interactions[g, b]
        assert i.isReal, (law, b)
        mine = 1 if i.id1 == g else 2
        out.append([getattr(i.phys, k) for k in names] + [i.geom.refR1 if mine == 1 else i.geom.refR2,
                                                           i.geom.refR2 if mine == 1 else i.geom.refR1])
    return np.array(out)


@pytest.mark.parametrize('law', ['linear', 'hertz', 'other'])
def test_contacts_of_a_shrunk_grain_are_those_created_at_the_new_radius(law):
    fresh = fields(law, *scene(law, GAMMA * R))
    g, partners = scene(law, R)
    before = fields(law, g, partners)
    shear = [O.interactions[g, b].phys.shearForce for b in partners]
    for i, b in enumerate(partners):  # a tangential force to keep (the laws above store it in the physics)
        O.interactions[g, b].phys.shearForce = (1.0 + i, 2.0, 0.0)
    utils.growParticle(g, GAMMA, True)
    assert contacts.resize(g, R, GAMMA * R) == 3
    if law == 'other':  # dropped: YADE's own functor makes it afresh at the next step
        assert all(O.interactions[g, b].phys is None for b in partners)
        O.run(1, True)
    after = fields(law, g, partners)
    # stiffness and reference radii (own side, partner side) as YADE makes them at the new radius
    np.testing.assert_allclose(after, fresh, rtol=1e-12)
    assert np.all(np.abs(before[:, :2] / fresh[:, :2] - 1) > 1e-3)  # they did differ (about 2.6 %, or 5 %)
    if law != 'other':
        for i, b in enumerate(partners):
            assert tuple(O.interactions[g, b].phys.shearForce) == (1.0 + i, 2.0, 0.0)
    assert shear  # read before the change


def test_growparticle_alone_leaves_the_old_stiffness():
    """Why resize exists: YADE's growParticle updates the grain but not its contacts' stiffness."""
    fresh = fields('hertz', *scene('hertz', GAMMA * R))
    g, partners = scene('hertz', R)
    utils.growParticle(g, GAMMA, True)
    stale = fields('hertz', g, partners)
    # kno ~ sqrt(R_eff): 1/sqrt(0.95) = 1.026 against a wall, sphere or facet of the grain's scale
    assert np.all(stale[:, 0] / fresh[:, 0] > 1.01)
