"""Tests of py/ballast/engines/fatigue.py inside YADE, against values computed by hand: FatigueState
through BallastCrushEngine(fatigue=True). Damage per load cycle and the cycle a grain crushes in, no
damage below the endurance ratio, none kept without fatigue, and the damage kept over save and load.
Runs in Debian's /usr/bin/python3 with YADE imported as a module (see conftest.py)."""
import builtins
import math

import numpy as np
import pytest
from yade import O

from ballast.engines import BallastCrushEngine, restore
from ballast.scenes import grainBetweenWalls
from engine_scenes import OVERLAP, R, add


PER_CYCLE = 50  # checks per load cycle in the fatigue tests (one per step)


def cyclicRatio(monkeypatch, sPeak, ft):
    """Makes every grain's fabric stress uniaxial with von Mises stress s f_t, s = sPeak (1 - cos 2 pi k /
    PER_CYCLE) / 2 at step k: the stress ratio a grain sees under a cyclic load, exactly."""
    from ballast import harvest

    def stresses(ids):
        s = sPeak * (1 - math.cos(2 * math.pi * O.iter / PER_CYCLE)) / 2
        out = np.zeros((len(ids), 3, 3))
        out[:, 2, 2] = -s * ft
        return out
    monkeypatch.setattr(harvest, 'stresses', stresses)


def fatigueGrain(monkeypatch, sPeak=0.6, **kw):
    g, _, _ = grainBetweenWalls(r=R, overlap=OVERLAP)
    O.dt = 1e-5
    ft0 = 2e5
    cyclicRatio(monkeypatch, sPeak, ft0 / R)
    return g, add(BallastCrushEngine(ft0=ft0, fatigue=True, fatigueExponent=8, fatigueEndurance=0.5,
                                     fatigueHysteresis=0.05, iterPeriod=1, label='crush', **kw))


def test_fatigue_crushes_a_grain_at_a_constant_ratio_in_the_cycle_worked_out_by_hand(monkeypatch):
    """s_p = 0.6 < 1, b = 8: each cycle's peak takes (1 - 0.6) 0.6^8 = 0.0067185 off the strength; the grain
    crushes once s > 1 - D, i.e. after more than N_f = 0.6^-8 = 59.54 peaks: 60 peaks, so in load cycle 61."""
    g, crush = fatigueGrain(monkeypatch)
    O.run(60 * PER_CYCLE, True)
    assert crush.nCrushed == 0 and O.bodies[g] is not None
    D, extreme, rising, peaks = crush.fatigueState([g])[0]
    assert peaks == 60 and D == pytest.approx(60 * 0.4 * 0.6 ** 8, rel=1e-12)
    assert crush.maxDamage == D
    O.run(PER_CYCLE, True)
    assert crush.nCrushed == 1 and O.bodies[g] is None and crush.nFatigueCrushed == 1
    e = crush.events[0]
    assert 60 * PER_CYCLE <= e['iter'] < 61 * PER_CYCLE            # in cycle 61
    ft = 2e5 / R
    assert e['strength'] == pytest.approx(ft * (1 - D), rel=1e-12)  # the damaged strength
    assert e['value'] / ft <= 0.6 + 1e-12 and e['value'] > e['strength']
    # the fragments start undamaged
    frag = crush.fatigueState(e['newIds'])
    assert frag.shape == (6, 4) and np.all(frag[:, 0] == 0) and np.all(frag[:, 3] <= 1)


def test_fatigue_below_the_endurance_ratio_does_no_damage(monkeypatch):
    g, crush = fatigueGrain(monkeypatch, sPeak=0.45)
    O.run(30 * PER_CYCLE, True)
    assert crush.nCrushed == 0 and crush.maxDamage == 0.0 and crush.fatigueState([g])[0, 3] == 0


def test_fatigue_off_is_the_paper(monkeypatch):
    """Without fatigue a grain at s = 0.6 never crushes and no state is kept."""
    g, _, _ = grainBetweenWalls(r=R, overlap=OVERLAP)
    cyclicRatio(monkeypatch, 0.6, 2e5 / R)
    crush = add(BallastCrushEngine(ft0=2e5, iterPeriod=1, label='crush'))
    O.run(30 * PER_CYCLE, True)
    assert crush.nCrushed == 0 and crush.fatigueState().shape == (0, 4)


def test_fatigue_damage_survives_save_and_load(monkeypatch, tmp_path):
    """Saved after 10 cycles and loaded: the damage is restored bitwise and the grain still crushes
    in cycle 61."""
    g, crush = fatigueGrain(monkeypatch)
    O.run(10 * PER_CYCLE + 7, True)
    before = crush.fatigueState()
    f = str(tmp_path / 'fatigue.yade.gz')
    O.save(f)
    O.load(f)
    restore()
    assert type(builtins.crush) is BallastCrushEngine and builtins.crush.fatigue
    np.testing.assert_array_equal(builtins.crush.fatigueState(), before)
    assert builtins.crush.fatigueState([g])[0, 3] == 10
    O.run(51 * PER_CYCLE - 7, True)
    e = builtins.crush.events
    assert len(e) == 1 and 60 * PER_CYCLE <= e[0]['iter'] < 61 * PER_CYCLE
