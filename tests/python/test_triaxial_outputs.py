"""ballast.experiments.triaxial.outputs: with cycle jumping, cycles.csv extrapolates the permanent strains over the
jumped cycles as it does the settlement, checked on an exact log law by hand (no simulation)."""
import math

import numpy as np
import pytest

pytest.importorskip('yade')
from ballast.experiments.triaxial import outputs  # noqa: E402
from ballast.experiments.triaxial.recorder import Recorder  # noqa: E402


class Exp:
    """What cycleTable reads of an experiment: six simulated cycles, the last numbered 20 (14 jumped before it), whose
    strains follow e = a + b ln n in the simulated count n exactly."""
    class recorder:
        cycles = []
    class jumper:   # noqa: E301
        jumped, jumps = 14, [{}]
    stepChoice = None


def test_the_strains_of_the_jumped_cycles_are_extrapolated_by_their_log_law():
    rows = []
    for n, N in enumerate([1, 2, 3, 4, 5, 20], start=1):
        row = dict.fromkeys(Recorder.CYCLE_COLUMNS, 0.0)
        row.update(cycle=N, settlement=1e-4 * math.log(n), axialStrain=0.01 + 0.002 * math.log(n),
                   volumetricStrain=-0.003 + 0.001 * math.log(n))
        rows.append([row[k] for k in Recorder.CYCLE_COLUMNS])
    Exp.recorder.cycles = rows
    frame = outputs.cycleTable(Exp)
    np.testing.assert_allclose(frame.axialStrainJumped[:5], 0, atol=1e-15)
    assert frame.axialStrainJumped.iloc[-1] == pytest.approx(0.002 * math.log(20 / 6), rel=1e-9)
    assert frame.volumetricStrainJumped.iloc[-1] == pytest.approx(0.001 * math.log(20 / 6), rel=1e-9)
    assert frame.settlementJumped.iloc[-1] == pytest.approx(1e-4 * math.log(20 / 6), rel=1e-9)
    assert 'axialStrainJumped' not in outputs.cycleTable(type('NoJump', (Exp,), {'jumper': None}))
