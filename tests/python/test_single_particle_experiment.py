"""ballast.experiments.single_particle: the test in YADE. A deterministic grain crushes at the closed-form
force of its criterion (three sizes, each criterion) quasi-statically; Weibull strengths of moduli 3 and
10 over 120 grains give back the modulus and the size law in their 95 % intervals; a grain that cannot
crush is reported so; the outputs and the command line running (its refusals: test_commandline.py)."""
import json
import math
import os
import shutil
import subprocess

import pandas as pd
import pytest

pytest.importorskip('yade')
from ballast.experiments.single_particle import SingleParticle  # noqa: E402
from ballast.experiments.single_particle.closedform import crushingForce  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SIZES = [0.022, 0.032, 0.044]   # [m] three grains
TOL_FORCE = 5e-3   # [-] measured against closed-form force: one step's rise (3e-4), the contact point r - u/2
#                    instead of r (overlap / 2r ~ 4e-4) and the grain's inertia (below 2e-3 at 0.002 m/s)
TOL_INERTIA = 1e-2  # [-] |F_top - F_bottom| / F at the crush: quasi-static
TOL_FORCE_SCALED = 1e-2  # [-] with densityStep 3 x the paper's step: 9e-4 a step's rise + the inertia (at 10 x: 1.4e-2
#                          and an inertia ratio of 2e-2: too heavy a grain for 0.002 m/s)


@pytest.mark.parametrize('criterion', ['vonMises', 'maxContactForce', 'majorPrincipal'])
def test_deterministic_grains_crush_at_the_closed_form_force(tmp_path, criterion):
    test = SingleParticle(diameters=SIZES, criterion=criterion, m=0.5, speed=0.002, results=str(tmp_path), progress=60)
    s = test.run()
    t = test.table()
    assert t.crushed.all() and s['nCrushed'] == 3
    for d, F in zip(t.diameter, t.force):
        assert F == pytest.approx(crushingForce(criterion, d / 2, 3.1e6, 0.5), rel=TOL_FORCE)
    assert s['closedFormErrorMax'] < TOL_FORCE and s['inertiaRatioMax'] < TOL_INERTIA
    # the criterion's stress at the crush is the strength f_t = ft0 / r^m to one step
    assert (t.criterionStress / t.strength - 1).abs().max() < 1e-3
    assert ((t.strength - 3.1e6 / (t.diameter / 2) ** 0.5).abs() / t.strength).max() < 1e-12


@pytest.mark.parametrize('k', [3.0, 10.0])
def test_weibull_strengths_give_back_the_modulus_and_the_size_law(tmp_path, k):
    test = SingleParticle(n=120, weibullModulus=k, seed=5, results=str(tmp_path), progress=60)
    s = test.run()
    assert s['nCrushed'] == 120
    law = s['sizeLawCriterion']   # the criterion's stress at the crush: ft0 r^-m w
    assert law['kLow'] < k < law['kHigh'] and law['bLow'] < 1.0 < law['bHigh'] and law['s0Low'] < 3.1e6 < law['s0High']
    assert s['sizeLawForceOverD2']['bLow'] < 1.0 < s['sizeLawForceOverD2']['bHigh']   # F/d^2 ~ r^-m too
    for name in ('strengths.csv', 'curves.csv', 'summary.json', 'weibull.png', 'size.png', 'state-end.yade.gz'):
        assert os.path.isfile(os.path.join(test.out, name)), name
    table = pd.read_csv(os.path.join(test.out, 'strengths.csv'))
    assert len(table) == 120   # written to 9 digits
    assert ((table.forceOverD2 / (table.force / table.diameter ** 2) - 1).abs() < 1e-8).all()
    assert s['cpuSecondsPerGrain'] > 0


def test_a_grain_that_cannot_crush_is_reported_at_max_strain(tmp_path):
    test = SingleParticle(diameters=[0.03, 0.04], ft0=1e12, maxStrain=0.002, results=str(tmp_path), progress=60)
    s = test.run()
    t = test.table()
    assert s['nCrushed'] == 0 and s['nNotCrushed'] == 2 and not t.crushed.any()
    assert (t.displacement >= 0.002 * t.diameter).all()


def test_reopened_read_only_the_test_gives_its_table_back(tmp_path):
    test = SingleParticle(diameters=SIZES, results=str(tmp_path), progress=60)
    test.run()
    again = SingleParticle.reopen(os.path.join(test.out, 'state-end.yade.gz'), readOnly=True)
    assert again.out is None
    pd.testing.assert_frame_equal(again.table(), test.table())


@pytest.mark.skipif(shutil.which('yade') is None, reason='needs yade')
def test_command_line_runs(tmp_path):
    """(Its refusals: test_commandline.py.)"""
    script = os.path.join(ROOT, 'scripts', 'single_particle.py')
    env = dict(os.environ, OMP_NUM_THREADS='1')
    ok = subprocess.run(['yade', '-n', '-x', script, '--n', '4', '--results', str(tmp_path), '--runId', 'cli'],
                        capture_output=True, text=True, timeout=300, env=env, cwd=str(tmp_path))
    assert ok.returncode == 0, ok.stdout[-2000:] + ok.stderr[-2000:]
    with open(tmp_path / 'cli' / 'summary.json') as fh:
        assert json.load(fh)['n'] == 4


def test_grains_side_by_side_never_touch_one_another(tmp_path):
    """Every interaction of the scene, at every step until the crushes, is between a grain and its own
    platens: pitch 1.5 dMax against platens 1.2 d wide."""
    from yade import O
    test = SingleParticle(n=12, weibullModulus=3, results=str(tmp_path), progress=60)
    test.prepare()
    t = test.tester
    own = {g: {top, bottom} for g, top, bottom in zip(t.grain, t.top, t.bottom)}
    seen = []

    def watch():
        pairs = [(i.id1, i.id2) for i in O.interactions if i.isReal]
        seen.append(len(pairs))
        for a, b in pairs:
            g, other = (a, b) if a in own else (b, a)
            assert g in own and other in own[g], (a, b)
    step = t.step
    t.step = lambda: (watch(), step())
    test.load()
    assert max(seen) == 2 * 12 and test.summary()['nCrushed'] == 12   # both platens of every grain, at first


def test_density_scaling_crushes_at_the_same_force_in_fewer_steps(tmp_path):
    """densityStep (the experiment base's, ballast.experiments.timestep): three times the paper's step; the
    platens are kinematic, the grain heavier, the test still quasi-static and at the closed-form force."""
    from yade import O
    from yade.wrapper import NewtonIntegrator, Sphere
    paper = 0.8 * 0.011 * (2600 / 3e11) ** 0.5   # dtSafety x PWaveTimeStep of the smallest grain [s]
    kw = dict(diameters=SIZES, m=0.5, speed=0.002, progress=60)
    plain = SingleParticle(results=str(tmp_path / 'plain'), **kw).run()
    test = SingleParticle(densityStep=3 * paper, results=str(tmp_path / 'scaled'), **kw)
    s = test.run()
    assert next(e for e in O.engines if isinstance(e, NewtonIntegrator)).densityScaling and O.dt == 3 * paper
    t = test.table()
    for d, F in zip(t.diameter, t.force):  # one step's rise is now 3 x 3e-4, the grain 9-16 times heavier
        assert F == pytest.approx(crushingForce('vonMises', d / 2, 3.1e6, 0.5), rel=TOL_FORCE_SCALED)
    assert s['inertiaRatioMax'] < TOL_INERTIA
    assert s['steps'] < 0.4 * plain['steps']    # 1/3 of the steps, give or take the last ones
    # every sphere, fragments included, scaled to its own step: (r sqrt(rho/E) / (densityStep / dtSafety))^2 <= 1
    for b in O.bodies:
        if b is not None and isinstance(b.shape, Sphere):
            rho = b.state.mass / (4 / 3 * 3.141592653589793 * b.shape.radius ** 3)
            want = min(1.0, (b.shape.radius * (rho / 3e11) ** 0.5 / (3 * paper / 0.8)) ** 2)
            assert b.state.densityScaling == pytest.approx(want, rel=1e-12)


def test_the_stiffness_step_crushes_at_the_same_force_in_fewer_steps(tmp_path):
    """timeStep (the experiment base's): YADE's GlobalStiffnessTimeStepper instead of eq. 5's step."""
    from yade import O
    kw = dict(diameters=SIZES, m=0.5, speed=0.002, progress=60)
    plain = SingleParticle(results=str(tmp_path / 'plain'), **kw).run()
    s = SingleParticle(timeStep='stiffness', results=str(tmp_path / 'stiffness'), **kw).run()
    assert O.dynDt and any(type(e).__name__ == 'GlobalStiffnessTimeStepper' for e in O.engines)
    assert s['closedFormErrorMax'] < TOL_FORCE and s['inertiaRatioMax'] < TOL_INERTIA
    assert s['steps'] < 0.8 * plain['steps']   # 1 301 against 2 201 on this machine's YADE


def test_density_scaling_and_the_stiffness_step_exclude_each_other():
    from ballast.params import ParamError
    with pytest.raises(ParamError, match='density scaling sets the step itself'):
        SingleParticle(diameters=SIZES, timeStep='stiffness', densityStep=1e-5)


def test_a_clump_between_the_platens_crushes_and_splits(tmp_path):
    """grain 'clump': one grain of r_eq 15 mm on its flat side, ft0 small; it crushes and the clump splits into pieces
    of its members (the crush engine's event: two planes under the platens' uniaxial load, 2 to 4 pieces)."""
    from yade import O
    from ballast.engines import BallastCrushEngine
    test = SingleParticle(grain='clump', clumpTemplates=2, diameters=[0.03], ft0=3e5, m=0.5, speed=0.002,
                          results=str(tmp_path), progress=60)
    test.prepare()
    # the clump's height between the platens, from the platens' inner faces (boxes of half-thickness t)
    top, bottom = O.bodies[test.tester.top[0]], O.bodies[test.tester.bottom[0]]
    h = (top.state.pos[2] - top.shape.extents[2]) - (bottom.state.pos[2] + bottom.shape.extents[2])
    assert 0.5 * 0.03 < h < 0.03    # a flat grain lying on its flat side: lower than its volume-equivalent sphere
    s = test.load()
    t = test.table()
    # the crush at the closed form for any shape (docs/calibration.md): sigma_zz = F h / V, uniaxial by the torque
    # balance, von Mises = sigma_zz reaches ft0 / r_eq^m at F = ft0 r_eq^-m V / h; within the grain's inertia
    # (inertiaRatioMax, 2 % at this speed) and the contact points' travel
    V = 4 / 3 * math.pi * 0.015 ** 3
    assert t.expectedForce[0] == pytest.approx(3e5 / 0.015 ** 0.5 * V / h, rel=1e-9)
    assert t.force[0] == pytest.approx(t.expectedForce[0], rel=0.03)
    assert s['closedFormErrorMax'] == pytest.approx(abs(t.force[0] / t.expectedForce[0] - 1), rel=1e-9)
    assert s['nCrushed'] == 1 and t.crushed.all() and t.diameter.tolist() == [0.03]
    # the force is what the clump carried: both platens the same to the grain's inertia, F/d^2 from d = 2 r_eq
    assert t.force[0] > 0 and abs(t.forceBottom[0] / t.force[0] - 1) < 0.05
    assert t.forceOverD2[0] == pytest.approx(t.force[0] / 0.03 ** 2, rel=1e-12)
    e = next(e for e in O.engines if isinstance(e, BallastCrushEngine)).events[0]
    assert e['id'] == test.tester.grain[0] and 2 <= len(e['newIds']) <= 4
    assert e['strength'] == pytest.approx(3e5 / 0.015 ** 0.5, rel=1e-12)   # f_t0 / r_eq^m with r_eq the clump's


def test_a_clump_from_a_template_file_lies_flat_and_crushes_at_its_closed_form(tmp_path):
    """clumpFile: three spheres of radius 1 at the corners of a triangle of side 1.2 (in the file's units, tilted out of
    every axis plane). The sample's template is the file's in its principal frame at r_eq 1 (the triangle's normal
    along z), so the grain lies flat between the platens, standing h = 2 of its members' radius high, and crushes at
    F = ft0 r_eq^-m V / h as a built clump does."""
    import numpy as np
    from yade import O, Quaternion, Vector3
    from ballast.experiments.clumpsample import ClumpSample
    from ballast.grainkinds.clumpshapes import principalTemplate
    from ballast.templatefile import readTemplates
    turn = Quaternion(Vector3(1, 2, 3).normalized(), 0.7)
    corners = [turn * Vector3(1.2 * math.cos(a), 1.2 * math.sin(a), 0) / math.sqrt(3) for a in (0, 2.094395, 4.188790)]
    f = tmp_path / 'triangle.csv'
    f.write_text('template,x,y,z,r\n' + ''.join('tri,%r,%r,%r,1\n' % tuple(c) for c in corners))
    test = SingleParticle(grain='clump', clumpFile=str(f), diameters=[0.03], ft0=3e5, m=0.5, speed=0.002,
                          results=str(tmp_path), progress=60, seed=4)
    test.prepare()
    (c, r, v), = ClumpSample.current().templates
    _, c0, r0 = readTemplates(str(f))[0]
    want = principalTemplate(c0, r0, seed=[4, 0])
    assert np.array_equal(c, want[0]) and np.array_equal(r, want[1]) and v == want[2]
    top, bottom = O.bodies[test.tester.top[0]], O.bodies[test.tester.bottom[0]]
    h = (top.state.pos[2] - top.shape.extents[2]) - (bottom.state.pos[2] + bottom.shape.extents[2])
    assert h == pytest.approx(2 * r[0] * 0.015, rel=1e-6)   # flat: the three members touch both platens
    s = test.load()
    t = test.table()
    V = 4 / 3 * math.pi * 0.015 ** 3
    assert t.expectedForce[0] == pytest.approx(3e5 / 0.015 ** 0.5 * V / h, rel=1e-9)
    assert t.force[0] == pytest.approx(t.expectedForce[0], rel=0.03) and s['nCrushed'] == 1
    assert s['nUnloaded'] == 0 and s['warnings'] == []


def test_grains_that_never_carried_load_are_counted_and_said():
    """A grain not crushed whose top-platen force stayed below a tenth of its closed-form force (it slid or tipped out
    from between the platens) is counted; one that carried load without crushing (maxStrain) or crushed is not."""
    from types import SimpleNamespace
    from ballast.experiments.single_particle import outputs
    s = pd.DataFrame({'grain': [0, 1, 2, 3], 'crushed': [False, False, True, False],
                      'expectedForce': [1000.0, 1000.0, 1000.0, 1000.0]})
    curves = [(0, 0.1, 0.0, 50.0), (0, 0.2, 0.0, 99.0),      # at most 9.9 %: unloaded
              (1, 0.1, 0.0, 20.0), (1, 0.2, 0.0, 400.0),     # 40 %: it carried load (stopped at maxStrain)
              (2, 0.1, 0.0, 1.0)]                            # crushed: not counted whatever its curve
    exp = SimpleNamespace(tester=SimpleNamespace(curves=curves))   # grain 3: no curve at all, never touched
    assert outputs.unloadedGrains(exp, s) == [0, 3]
