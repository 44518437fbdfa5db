"""ballast.experiments.triaxial.strains and .parameters (no YADE): strains from the boundary by hand, the measured
curves' reader strict with the line named, the parameters' cross-checks."""
import math

import numpy as np
import pytest

from ballast.experiments.triaxial import check
from ballast.experiments.triaxial.strains import (CurveError, atCycles, axialStrain, readReference, resilientModulus,
                                                  volumetricStrain)
from ballast.params import ParamError


def test_strains_by_hand():
    # a 0.6 m specimen shortened by 3 mm: 0.5 %; 0.0424 m^3 down to 0.0420: 0.943 %; dilation negative
    assert axialStrain(0.6, 0.597) == pytest.approx(0.005, rel=1e-12)
    assert volumetricStrain(0.0424, 0.0420) == pytest.approx(0.0004 / 0.0424, rel=1e-12)
    assert volumetricStrain(0.0424, 0.0430) < 0
    assert resilientModulus(185e3, 1e-3) == pytest.approx(1.85e8, rel=1e-12)
    assert math.isnan(resilientModulus(185e3, 0.0))


def write(tmp_path, text, name='curve.csv'):
    path = tmp_path / name
    path.write_text(text)
    return str(path)


def test_reads_a_curve_and_interpolates_in_log_N(tmp_path):
    kind, N, e = readReference(write(tmp_path, 'N,axial_strain\n1,0.01\n100,0.03\n\n10000,0.04\n'))
    assert kind == 'axial' and N.tolist() == [1, 100, 10000] and e.tolist() == [0.01, 0.03, 0.04]
    # N = 10 is halfway between 1 and 100 in log N: 0.02; 1000 halfway between 100 and 1e4: 0.035
    assert atCycles(N, e, [10, 1000]) == pytest.approx([0.02, 0.035], rel=1e-12)
    assert np.isnan(atCycles(N, e, [1e5])).all()
    kind, _, _ = readReference(write(tmp_path, 'N,volumetric_strain\n1,-0.001\n5,0.002\n', 'v.csv'))
    assert kind == 'volumetric'


@pytest.mark.parametrize('text, words', [
    ('', 'empty'),
    ('N,strain\n1,0.01\n2,0.02\n', "line 1: header 'N,strain'"),
    ('cycle,axial_strain\n1,0.01\n2,0.02\n', "line 1: header"),
    ('N,axial_strain\n1,0.01\n2,0.02,7\n', 'line 3: 3 fields'),
    ('N,axial_strain\n1,0.01\n2,abc\n', "line 3: '2,abc' is not two numbers"),
    ('N,axial_strain\n0,0.01\n2,0.02\n', 'line 2: N = '),
    ('N,axial_strain\n10,0.01\n2,0.02\n', 'line 3: N = 2 after 10'),
    ('N,axial_strain\n1,4.3\n2,0.02\n', 'line 2: axial_strain = '),
    ('N,axial_strain\n1,nan\n2,0.02\n', 'line 2: axial_strain = '),
    ('N,axial_strain\n1,0.01\n', '1 rows of numbers'),
])
def test_refuses_a_malformed_curve_naming_the_line(tmp_path, text, words):
    path = write(tmp_path, text)
    with pytest.raises(CurveError, match='^%s' % path) as e:
        readReference(path)
    assert words in str(e.value)


def test_a_binary_or_missing_file_is_refused(tmp_path):
    path = tmp_path / 'bin.csv'
    path.write_bytes(b'\xff\xfe\x00\x01')
    with pytest.raises(CurveError, match='not a text file'):
        readReference(str(path))
    with pytest.raises(CurveError, match='cannot be read'):
        readReference(str(tmp_path / 'none.csv'))


def test_parameters_cross_checks(tmp_path):
    p = check({})
    assert p['diameter'] == 0.3 and p['height'] == 0.6 and p['confining'] == 60e3 and p['qMax'] == 230e3
    assert p.cell() == pytest.approx(p['dMin'] / 2) and p.depth() == pytest.approx(p['dMin'] / 4)
    # the sine: qMin at a cycle's start and end, qMax at its middle
    assert p.deviator(0) == pytest.approx(45e3) and p.deviator(0.1) == pytest.approx(230e3)
    assert p.deviator(0.2) == pytest.approx(45e3)
    for bad, name in (({'qMin': 230e3}, 'qMin'), ({'diameter': 0.15}, 'diameter'), ({'height': 1.0}, 'height'),
                      ({'membraneCell': 0.05}, 'membraneCell'), ({'layers': 30}, 'layers'),
                      ({'diameter': 20.0, 'height': 20.0}, 'diameter'),
                      ({'reference': write(tmp_path, 'N,x\n')}, 'reference')):
        with pytest.raises(ParamError, match='TriaxialTest: %s = ' % name):
            check(bad)
    # the ends carry confining + qMax: at most young / 16 (the smallest grain's overlap at most a quarter of its radius)
    most = p['young'] / 16
    check({'qMax': 0.99 * most - 60e3})
    with pytest.raises(ParamError, match=r"TriaxialTest: qMax = .* on the specimen's ends"):
        check({'qMax': 1.01 * most - 60e3})
    good = write(tmp_path, 'N,axial_strain\n1,0.01\n2,0.02\n', 'a.csv')
    assert [k for k, _, _ in check({'reference': good + ',' + good}).references()] == ['axial', 'axial']


def test_a_deviator_history_from_a_csv(tmp_path):
    """loadFile: q(t) interpolated linearly over one cycle and repeated; its first q seats the specimen; qMin, qMax
    and f refused beside it; a malformed file refused with its line; the peak bounded as qMax is."""
    path = write(tmp_path, 't,q\n0,40000\n0.1,240000\n0.25,40000\n', 'q.csv')
    p = check({'loadFile': path})
    assert p.period() == pytest.approx(0.25) and p.seatDeviator() == 40e3 and p.peakDeviator() == 240e3
    assert p.deviator(0.05) == pytest.approx(140e3) and p.deviator(0.175) == pytest.approx(140e3)
    assert p.deviator(0.25 + 0.05) == pytest.approx(140e3)   # the next cycle repeats it
    for k, v in (('qMax', 300e3), ('qMin', 10e3), ('f', 10.0)):
        with pytest.raises(ParamError, match='TriaxialTest: %s = .* is not used with loadFile' % k):
            check({'loadFile': path, k: v})
    bad = write(tmp_path, 't,q\n0,40000\n0.1,abc\n0.2,40000\n', 'bad.csv')
    with pytest.raises(ParamError, match=r"TriaxialTest: loadFile = .*line 3: expected numbers in columns t and q"):
        check({'loadFile': bad})
    force = write(tmp_path, 't,F\n0,1\n0.1,2\n0.2,1\n', 'F.csv')
    with pytest.raises(ParamError, match=r'must name the columns t \(time \[s\]\) and q \(deviator stress \[Pa\]\)'):
        check({'loadFile': force})
    huge = write(tmp_path, 't,q\n0,40000\n0.1,1e11\n0.2,40000\n', 'huge.csv')
    with pytest.raises(ParamError, match="TriaxialTest: loadFile = .* on the specimen's ends"):
        check({'loadFile': huge})
    # without loadFile the sine's closed form, as before
    assert check({}).deviator(0.05) == pytest.approx(45e3 + 185e3 * 0.5 * (1 - math.cos(math.pi / 2)))
