"""Tests of py/ballast/engines/crush.py inside YADE, against values computed by hand: BallastCrushEngine.
Crushing exactly above the strength for each criterion, Weibull strength factors, the fragments
(inside the parent, its rigid-body velocity, keep='mass'), rMin, a burst of crushing and maxPerCheck.
Runs in Debian's /usr/bin/python3 with YADE imported as a module (see conftest.py)."""
import math

import numpy as np
import pytest
from yade import O, utils

import ballast
from ballast.engines import BallastAbrasionEngine, BallastCrushEngine
from ballast.scenes import squeezedStress
from engine_scenes import OVERLAP, R, add, loadedGrain, packedBox


def potentialEnergy():
    return sum(b.state.mass * 9.81 * b.state.pos[2] for b in O.bodies if b is not None and b.dynamic)


@pytest.mark.parametrize('ratio', [1.01, 0.99])
def test_grain_crushes_when_and_only_when_sigma_e_exceeds_ft(ratio):
    g, w1, F, arm, uN = loadedGrain()
    sigmaE = squeezedStress(F, R, arm)           # eqs. 2-3 by hand
    assert arm == pytest.approx(R - OVERLAP, rel=1e-9)  # a wall contact point lies on the wall
    ft = sigmaE / ratio                          # f_t = ft0 / r (eq. 4)
    crush = add(BallastCrushEngine(ft0=ft * R, iterPeriod=1, label='crush'))
    O.run(2, True)
    assert crush.nChecks >= 1
    assert crush.maxStressRatio == pytest.approx(ratio, rel=1e-9) or crush.nCrushed == 1
    if ratio > 1:
        assert crush.nCrushed == 1 and O.bodies[g] is None
        e = crush.events[0]
        assert e['kind'] == 'crush' and e['id'] == g and e['radius'] == R
        assert e['value'] == pytest.approx(sigmaE, rel=1e-9)
        assert e['strength'] == pytest.approx(ft, rel=1e-12)
        a = crush.eventsArray()
        assert a.shape == (1,) and a['id'][0] == g and a['nNew'][0] == 6 and a['value'][0] == e['value']
        assert (a['x'][0], a['y'][0], a['z'][0]) == (0.0, 0.0, 0.0)   # the grain sat at the origin
        header = str(a).splitlines()[0].split()   # printed as a table with its column names
        assert header == ['t', 'iter', 'id', 'x', 'y', 'z', 'radius', 'value', 'strength', 'nNew']
    else:
        assert crush.nCrushed == 0 and O.bodies[g] is not None
        assert crush.maxCrushableRatio == crush.maxStressRatio  # rMin = 0: every grain can crush


@pytest.mark.parametrize('criterion', ['vonMises', 'maxContactForce', 'majorPrincipal'])
@pytest.mark.parametrize('ratio', [1.01, 0.99])
def test_each_criterion_crushes_when_its_stress_exceeds_ft(criterion, ratio):
    """A grain squeezed between two walls by F at arm R - overlap: von Mises and the major principal stress of
    eq. 3 are both 2 F arm / V (uniaxial), de Bono & McDowell's F / d^2 = F / (4 R^2)."""
    g, w1, F, arm, uN = loadedGrain()
    stress = F / (4 * R ** 2) if criterion == 'maxContactForce' else squeezedStress(F, R, arm)
    crush = add(BallastCrushEngine(ft0=stress / ratio * R, criterion=criterion, iterPeriod=1, label='crush'))
    O.run(2, True)
    assert crush.nCrushed == (1 if ratio > 1 else 0)
    if ratio > 1:
        assert crush.events[0]['value'] == pytest.approx(stress, rel=1e-9)
    else:
        assert crush.maxStressRatio == pytest.approx(ratio, rel=1e-9)


def test_weibull_strengths_per_grain_reproducible_and_fragments_draw_their_own():
    """weibullModulus k: a grain's strength is w ft0 / r with w = weibullFactors(seed, id, k); the crush event
    carries it; the same seed gives the same factors, another seed others; fragments (new ids) their own."""
    g, w1, F, arm, uN = loadedGrain()
    se = squeezedStress(F, R, arm)
    w = float(ballast.weibullFactors(4, [g], 3.0)[0])
    crush = add(BallastCrushEngine(ft0=se * R / w / 1.01, weibullModulus=3.0, seed=4, iterPeriod=1, label='crush'))
    O.run(2, True)
    assert crush.nCrushed == 1
    e = crush.events[0]
    assert e['strength'] == pytest.approx(w * se / w / 1.01, rel=1e-12)
    np.testing.assert_array_equal(crush.strengthFactors(e['newIds']), ballast.weibullFactors(4, e['newIds'], 3.0))
    assert len(set(crush.strengthFactors(e['newIds']).tolist())) == len(e['newIds'])
    assert ballast.weibullFactors(5, [g], 3.0)[0] != w
    assert BallastCrushEngine(ft0=1.0).strengthFactors([g]) is None  # k = 0: the paper's strength
    # the factors are kept between checks of the same grains, drawn again for other grains, seed or modulus
    ids = [g] + e['newIds']
    kept = crush.strengthFactors(ids)
    assert crush.strengthFactors(list(ids)) is kept and not kept.flags.writeable
    np.testing.assert_array_equal(crush.strengthFactors(ids[1:]), ballast.weibullFactors(4, ids[1:], 3.0))
    crush.seed = 5
    np.testing.assert_array_equal(crush.strengthFactors(ids), ballast.weibullFactors(5, ids, 3.0))
    crush.weibullModulus = 2.0
    np.testing.assert_array_equal(crush.strengthFactors(ids), ballast.weibullFactors(5, ids, 2.0))


@pytest.mark.parametrize('pattern', [4, 'planar4', 6, 14])
def test_fragments_inside_parent_without_overlap_and_ledger(pattern):
    g, w1, F, arm, uN = loadedGrain()
    pos = np.array(O.bodies[g].state.pos)
    m0 = O.bodies[g].state.mass
    crush = add(BallastCrushEngine(ft0=1.0, pattern=pattern, seed=3, iterPeriod=1))
    O.run(1, True)
    assert crush.nCrushed == 1
    ids = crush.events[0]['newIds']
    frag = [O.bodies[i] for i in ids]
    c = np.array([f.state.pos for f in frag])
    r = np.array([f.shape.radius for f in frag])
    assert len(ids) == len(ballast.fragmentPattern(pattern))
    assert np.all(np.linalg.norm(c - pos, axis=1) + r <= R * (1 + 1e-12))
    gap = np.linalg.norm(c[:, None] - c[None], axis=2) - (r[:, None] + r[None])
    assert np.all(gap[~np.eye(len(ids), dtype=bool)] >= -1e-12 * R)
    kept = ballast.keptVolumeFraction(pattern)
    assert crush.volumeLost == pytest.approx((1 - kept) * 4 / 3 * math.pi * R ** 3, rel=1e-12)
    assert crush.massLost == pytest.approx((1 - kept) * m0, rel=1e-12)
    # mass and inertia from each fragment's own radius and density
    rho = O.bodies[ids[0]].material.density
    for f in frag:
        m = 4 / 3 * math.pi * f.shape.radius ** 3 * rho
        assert f.state.mass == pytest.approx(m, rel=1e-12)
        assert f.state.inertia[0] == pytest.approx(0.4 * m * f.shape.radius ** 2, rel=1e-12)
        assert f.material.label == 'ballast'


def test_fragments_move_with_the_parent_rigid_body_velocity():
    g, w1, F, arm, uN = loadedGrain()
    b = O.bodies[g]
    v, w = np.array([0.3, -0.2, 0.0]), np.array([1.0, 2.0, 5.0])
    b.state.vel, b.state.angVel = tuple(v), tuple(w)  # kept constant by the blocked DOFs
    crush = add(BallastCrushEngine(ft0=1.0, pattern=14, iterPeriod=1))
    O.run(1, True)
    frag = [O.bodies[i] for i in crush.events[0]['newIds']]
    m = np.array([f.state.mass for f in frag])
    vel = np.array([f.state.vel for f in frag])
    x = np.array([f.state.pos for f in frag])
    parent = np.array(crush.events[0]['pos'])       # the parent's centre when it crushed
    np.testing.assert_allclose((m[:, None] * x).sum(0) / m.sum(), parent, rtol=0, atol=1e-15)
    np.testing.assert_allclose(vel, v + np.cross(w, x - parent), rtol=0, atol=1e-12)
    # momentum is kept with the mass kept: centre-of-mass velocity of the fragments = parent velocity
    np.testing.assert_allclose((m[:, None] * vel).sum(0) / m.sum(), v, rtol=0, atol=1e-12)
    for f in frag:
        np.testing.assert_allclose(np.array(f.state.angVel), w, atol=1e-15)


@pytest.mark.parametrize('pattern', [4, 'planar4', 6, 14])
def test_keep_mass_scales_the_fragments_to_the_parents_mass_and_momentum(pattern):
    """keep='mass': each fragment's mass is rho 4/3 pi r_f^3 times M / (rho V_fragments) = 1 / kept, so the
    fragments weigh M: the mass ledger loses nothing, the lost volume is the geometric one, the moment of
    inertia stays 2/5 m r_f^2 of the scaled mass, and the momentum is M v."""
    g, w1, F, arm, uN = loadedGrain()
    b = O.bodies[g]
    v = np.array([0.0, 0.0, 0.4])
    b.state.vel = tuple(v)
    M = b.state.mass
    crush = add(BallastCrushEngine(ft0=1.0, pattern=pattern, keep='mass', iterPeriod=1))
    O.run(1, True)
    frag = [O.bodies[i] for i in crush.events[0]['newIds']]
    m = np.array([f.state.mass for f in frag])
    kept = ballast.keptVolumeFraction(pattern)
    assert m.sum() == pytest.approx(M, rel=1e-12) and crush.massLost == pytest.approx(0.0, abs=1e-12 * M)
    assert crush.volumeLost == pytest.approx((1 - kept) * 4 / 3 * math.pi * R ** 3, rel=1e-12)
    rho = b.material.density if O.bodies[g] is not None else frag[0].material.density
    for f in frag:
        m0 = 4 / 3 * math.pi * f.shape.radius ** 3 * rho
        assert f.state.mass == pytest.approx(m0 / kept, rel=1e-12)
        assert f.state.inertia[2] == pytest.approx(0.4 * f.state.mass * f.shape.radius ** 2, rel=1e-12)
    vel = np.array([f.state.vel for f in frag])
    np.testing.assert_allclose((m[:, None] * vel).sum(0), M * v, rtol=1e-12, atol=1e-15)


def test_rmin_stops_crushing_and_abrasion_equal_radius_is_eligible():
    loadedGrain()
    c = add(BallastCrushEngine(ft0=1.0, rMin=1.0001 * R, iterPeriod=1))
    a = add(BallastAbrasionEngine(strength=1.0, rMin=1.0001 * R, iterPeriod=1))
    O.run(3, True)
    assert c.nCrushed == 0 and a.nAbraded == 0 and c.nChecks > 0 and a.nChecks > 0
    # the log sees the grain far above its strength, but none that can crush
    assert c.maxStressRatio > 1e3 and c.maxCrushableRatio == 0.0
    c.rMin = R          # r >= rMin degrades
    O.run(1, True)
    assert c.nCrushed == 1
    # fragments are below rMin: they never crush again, however low the strength
    frag = c.events[0]['newIds']
    O.run(5, True)
    assert c.nCrushed == 1 and all(O.bodies[i] is not None for i in frag)


def test_burst_of_crushing_keeps_kinetic_energy_bounded():
    """Energy balance: fragments inside their parents, moving with the parents' velocity, overlap their
    neighbours less than the parents did, so a burst adds no energy. Without damping, kinetic plus
    potential energy afterwards stays below the kinetic energy before, plus the Hertz elastic energy
    before (2/5 Fn uN per contact), plus the potential energy of the fragments as placed. Fragments
    0.3 % too large break this bound by 40 times the elastic energy."""
    H = packedBox()
    el = sum(0.4 * i.phys.normalForce.norm() * i.geom.penetrationDepth for i in O.interactions.all(True))
    ke0 = utils.kineticEnergy()
    O.engines[-1].damping = 0.0                       # no numerical damping to hide an explosion
    nGrains = sum(1 for b in O.bodies if b.dynamic)
    rSmall = min(b.shape.radius for b in O.bodies if b.dynamic)
    # rMin above the fragment size: one burst, no cascade
    crush = add(BallastCrushEngine(ft0=1e-3, pattern=6, rMin=0.5 * rSmall, iterPeriod=1))
    dt0 = O.dt
    O.run(1, True)
    assert crush.nCrushed >= 0.9 * nGrains           # a real burst: nearly every grain is loaded
    assert O.dt < dt0                                # eq. 5: smaller grains, smaller step
    budget = ke0 + el + potentialEnergy()
    excess = -budget
    for _ in range(50):
        O.run(20, True)
        excess = max(excess, utils.kineticEnergy() + potentialEnergy() - budget)
    assert excess <= 0.05 * el                      # 5 % of the elastic energy for integration error
    for b in O.bodies:
        if b is not None and b.dynamic:
            x = b.state.pos
            assert -1e-3 <= x[0] <= H + 1e-3 and -1e-3 <= x[1] <= H + 1e-3 and x[2] >= -1e-3


@pytest.mark.parametrize('maxPerCheck', [0, 1, 3])
def test_max_per_check_crushes_the_most_overloaded_grains_first(maxPerCheck):
    """Sequential crushing (maxPerCheck = N): of the grains over their strength, the N with the largest
    sigma_e / f_t crush at a check, the others wait; 0 crushes all of them (the paper). The strength is
    set so that about half the grains of a settled box are over it."""
    packedBox(n=3)
    ids = np.array([b.id for b in O.bodies if b.dynamic])
    radii = np.array([b.shape.radius for b in O.bodies if b.dynamic])
    probe = BallastCrushEngine(ft0=1.0, rMin=0.0)
    se, ft, _ = probe.evaluate(ids, radii)        # stress and strength at ft0 = 1 Pa m
    ratio = se / ft
    ft0 = float(np.median(ratio))                 # half the grains have sigma_e / f_t > 1 at this ft0
    over = ids[ratio > ft0]
    expected = over if maxPerCheck == 0 else ids[np.argsort(-ratio)[:maxPerCheck]]
    assert len(over) >= 5
    # a check at the next step, before anything moves much: rMin above the fragments, no cascade
    crush = add(BallastCrushEngine(ft0=ft0, rMin=0.5 * radii.min(), iterPeriod=1, maxPerCheck=maxPerCheck, nDo=1))
    O.dt = 1e-9
    O.run(1, True)
    assert sorted(e['id'] for e in crush.events) == sorted(expected.tolist())
    assert crush.nCrushed == len(expected)
