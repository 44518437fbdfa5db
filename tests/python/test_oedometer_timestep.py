"""The oedometer's time step choice (issue 25, item 1): 'pwave' (eq. 5, the paper's) or 'stiffness' (YADE's
GlobalStiffnessTimeStepper with the safety dtSafety). With the stiffer steel the P-wave step of the
smallest grain is the binding one; the stiffness-based step is larger (fewer steps), and the plate's
force still follows eq. 8."""
import os

import numpy as np
import pytest

pytest.importorskip('yade')
from ballast.oedometer import Oedometer  # noqa: E402
from ballast.oedometer.loadcurve import eq8  # noqa: E402

F, FMAX = 20.0, 1.5e6   # [Hz], [N]
SMALL = dict(diameter=0.15, height=0.08, vMax=5, samples=1000, progress=60, f=F, ft0=1e12, strength=1e15)
TOL_FORCE_RMS = 0.03    # [-] of Fmax: the grains' force on the plate against eq. 8 (as test_oedometer_experiment)


@pytest.fixture(scope='module')
def runs(tmp_path_factory):
    root = str(tmp_path_factory.mktemp('timestep'))
    out = {}
    for mode in ('pwave', 'stiffness'):
        run = Oedometer(timeStep=mode, results=os.path.join(root, mode), runId=mode,
                        packingDir=os.path.join(root, 'packings'), **SMALL)
        out[mode] = (run, run.run())
    return out


def test_stiffness_mode_runs_yades_time_stepper(runs):
    from yade import O
    run, s = runs['stiffness']
    steppers = [e for e in O.engines if type(e).__name__ == 'GlobalStiffnessTimeStepper']
    assert len(steppers) == 1 and steppers[0].timestepSafetyCoefficient == pytest.approx(0.8) and O.dynDt


def test_stiffness_step_is_larger_and_the_force_still_follows_eq8(runs):
    sp, ss = runs['pwave'][1], runs['stiffness'][1]
    assert ss['stepsByPhase']['load'] < sp['stepsByPhase']['load']
    run = runs['stiffness'][0]
    a = np.loadtxt(os.path.join(run.out, 'fd.csv'), delimiter=',', skiprows=1)
    loaded = a[:, 0] > 0.05 / F
    rms = np.sqrt(np.mean((a[loaded, 1] - eq8(FMAX, F, a[loaded, 0])) ** 2))
    assert rms <= TOL_FORCE_RMS * FMAX
