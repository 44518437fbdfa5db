"""Tests of py/ballast/engines/base.py inside YADE, against values computed by hand: what every
ballast engine shares. Parameters checked when built and when set later, outputs read-only, the
periodic settings and the crushing period, a new scene read afresh, and the state saved with the
scene (a save/load round trip, restored at the next check).
Runs in Debian's /usr/bin/python3 with YADE imported as a module (see conftest.py)."""
import builtins
import math

import pytest
from yade import O
from yade.wrapper import PyRunner

from ballast.engines import BallastAbrasionEngine, BallastCrushEngine, restore
from ballast.scenes import squeezedStress
from engine_scenes import OVERLAP, R, add, loadedGrain


def test_a_new_scene_at_the_same_step_is_read_afresh():
    """Two scenes one after the other (O.reset()), with the same bodies and step number: what the
    engine read from the first must not be taken for the second. The second grain is squeezed twice
    as hard, so it crushes where the first did not."""
    g, w1, F, arm, uN = loadedGrain()
    ft = squeezedStress(F, R, arm) / 0.99            # sigma_e = 0.99 f_t: no crushing
    c1 = add(BallastCrushEngine(ft0=ft * R, iterPeriod=1))
    O.run(1, True)
    assert c1.nCrushed == 0 and c1.maxStressRatio == pytest.approx(0.99, rel=1e-6)
    g, w1, F2, arm2, uN2 = loadedGrain(overlap=OVERLAP * 2 ** (2 / 3))  # Hertz: twice the force
    assert F2 == pytest.approx(2 * F, rel=2e-2)
    c2 = add(BallastCrushEngine(ft0=ft * R, iterPeriod=1))
    O.run(1, True)                                    # the same step number as c1's check
    assert c2.nCrushed == 1 and c2.events[0]['value'] == pytest.approx(squeezedStress(F2, R, arm2), rel=2e-2)


def test_crushing_period_is_honoured():
    loadedGrain()
    dt = O.dt
    Tc = 7.3 * dt
    c = add(BallastCrushEngine(ft0=1e12, virtPeriod=Tc))
    e = add(BallastCrushEngine(ft0=1e12, iterPeriod=1))
    n = 200
    t0 = O.time
    O.run(n, True)
    # PeriodicEngine's rule, by hand: fire when time - last >= Tc (last starts at 0); a first call that
    # does not fire only sets last = time. Time advances by dt after the engines.
    t, last, fired, first = t0, 0.0, 0, True
    for _ in range(n):
        if t - last >= Tc:
            fired, last = fired + 1, t
        elif first:
            last = t
        first = False
        t += dt
    assert c.nChecks == fired and fired > 20
    assert e.nChecks == n


@pytest.mark.parametrize('cls,kw,words', [
    (BallastCrushEngine, dict(ft0=-1.0), ['BallastCrushEngine', 'ft0', '-1', '> 0']),
    (BallastCrushEngine, dict(ft0=float('nan')), ['ft0', 'nan']),
    (BallastCrushEngine, dict(ft0=1.0, pattern=5), ['pattern', '5']),
    (BallastCrushEngine, dict(ft0=1.0, pattern='hex'), ['pattern', 'hex']),
    (BallastCrushEngine, dict(ft0=1.0, rMin=-0.1), ['rMin', '-0.1']),
    (BallastCrushEngine, dict(ft0=1.0, m=-1), ['m', '-1']),
    (BallastCrushEngine, dict(ft0='1e5'), ['ft0', "'1e5'"]),
    (BallastCrushEngine, dict(), ['ft0', 'required']),
    (BallastCrushEngine, dict(ft0=1.0, ft=2.0), ['unknown', 'ft']),
    (BallastAbrasionEngine, dict(strength=1.0, gamma=1.0), ['BallastAbrasionEngine', 'gamma', '1.0', '[0.5, 1)']),
    # issue 15's audit: accepted and silently wrong, or failing at the first event
    (BallastCrushEngine, dict(ft0=1.0, iterPeriod=-5), ['iterPeriod', '-5', '[0, 2^63 - 1]']),
    (BallastCrushEngine, dict(ft0=1.0, virtPeriod=float('nan')), ['virtPeriod', 'nan', '>= 0']),
    (BallastCrushEngine, dict(ft0=1.0, virtPeriod=-1.0), ['virtPeriod', '-1.0']),
    (BallastCrushEngine, dict(ft0=1.0, iterPeriod=0, virtPeriod=0.0), ['iterPeriod', 'never check']),
    (BallastCrushEngine, dict(ft0=1.0, iterPeriod='x'), ['iterPeriod', "'x'"]),
    (BallastCrushEngine, dict(ft0=1.0, seed=2 ** 64), ['seed', '2^63 - 1']),
    (BallastCrushEngine, dict(ft0=1.0, m=1e5), ['m', '100000.0', '[0, 3]']),
    (BallastCrushEngine, dict(ft0=1.0, mask=2 ** 40), ['mask', '2^31 - 1']),
    (BallastAbrasionEngine, dict(strength=1.0, gamma=1e-300), ['gamma', '1e-300', '[0.5, 1)']),
    (BallastAbrasionEngine, dict(strength=1.0, gamma=0.0), ['gamma', '0.0']),
    (BallastAbrasionEngine, dict(strength=0.0), ['strength', '0.0']),
    (BallastAbrasionEngine, dict(strength=1.0, adjustDt=1), ['adjustDt', '0 or 1']),
    (BallastAbrasionEngine, dict(strength=1.0, prefilter='yes'), ['prefilter', "'yes'", '0 or 1']),
    (BallastAbrasionEngine, dict(strength=1.0, verifyPeriod=0), ['verifyPeriod', '0', '>= 1']),
    (BallastAbrasionEngine, dict(strength=1.0, maxCandidates=1.5), ['maxCandidates', '1.5', '[0, 1]']),
])
def test_bad_parameters_raise_naming_engine_parameter_value(cls, kw, words):
    with pytest.raises((ValueError, TypeError)) as e:
        cls(**kw)
    for w in words:
        assert w in str(e.value), (w, str(e.value))


def test_bad_parameter_set_later_raises_and_keeps_old_value():
    c = BallastCrushEngine(ft0=1.0)
    with pytest.raises(ValueError, match='ft0 = 0'):
        c.ft0 = 0
    assert c.ft0 == 1.0
    with pytest.raises(AttributeError, match='output'):
        c.nCrushed = 3
    # periodic settings are checked on every set too; the last period cannot go to 0
    assert c.iterPeriod == 1  # no period given: a check every step
    with pytest.raises(ValueError, match='virtPeriod = -1'):
        c.virtPeriod = -1
    with pytest.raises(ValueError, match='never check'):
        c.iterPeriod = 0
    c.virtPeriod = 1e-4
    c.iterPeriod = 0       # allowed now: the engine checks by time
    assert (c.iterPeriod, c.virtPeriod) == (0, 1e-4)
    # a misspelt name is refused, not silently added
    with pytest.raises(AttributeError, match="no attribute 'ft0x'"):
        c.ft0x = 1
    assert not hasattr(c, 'ft0x')


def test_outputs_cannot_be_changed_from_outside():
    g, w1, F, arm, uN = loadedGrain()
    crush = add(BallastCrushEngine(ft0=squeezedStress(F, R, arm) * R / 1.5, iterPeriod=1, label='crush'))
    O.run(2, True)
    assert crush.nCrushed == 1
    crush.events.append({'kind': 'fake'})
    crush.events[0]['radius'] = -1.0
    crush.events[0]['newIds'].append(10 ** 6)
    assert len(crush.events) == 1 and crush.events[0]['radius'] == R and 10 ** 6 not in crush.events[0]['newIds']


def test_save_load_round_trip(tmp_path):
    g, w1, F, arm, uN = loadedGrain()
    p0 = 3 * F / (2 * math.pi * R * uN)
    add(BallastAbrasionEngine(strength=p0 / 1.01, gamma=0.999, iterPeriod=1, label='abrasion'))
    add(BallastCrushEngine(ft0=squeezedStress(F, R, arm) * R / 1.5, pattern=14, seed=9, iterPeriod=1,
                           label='crush'))
    O.run(3, True)
    assert crush.nCrushed == 1 and abrasion.nAbraded >= 1
    before = {n: dict(e.state()) for n, e in (('crush', crush), ('abrasion', abrasion))}
    f = str(tmp_path / 'scene.yade.gz')
    O.save(f)
    O.load(f)
    assert type(O.engines[-1]) is PyRunner          # what YADE itself gives back
    back = restore()
    assert sorted(type(e).__name__ for e in back) == ['BallastAbrasionEngine', 'BallastCrushEngine']
    assert builtins.crush is O.engines[-1] and type(crush) is BallastCrushEngine
    for name, e in (('crush', crush), ('abrasion', abrasion)):
        s = e.state()
        assert s['params'] == before[name]['params'] and s['outputs'] == before[name]['outputs']
    assert crush.iterPeriod == 1 and crush.label == 'crush' and crush.pattern == 14
    n = crush.nChecks
    O.run(3, True)
    assert crush.nChecks == n + 3
    # a second round trip after checks without events: the events and the per-check outputs survive
    before = {n: dict(e.state()) for n, e in (('crush', crush), ('abrasion', abrasion))}
    assert before['crush']['outputs']['events'] and before['crush']['outputs']['nChecks'] == 6
    O.save(f)
    O.load(f)
    restore()
    for name, e in (('crush', crush), ('abrasion', abrasion)):
        assert e.state()['outputs'] == before[name]['outputs']


def test_loaded_engine_restores_itself_at_its_next_check(tmp_path):
    loadedGrain()
    add(BallastCrushEngine(ft0=1e12, iterPeriod=1, label='crush'))
    O.run(2, True)
    f = str(tmp_path / 's.yade.gz')
    O.save(f)
    O.load(f)
    O.run(2, True)
    assert type(O.engines[-1]) is BallastCrushEngine and O.engines[-1].nChecks == 4
    assert builtins.crush is O.engines[-1]


def test_resize_grain_goes_through_the_kind_and_updates_the_table():
    """resizeGrain: the grain kind's Resized (r, gamma r, 4/3 pi r^3, m, gamma^3 m) and the table's radius."""
    from ballast import harvest
    from ballast.engines.base import resizeGrain
    g, w1, F, arm, uN = loadedGrain()
    tab = harvest.grains()
    m = O.bodies[g].state.mass
    rs = resizeGrain(tab, g, 0.9)
    assert rs.radiusBefore == R and rs.radiusAfter == 0.9 * R == O.bodies[g].shape.radius
    assert rs.volumeBefore == pytest.approx(4 / 3 * math.pi * R ** 3, rel=1e-15)
    assert rs.massBefore == m and rs.massAfter == pytest.approx(0.9 ** 3 * m, rel=1e-14)
    assert tab.radii.tolist() == [0.9 * R] and tab.radiusById[g] == 0.9 * R


def test_an_engine_built_before_its_scene_runs_in_it():
    """As YADE's own engines: built, then O.reset() and the scene built (packedBox resets), then put in O.engines:
    the scene adopts them at their first call; they check, and their state goes with the scene's saves."""
    from engine_scenes import packedBox
    crush = BallastCrushEngine(ft0=1e9, iterPeriod=1)
    abrasion = BallastAbrasionEngine(strength=1e3, iterPeriod=1)   # far below any contact's Hertz pressure
    packedBox(n=3)
    O.engines = O.engines + [crush, abrasion]
    O.run(10, True)
    assert crush.nChecks == 10 and crush.nCrushed == 0
    assert abrasion.nAbraded > 0
    n = abrasion.nAbraded
    O.saveTmp('built-before')
    O.loadTmp('built-before')
    O.run(1, True)
    back = [e for e in O.engines if isinstance(e, BallastAbrasionEngine)]
    assert len(back) == 1 and back[0].nChecks == 11 and back[0].nAbraded >= n


def test_yade_timing_counts_the_engines_and_resets_them():
    """yade.timing.reset() sets every engine's execTime and execCount to 0 (it failed on ours); with O.timingEnabled
    each call of an engine is counted: iterPeriod 1 over n steps, n calls."""
    from yade import timing
    loadedGrain()
    c = add(BallastCrushEngine(ft0=1e12, iterPeriod=1))
    a = add(BallastAbrasionEngine(strength=1e12, iterPeriod=1))
    O.timingEnabled = True
    try:
        O.run(5, True)
        assert c.execCount == 5 and c.execTime > 0
        timing.reset()
        assert (c.execCount, c.execTime, a.execCount, a.execTime) == (0, 0, 0, 0)
        O.run(7, True)
        assert c.execCount == 7 and a.execCount == 7
    finally:
        O.timingEnabled = False
