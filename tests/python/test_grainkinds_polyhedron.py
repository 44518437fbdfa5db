"""The polyhedron kind and its crushing by YADE's PolyhedraSplitter (issue 47, item 4; ballast.grainkinds.polyhedron,
ballast.engines.polyhedra), against values worked out by hand: a cube's and a regular tetrahedron's volume, mass and
inertia; the splitter's stress of a cube pressed between two facets; the force that crushes it,
F = ft0 V / (r_eq h) (the von Mises stress of a uniaxial F h / V against ft0 / r_eq); the pieces' mass and volume
against the grain's; the single-particle test with a polyhedron; the options refused before any work. Debian's
/usr/bin/python3, YADE as a module."""
import math

import numpy as np
import pytest
from yade import O, Vector3, utils
from yade.wrapper import PyRunner

from ballast import grainkinds
from ballast.engines import PolyhedronCrushEngine
from ballast.experiments.scene import polyhedronEngines, polyhedronMaterials
from ballast.geometry import equivalentRadius
from ballast.grainkinds import polyhedron
from ballast.params import ParamError

RHO = 2600.0
P = {'dMin': 0.0205, 'dMax': 0.0445, 'poisson': 0.3, 'friction': 0.5, 'density': RHO, 'steelYoungRatio': 10.0,
     'steelPoisson': 0.25, 'steelFriction': 0.0, 'steelDensity': 7850.0, 'ft0': 3e5}


def _scene(young=3e11):
    O.reset()
    grainkinds.use('polyhedron')
    ballast, steel = polyhedronMaterials(P, young)
    O.engines = polyhedronEngines(0.2, gravity=(0, 0, 0))
    return ballast, steel


def _cube(a, material, z0=0.0):
    v = [(x, y, z0 + z) for x in (-a / 2, a / 2) for y in (-a / 2, a / 2) for z in (-a / 2, a / 2)]
    return polyhedron.addPolyhedron(v, material)


def _facet(z, R, material, up):
    pts = [Vector3(R * math.cos(t), R * math.sin(t), z) for t in (math.pi / 2, math.pi * 7 / 6, math.pi * 11 / 6)]
    return O.bodies.append(utils.facet(pts if up else pts[::-1], material=material, fixed=True))


def test_cube_and_tetrahedron_volume_mass_inertia_by_hand():
    ballast, steel = _scene()
    a = 0.02
    c = _cube(a, ballast, z0=0.1)
    L = 0.03
    t = polyhedron.addPolyhedron([(0, 0, 0), (L, 0, 0), (L / 2, L * math.sqrt(3) / 2, 0),
                                  (L / 2, L * math.sqrt(3) / 6, L * math.sqrt(2 / 3))], ballast)
    f = _facet(-0.1, 0.05, steel, True)
    kind = grainkinds.current()
    assert kind.name == 'polyhedron'
    assert kind.ids().tolist() == [c, t]   # the facet is steel, not a grain
    assert not kind.isGrain(O.bodies[f])
    V = kind.volumes([c, t])
    assert V[0] == pytest.approx(a ** 3, rel=1e-12)
    assert V[1] == pytest.approx(L ** 3 / (6 * math.sqrt(2)), rel=1e-12)
    assert kind.masses([c, t]) == pytest.approx(RHO * V, rel=1e-12)
    assert kind.inertias([c])[0] == pytest.approx([RHO * a ** 5 / 6] * 3, rel=1e-9)
    # a regular tetrahedron's inertia about any axis through its centroid: m L^2 / 20
    assert kind.inertias([t])[0] == pytest.approx([RHO * V[1] * L ** 2 / 20] * 3, rel=1e-9)
    assert kind.radii([c])[0] == pytest.approx((3 / (4 * math.pi)) ** (1 / 3) * a, rel=1e-12)
    assert tuple(O.bodies[c].state.pos) == pytest.approx((0, 0, 0.1), abs=1e-15)


def test_random_grain_has_the_volume_of_its_equivalent_sphere():
    from scipy.spatial import ConvexHull
    _scene()
    v = polyhedron.randomVertices(0.015, [1, 2])
    assert len(v) == polyhedron.VERTICES
    assert ConvexHull(v).volume == pytest.approx(4 / 3 * math.pi * 0.015 ** 3, rel=1e-9)   # SciPy's hull, not YADE's
    assert polyhedron.randomVertices(0.015, [1, 2]) == pytest.approx(v, abs=0)   # the seed gives the grain


def _pressed(ft0, speed=0.05, a=0.02, adjustDt=False):
    """A cube of side a between a fixed bottom facet and a top one closing at speed, the crushing engine and YADE's
    splitter after Newton, and the top facet's force and the contacts' levers recorded every step before them."""
    ballast, steel = _scene()
    cid = _cube(a, ballast)
    bottom, top = _facet(-a / 2, 0.05, steel, True), _facet(a / 2, 0.05, steel, False)
    O.bodies[top].state.vel = (0, 0, -speed)
    crush = PolyhedronCrushEngine(ft0=ft0, iterPeriod=1, adjustDt=adjustDt, label='crush')
    seen = []

    def record():   # (iter, the mean force on the facets [N], sigma_zz V by hand [N m]: -f (z_c - z) on the cube)
        zs = {i.id1: i.geom.contactPoint[2] for i in O.interactions if i.isReal}
        z, ft, fb = O.bodies[cid].state.pos[2], O.forces.f(top)[2], O.forces.f(bottom)[2]
        seen.append((O.iter, (ft - fb) / 2, -ft * (zs.get(top, math.nan) - z) - fb * (zs.get(bottom, math.nan) - z)))
    O.engines = O.engines + [PyRunner(iterPeriod=1, command='_record()')] + crush.engines()
    import builtins
    builtins._record = record
    O.dt = 0.5 * grainkinds.current().pWaveTimeStep()
    return cid, crush, seen


def test_cube_between_facets_crushes_at_the_closed_form_force_and_keeps_its_mass():
    a, ft0 = 0.02, 3e5
    cid, crush, seen = _pressed(ft0, a=a)
    V0, M0 = a ** 3, RHO * a ** 3
    S = None
    while crush.nCrushed == 0 and O.iter < 5000:
        O.step()
        if crush.nCrushed == 0:
            S = grainkinds.current().stressTensors()[cid]
    assert crush.nCrushed == 1
    ev = crush.events[0]
    rEq = (3 * V0 / (4 * math.pi)) ** (1 / 3)
    it, F, SV = next(s for s in seen if s[0] == ev['iter'])
    # the splitter's stress by hand: the facets' forces at the overlaps' centroids; nearly uniaxial, so its von Mises
    # stress is |sigma_zz| (the off-axis terms come from the overlaps' centroids off the axis by 1e-4 a)
    assert SV < 0
    assert ev['value'] == pytest.approx(-SV / V0, rel=1e-4)
    assert ev['strength'] == pytest.approx(ft0 / rEq, rel=1e-12)
    assert ev['value'] > ev['strength']
    prev = next(s for s in seen if s[0] == ev['iter'] - 1)
    assert -prev[2] / V0 < ev['strength'] * (1 + 1e-4)   # the step before was below
    # the closed form with the cube's height (the overlap is about 1e-3 a): within 1 %
    assert F == pytest.approx(ft0 * V0 / (rEq * a), rel=0.01)
    assert S[2, 2] < 0 and abs(S[0, 0]) < 1e-6 * abs(S[2, 2])   # compression negative, uniaxial
    # four pieces: the grain's body and three new ones; mass and volume kept but for the gap YADE leaves, booked
    pieces = ev['newIds']
    assert len(pieces) == 4 and pieces[0] == cid
    kind = grainkinds.current()
    Vp, Mp = kind.volumes(pieces), kind.masses(pieces)
    assert np.all(Vp > 0)
    assert float(np.sum(Mp)) + crush.massLost == pytest.approx(M0, rel=1e-12)
    assert float(np.sum(Vp)) + crush.volumeLost == pytest.approx(V0, rel=1e-12)
    assert Mp == pytest.approx(RHO * Vp, rel=1e-12)
    assert 0 <= crush.volumeLost < 1e-4 * V0
    assert kind.signature()[1] == 1


def test_a_split_shrinks_the_step_as_eq5_says_for_the_smallest_piece():
    """The kind's step is r_eq sqrt(rho / (Y r_eq)) of the smallest grain, so after a split O.dt scales by
    sqrt(r_eq of the smallest piece / r_eq of the cube). (Until 2026-12-05 the step was read after the splitter had cut
    the grain, so it never shrank, and the oedometer's pieces flew out of the cylinder.)"""
    a = 0.02
    _, crush, _ = _pressed(3e5, a=a, adjustDt=True)
    dt0 = O.dt
    while crush.nCrushed == 0 and O.iter < 5000:
        O.step()
    assert crush.nCrushed == 1
    rEq = (3 * a ** 3 / (4 * math.pi)) ** (1 / 3)
    rPiece = float(np.min(equivalentRadius(grainkinds.current().volumes(crush.events[0]['newIds']))))
    assert rPiece < 0.7 * rEq   # a quarter of the cube, about
    assert O.dt == pytest.approx(dt0 * math.sqrt(rPiece / rEq), rel=1e-9)


def test_rMin_stops_pieces_below_it_from_splitting_again():
    a = 0.02
    rEq = (3 * a ** 3 / (4 * math.pi)) ** (1 / 3)
    cid, crush, seen = _pressed(3e4, a=a)
    crush.rMin = 0.9 * rEq   # the cube above it, its quarters (r_eq 0.63 of it) below
    while crush.nCrushed == 0 and O.iter < 5000:
        O.step()
    O.run(300, True)
    assert crush.nCrushed == 1
    assert all(not O.bodies[i].material.IsSplitable for i in crush.events[0]['newIds'])


def test_engine_refuses_what_is_not_the_splitters_rule():
    with pytest.raises(ParamError, match='weibullModulus'):
        PolyhedronCrushEngine(ft0=1e5, weibullModulus=3, iterPeriod=1)
    with pytest.raises(ParamError, match='criterion'):
        PolyhedronCrushEngine(ft0=1e5, criterion='maxContactForce', iterPeriod=1)


def test_single_particle_test_crushes_a_polyhedron_and_its_pieces_keep_the_mass(tmp_path):
    from ballast.experiments.single_particle import SingleParticle
    d = 0.025
    run = SingleParticle(diameters=[d], grain='polyhedron', ft0=3e5, speed=0.1, maxStrain=0.05,
                         results=str(tmp_path), progress=1e3)
    run.prepare()
    gid = run.tester.grain[0]
    V0 = grainkinds.current().volumes([gid])[0]
    M0 = O.bodies[gid].state.mass
    assert V0 == pytest.approx(4 / 3 * math.pi * (d / 2) ** 3, rel=1e-9)
    crush = next(e for e in O.engines if isinstance(e, PolyhedronCrushEngine))
    masses = []
    O.engines = O.engines[:-1] + [PyRunner(iterPeriod=1, command='_pieces()'), O.engines[-1]]
    import builtins
    builtins._pieces = lambda: masses.append(
        sum(O.bodies[i].state.mass for e in crush.events for i in e['newIds'] if O.bodies[i] is not None))
    s = run.load()
    assert s['nCrushed'] == 1
    r = run.tester.result[0]
    assert r['crushed'] and r['value'] > r['strength']
    assert r['strength'] == pytest.approx(3e5 / (d / 2), rel=1e-9)
    assert max(masses) + crush.massLost == pytest.approx(M0, rel=1e-12)
    assert r['F'] > 0


@pytest.mark.parametrize('name, values, bad', [
    ('single_particle', {'grain': 'polyhedron', 'weibullModulus': 3}, 'weibullModulus'),
    ('single_particle', {'grain': 'polyhedron', 'm': 0.5}, 'm'),
    ('single_particle', {'grain': 'polyhedron', 'criterion': 'majorPrincipal'}, 'criterion'),
    ('oedometer', {'grain': 'polyhedron'}, 'abrasion'),   # abrasion on by default: eq. 7 is for spheres
    ('oedometer', {'grain': 'polyhedron', 'abrasion': False, 'loadMode': 'servo'}, 'loadMode'),
    ('box', {'grain': 'polyhedron'}, 'grain'),
    ('triaxial', {'grain': 'polyhedron'}, 'grain'),
])
def test_refused_before_any_work_in_one_line(name, values, bad):
    from ballast.experiments import declaration
    with pytest.raises(ParamError) as e:
        declaration(name).check(values)
    msg = str(e.value)
    assert e.value.name == bad
    assert '\n' not in msg and "%s = " % bad in msg


def test_taken_where_offered():
    from ballast.experiments import declaration
    p = declaration('single_particle').check({'grain': 'polyhedron'})
    assert p['grain'] == 'polyhedron'
    assert declaration('oedometer').check({'grain': 'polyhedron', 'abrasion': False})['grain'] == 'polyhedron'
