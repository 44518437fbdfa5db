"""The oedometer's stop conditions (issue 25, item 3): at stopAt load periods (0.5: the applied peak, what
Fig. 5 reads) and, with stopQuiet, once after the peak the applied load has fallen below stopQuiet Fmax
with no crush for quietTime; summary.json says where and why a run stopped."""
import os

import pytest

pytest.importorskip('yade')
from ballast.oedometer import Oedometer  # noqa: E402

F = 20.0   # [Hz]
SMALL = dict(diameter=0.15, height=0.08, vMax=5, samples=1000, progress=60, f=F, ft0=1e12, strength=1e15)
CHECK_EVERY = 200   # [steps] the load phase's end test runs every 200 steps


@pytest.fixture(scope='module')
def root(tmp_path_factory):
    return str(tmp_path_factory.mktemp('stops'))


def run(root, name, **kw):
    return Oedometer(results=os.path.join(root, name), runId=name, packingDir=os.path.join(root, 'packings'),
                     **dict(SMALL, **kw)).run()


def test_a_whole_cycle_by_default(root):
    s = run(root, 'cycle')
    assert s['stoppedBy'] == 'cycles' and s['cycles'] == 1


def test_stop_at_the_applied_peak(root):
    """stopAt 0.5: the loading ends at T/2 + 1.5 Tc (Tc = 1e-4 s), a step past the crushing check after the peak."""
    s = run(root, 'peak', stopAt=0.5)
    assert s['stoppedBy'] == 'stopAt'
    assert s['loadingTime'] == pytest.approx(0.5 / F + 1.5e-4, abs=2 * s['dtFinal'])


def test_stop_when_quiet_after_the_peak(root):
    """No grain crushes (ft0 1e12): after T/2 the applied load Fmax/2 (1 + cos 2 pi f (t - T/2)) falls below
    Fmax/2 at t = 3T/4; the test, every 200 steps, stops the run at the first check past it."""
    s = run(root, 'quiet', stopQuiet=0.5, quietTime=0.001)
    assert s['stoppedBy'] == 'quiet' and s['nCrushed'] == 0
    assert 0.75 / F <= s['loadingTime'] <= 0.75 / F + (CHECK_EVERY + 1) * s['dtFinal']
    assert s['appliedFinal'] < 0.5 * s['params']['Fmax']
