"""Density scaling that survives crushing (issue 25, item 2; docs/performance.md): with densityStep the
loading steps at densityStep, every grain, fragments and abraded grains included, has YADE's
State.densityScaling (own P-wave step / (densityStep / dtSafety))^2 capped at 1, the plate a factor too
(YADE's default -1 would turn its acceleration around), and the inertial number is reported at every
check. Without the fragments' factor the same run blew up (the sample 27 m high)."""
import math
import os

import numpy as np
import pytest

pytest.importorskip('yade')
from yade import O  # noqa: E402
from yade.wrapper import NewtonIntegrator, Sphere  # noqa: E402

from ballast.oedometer import Oedometer  # noqa: E402
from ballast.params import ParamError  # noqa: E402

STEP = 2e-6   # [s] 2.6 times the paper's step of this sample (0.8 x 0.01025 sqrt(2600 / 3e11) = 7.63e-7 s)
WEAK = dict(diameter=0.15, height=0.08, vMax=5, samples=1000, progress=60, f=20, ft0=5e5, strength=1.5e10)


@pytest.fixture(scope='module')
def run(tmp_path_factory):
    root = str(tmp_path_factory.mktemp('densityscaling'))
    exp = Oedometer(densityStep=STEP, results=root, runId='scaled', packingDir=os.path.join(root, 'packings'), **WEAK)
    return exp, exp.run(), root


def expectedFactors():
    """Each sphere's densityScaling by hand: its own P-wave step r sqrt(rho / E) with rho its mass over its
    volume, against densityStep / dtSafety."""
    bs = [b for b in O.bodies if b is not None and isinstance(b.shape, Sphere)]
    r = np.array([b.shape.radius for b in bs])
    rho = np.array([b.state.mass for b in bs]) / (4 / 3 * math.pi * r ** 3)
    own = r * np.sqrt(rho / np.array([b.material.young for b in bs]))
    return np.array([b.state.densityScaling for b in bs]), np.minimum(1.0, (own / (STEP / 0.8)) ** 2)


def test_the_run_warns_that_density_scaling_changes_the_avalanches(run):
    """Said when the run starts and kept in summary.json; a run without scaling has no warning."""
    exp, s, root = run
    assert len(s['warnings']) == 1 and s['warnings'][0].startswith('densityStep 2e-06: density scaling changes whether')
    assert 'avalanches' in s['warnings'][0]
    assert Oedometer(**WEAK).warnings() == []
    assert Oedometer(quasiStatic=1e-3, **WEAK).warnings()[0].startswith('quasiStatic 0.001: density scaling')


def test_every_grain_and_fragment_scaled_to_the_step(run):
    exp, s, _ = run
    assert s['nCrushed'] > 0 and s['nAbraded'] > 0  # fragments and shrunk grains exist
    assert next(e for e in O.engines if isinstance(e, NewtonIntegrator)).densityScaling
    assert O.dt == STEP and s['dtFinal'] == STEP  # the engines scale the grains, not the step
    got, want = expectedFactors()
    np.testing.assert_allclose(got, want, rtol=1e-12)
    plate = O.bodies[exp.loading.plate].state.densityScaling
    assert 0 < plate <= 1


def test_the_sample_stays_in_the_cylinder(run):
    _, s, _ = run
    assert s['nEscaped'] == 0 and 0 < s['deltaMax'] < 0.08  # the sample is 0.08 m high


def test_the_inertial_number_at_every_loaded_check(run):
    exp, s, _ = run
    import pandas as pd
    c = pd.read_csv(os.path.join(exp.out, 'checks.csv'))
    assert 'inertialNumber' in c and np.isfinite(c['inertialNumber']).sum() > 10
    info = s['inertialNumber']
    assert info['bound'] == 1e-3 and info['maxCrushing'] == pytest.approx(np.nanmax(c['inertialNumber']), rel=1e-5) \
        or info['maxAfterCrushing'] == pytest.approx(np.nanmax(c['inertialNumber']), rel=1e-5)
    assert info['exceeded'] == bool(np.nanmax(c['inertialNumber']) > 1e-3)
    # the probe's value now, by hand: |v| / h, mean diameter, density over the mass-weighted mean factor, F / area
    F, h = exp.loading.force(), exp.loading.top()
    if F >= 0.01 * exp.p['Fmax']:
        bs = [b for b in O.bodies if b is not None and isinstance(b.shape, Sphere) and b.dynamic]
        r = np.array([b.shape.radius for b in bs])
        factor, _ = expectedFactors()
        rho = 2600.0 * np.sum(r ** 3 / factor) / np.sum(r ** 3)
        I = abs(O.bodies[exp.loading.plate].state.vel[2]) / h * 2 * np.mean(r) * math.sqrt(rho / (F / (math.pi * 0.075 ** 2)))
        assert exp.probe.inertialNumber() == pytest.approx(I, rel=1e-9)


def test_the_scaling_survives_save_and_load(run):
    _, _, root = run
    got, _ = expectedFactors()
    path = os.path.join(root, 'again.yade.gz')
    O.save(path)
    O.load(path)
    newton = next(e for e in O.engines if isinstance(e, NewtonIntegrator))
    assert not newton.densityScaling  # YADE does not keep it: the guard's first step puts it back
    O.step()
    assert newton.densityScaling and O.dt == STEP
    guard = next(e for e in O.engines if e.label == 'densityScalingGuard')
    assert guard.dead  # asleep until the next save
    np.testing.assert_array_equal(expectedFactors()[0], got)


@pytest.mark.parametrize('values, words', [
    (dict(densityStep=5e-7), "below the paper's step"),
    (dict(densityStep=2e-6, timeStep='stiffness'), 'density scaling sets the step itself'),
    (dict(densityStep=-1.0), 'densityStep'),
])
def test_bad_density_steps_refused(values, words):
    with pytest.raises(ParamError, match='densityStep') as e:
        Oedometer(**dict(WEAK, **values))
    assert words in str(e.value)


def test_a_reopened_run_scales_at_once(run, tmp_path):
    exp, _, _ = run
    again = Oedometer.reopen(os.path.join(exp.out, 'state-end.yade.gz'), results=str(tmp_path), runId='again')
    assert next(e for e in O.engines if isinstance(e, NewtonIntegrator)).densityScaling  # before any step
    assert again.p['densityStep'] == STEP and O.dt == STEP


def test_growing_fragments_are_scaled_again(tmp_path):
    """keep='volume': fragments grow back to the parent's volume over growTime; each growth step rescales
    them (a larger grain needs less scaling), so the factors are the hand values at the end too."""
    exp = Oedometer(densityStep=STEP, keep='volume', results=str(tmp_path), runId='grow',
                    packingDir=os.path.join(str(tmp_path), 'packings'), **WEAK)
    s = exp.run()
    assert s['nCrushed'] > 0 and s['nEscaped'] == 0
    got, want = expectedFactors()
    np.testing.assert_allclose(got, want, rtol=1e-12)
