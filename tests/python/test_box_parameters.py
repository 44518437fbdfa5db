"""ballast.experiments.box.parameters: every bad value refused before any work, naming the parameter, the
value and what is allowed (no YADE); the bed's key (what decides a stored bed)."""
import pytest

from ballast.experiments.box import PARAMS, check
from ballast.experiments.box.parameters import BED_KEYS, bedKey
from ballast.params import ParamError


@pytest.mark.parametrize('values, name, why', [
    ({'dMin': 0.05}, 'dMin', 'must be smaller than dMax = 0.0445'),
    ({'bedDepth': 0.08}, 'bedDepth', 'must hold at least two of the largest grains, 2 dMax = 0.089 m'),
    ({'layers': 8}, 'layers', 'layers of 0.0375 m are thinner than the largest grain dMax = 0.0445 m'),
    ({'boxWidth': 0.1}, 'boxWidth', 'must be at least 3 dMax'),
    ({'sleeperWidth': 0.6}, 'sleeperWidth', 'leaves less than 2 dMax of ballast on either side'),
    ({'sleeperGap': 0.15}, 'sleeperGap', 'leaves no sleeper in a box of width 0.3 m'),
    ({'seatLoad': 4e4}, 'seatLoad', 'must be smaller than peakLoad = 40000 N'),
    ({'rMin': 0.03}, 'rMin', 'larger than the largest grain radius'),
    ({'prepYoung': 1e12}, 'prepYoung', 'must not exceed young'),
    ({'f': 5e4}, 'f', 'fewer than 100'),
    ({'cycles': 10 ** 7}, 'cycles', 'more than the 1e+09 a run may take'),
    ({'Tc': 1.0}, 'Tc', 'longer than the load cycle'),
    ({'abrasionPeriod': 10 ** 6}, 'abrasionPeriod', 'longer than the load cycle'),
    ({'rollingFriction': 0.2, 'law': 'hertz'}, 'rollingFriction', "needs law = 'linear'"),
    ({'peakLoad': -1}, 'peakLoad', 'expected a finite number > 0'),
    ({'layers': 0}, 'layers', 'an integer in [1, 20]'),
    ({'saveEvery': -1}, 'saveEvery', 'a finite number >= 0'),
    ({'quasiStaticStart': 1.0}, 'quasiStaticStart', 'is used only with quasiStatic > 0'),
    ({'quasiStatic': 1e-3, 'quasiStaticStart': 0.5}, 'quasiStaticStart', 'a number in [1, 16]'),
])
def test_a_bad_value_is_refused_naming_the_parameter(values, name, why):
    with pytest.raises(ParamError, match=r'BoxTest: %s = ' % name) as e:
        check(values)
    assert e.value.name == name and why in str(e.value)


def test_the_defaults_are_valid_and_every_parameter_has_a_unit_and_a_doc():
    p = check({})
    assert p.history().period == pytest.approx(1 / 3.0) and p.sleeperLength() == pytest.approx(0.28)
    for name, decl in PARAMS.items():
        assert decl.unit and decl.doc, name


def test_the_bed_key_changes_with_what_decides_the_bed_only():
    base = bedKey(check({}))[1]
    assert bedKey(check({'seed': 2}))[1] != base and bedKey(check({'layerPressure': 5e4}))[1] != base
    assert bedKey(check({'peakLoad': 30e3, 'f': 5.0, 'fatigue': True}))[1] == base   # the load is not the bed
    assert set(BED_KEYS) <= set(PARAMS)


def test_a_box_of_more_grains_than_a_run_may_take_is_refused():
    # 1000 x 0.3 x 0.3 m at solid fraction 0.6: 54 m^3 of grains of mean volume pi/6 E[d^3] (d uniform in
    # 20.5-44.5 mm: pi/6 (dMax^4 - dMin^4) / (4 (dMax - dMin)) = 2.04e-5 m^3): 2.6e6 grains, above 1e6
    with pytest.raises(ParamError, match=r'boxLength = 1000.0 is not allowed: a sample of 90 m\^3 holds about 2.6e\+06'):
        check({'boxLength': 1e3})
    check({'boxLength': 2.0})   # 0.18 m^3: 5 300 grains


def test_a_load_beyond_rigid_sphere_dem_is_refused():
    """The mean stress under the sleeper's footprint through the smallest grain's contact (F = sigma dMin^2, kn = E r
    for two equal grains of the linear law) overlaps it by sigma dMin^2 / (E r) = 4 sigma / E of its radius: at most
    0.25, so sigma <= E / 16 (1.875e10 Pa at the paper's E), whatever gives the load (peakLoad 1e12 N sank a sleeper
    1 m into the floor)."""
    p = check({})
    area = p['sleeperWidth'] * p.sleeperLength()
    most = p['young'] / 16 * area
    check({'peakLoad': 0.99 * most})
    with pytest.raises(ParamError, match=r"peakLoad = .* mean stress of .* on the bed under the sleeper's footprint.*"
                                         r"at most 1.87e\+10 Pa") as e:
        check({'peakLoad': 1.01 * most})
    assert e.value.name == 'peakLoad'
    with pytest.raises(ParamError, match='peakLoad = 1000000000000.0 is not allowed'):
        check({'peakLoad': 1e12})   # the audit's case
    # a softer grain bears less: young / 100, the bound / 100
    with pytest.raises(ParamError, match='peakLoad'):
        check({'peakLoad': 0.02 * most, 'young': p['young'] / 100, 'prepYoung': p['young'] / 1000})
