"""Cycle jumping in the oedometer (docs/cycles.md) on the small packing of test_oedometer_experiment.py between
Fmax and 0.2 Fmax at 20 Hz, with ft0 set so that the most loaded grain peaks at s = 0.6 of its strength (the strong
run's largest ratio scales with 1/ft0 while nothing crushes) and fatigue of exponent 4: it loses (1 - 0.6) 0.6^4 =
0.052 a cycle and survives floor(0.4 / 0.052) = 7 peaks, so it crushes in a dozen cycles (cycle 13 directly). With
jumping the cycles are numbered with the jumped ones, every jump is recorded, and no jump steps over the first
crush; a run whose jumps are never allowed is the run without jumping, bit for bit."""
import os

import numpy as np
import pandas as pd
import pytest

pytest.importorskip('yade')
from ballast.oedometer import Oedometer  # noqa: E402
from ballast.params import ParamError  # noqa: E402
from ballast.experiments.cyclic import COLUMNS as CYCLE_COLUMNS  # noqa: E402
from test_oedometer_experiment import F_STRONG, FMAX, SMALL  # noqa: E402

FATIGUE = dict(f=F_STRONG, strength=1e15, Fmin=0.2 * FMAX, fatigue=True, fatigueExponent=4, fatigueEndurance=0.3,
               fatigueHysteresis=0.05)
JUMP = dict(jump=True, jumpWindow=3, jumpMargin=0, jumpMaxDamage=0.5, jumpSteady=1.0)
PEAK = 0.6   # [-] the largest stress ratio of the first cycle


@pytest.fixture(scope='module')
def root(tmp_path_factory):
    return str(tmp_path_factory.mktemp('oedometer-jump'))


@pytest.fixture(scope='module')
def ft0(root):
    """ft0 [Pa m] that puts the most loaded grain of the first cycle at PEAK."""
    run = Oedometer(f=F_STRONG, ft0=1e12, strength=1e15, results=root, runId='strong',
                    packingDir=os.path.join(root, 'packings'), **SMALL)
    run.run()
    smax = pd.read_csv(os.path.join(run.out, 'checks.csv')).iloc[:, 3].max()
    return 1e12 * smax / PEAK


def test_jumping_numbers_the_cycles_and_never_steps_over_the_first_crush(root, ft0, capsys):
    run = Oedometer(ft0=ft0, cycles=14, results=root, runId='jump', packingDir=os.path.join(root, 'packings'),
                    **dict(SMALL, progress=1e-6), **FATIGUE, **JUMP)
    s = run.run()
    lines = [line for line in capsys.readouterr().out.splitlines() if '] load ' in line]
    # how much is simulated is not known ahead: no share of the loading nor time left, the cycle count instead
    assert lines and all('ETA' not in line and '% of' not in line and ' cycle ' in line for line in lines)
    cyc = pd.read_csv(os.path.join(run.out, 'cycles.csv'))
    jumps = pd.read_csv(os.path.join(run.out, 'jumps.csv'))
    assert s['cycles'] == 14 and cyc.cycle.iloc[-1] == 14 and s['jumps'] == len(jumps) >= 1
    assert s['cyclesSimulated'] == len(cyc) and s['cyclesSimulated'] + s['cyclesJumped'] == 14
    assert np.array_equal(cyc.cycle, np.arange(1, len(cyc) + 1) + cyc.jumped)
    assert list(cyc.cycle[:4]) == [1, 2, 3, 4]                        # the window's cycles, simulated
    first = int(cyc.cycle[cyc.crushes > 0].iloc[0])                  # the first crush, a fatigue crush
    assert s['nFatigueCrushed'] == s['nCrushed'] >= 1
    for _, e in jumps.iterrows():                                      # each jump ends before the cycle it fails in
        assert e.to + JUMP['jumpMargin'] + 1 < first or e.cycle >= first
    for name in list(jumps.stateBefore) + list(jumps.stateAfter):
        assert os.path.isfile(os.path.join(run.out, name))


@pytest.fixture(scope='module')
def off(root, ft0):
    """Five cycles without jumping."""
    run = Oedometer(ft0=ft0, cycles=5, results=root, runId='off', packingDir=os.path.join(root, 'packings'),
                    **SMALL, **FATIGUE)
    run.run()
    return run.out


def files(folder):
    out = {f: open(os.path.join(folder, f)).read() for f in ('fd.csv', 'checks.csv', 'events.csv')}
    # the shared columns but the process's CPU (the run with jumping on also has jumped, settlementJumped)
    out['cycles'] = pd.read_csv(os.path.join(folder, 'cycles.csv'))[[c for c in CYCLE_COLUMNS if c != 'cpuSeconds']]
    return out


def test_a_run_whose_jumps_are_never_allowed_is_the_run_without_jumping(root, ft0, off):
    run = Oedometer(ft0=ft0, cycles=5, results=root, runId='never', packingDir=os.path.join(root, 'packings'),
                    **SMALL, **FATIGUE, **dict(JUMP, jumpMaxDamage=1e-12))
    s = run.run()
    assert s['jumps'] == 0 and s['cyclesJumped'] == 0
    out = {'off': files(off), 'never': files(run.out)}
    assert out['off']['cycles'].maxDamage.iloc[-1] > 0
    for f in ('fd.csv', 'checks.csv', 'events.csv'):
        assert out['off'][f] == out['never'][f], f
    pd.testing.assert_frame_equal(out['off']['cycles'], out['never']['cycles'], check_exact=True)


def test_a_run_reopened_with_jumping_jumps_and_counts_on(root, off):
    run = Oedometer.reopen(os.path.join(off, 'state-end.yade.gz'), results=root, runId='reopened', **JUMP)
    s = run.load(9)
    cyc = pd.read_csv(os.path.join(run.out, 'cycles.csv'))
    assert s['cycles'] == 14 and cyc.cycle.iloc[-1] == 14 and s['jumps'] >= 1 and cyc.jumped.iloc[-1] > 0
    assert list(cyc.cycle[:5]) == [1, 2, 3, 4, 5]


def test_jumping_needs_fatigue():
    with pytest.raises(ParamError, match='jump = True is not allowed: cycle jumping advances fatigue damage'):
        Oedometer(jump=True, **SMALL)
