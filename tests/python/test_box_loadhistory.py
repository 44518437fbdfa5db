"""ballast.experiments.loadhistory (the box's load): the sine between the seating and the peak load, a CSV history
(shape, interpolation, repetition) and every malformed CSV refused with its line named (no YADE)."""
import math
import re

import pytest

from ballast.experiments.box import check
from ballast.experiments.loadhistory import SINE_SAMPLES, LoadHistory, LoadHistoryError
from ballast.params import ParamError


def test_the_sine_rises_from_the_seat_to_the_peak_at_half_period_and_back():
    h = LoadHistory.sine(3e3, 40e3, 3.0)
    assert h.period == pytest.approx(1 / 3.0, rel=1e-15) and h.seat == 3e3 and h.peak == pytest.approx(40e3, rel=1e-12)
    assert len(h.times) == SINE_SAMPLES + 1
    for tau in (0.0, 0.01, 0.0833, 0.2, 1 / 6, 0.3):   # F = seat + (peak - seat)(1 - cos 2 pi f tau)/2, by hand
        exact = 3e3 + 37e3 * 0.5 * (1 - math.cos(2 * math.pi * 3.0 * tau))
        assert h.at(tau) == pytest.approx(exact, abs=37e3 * math.pi ** 2 / (4 * SINE_SAMPLES ** 2) + 1e-9)
    assert h.at(1 / 6 + 5 / 3.0) == pytest.approx(40e3, rel=1e-9)   # cycle after cycle


def test_a_csv_history_is_interpolated_linearly_and_repeated(tmp_path):
    path = tmp_path / 'passage.csv'
    path.write_text('t,F,note\n0,1000,seat\n0.1,5000,axle\n0.15,2000,\n0.2,1000,\n')
    h = LoadHistory.fromCsv(str(path))
    assert (h.period, h.seat, h.peak) == (0.2, 1000.0, 5000.0)
    assert h.at(0.05) == pytest.approx(3000.0) and h.at(0.125) == pytest.approx(3500.0)
    assert h.at(0.2 + 0.05) == pytest.approx(3000.0)
    times, forces = h.table()
    assert times == [0.0, 0.1, 0.15, 0.2] and forces == [1000.0, 5000.0, 2000.0, 1000.0]


@pytest.mark.parametrize('text, where', [
    ('time,force\n0,1\n1,1\n', 'line 1 must name the columns t'),
    ('t,F\n0,1000\n0.1,abc\n0.2,1000\n', 'line 3: expected numbers'),
    ('t,F\n0,1000\n0.1\n', 'line 3: expected numbers'),
    ('t,F\n0,1000\n0.1,-5\n0.2,1000\n', 'line 3: t = 0.1 s, F = -5.0 N'),
    ('t,F\n0,1000\n0.1,nan\n0.2,1000\n', 'line 3: t = 0.1 s, F = nan N'),
    ('t,F\n0.05,1000\n0.1,2000\n', 'line 2: the history starts at t = 0'),
    ('t,F\n0,1000\n0.1,2000\n0.1,1000\n', 'line 4: t = 0.1 s does not rise'),
    ('t,F\n0,1000\n0.1,5000\n0.2,2000\n', 'line 4: the cycle ends at F = 2000.0 N but starts at 1000.0 N'),
    ('t,F\n0,1000\n', '1 row(s) of data'),
    ('t,F\n0,1000\n1,1000\n', 'the load never changes'),
])
def test_a_malformed_csv_is_refused_naming_the_line(tmp_path, text, where):
    path = tmp_path / 'bad.csv'
    path.write_text(text)
    with pytest.raises(LoadHistoryError, match='bad.csv') as e:
        LoadHistory.fromCsv(str(path))
    assert where in str(e.value)


def test_the_parameters_refuse_a_bad_history_before_any_work(tmp_path):
    path = tmp_path / 'bad.csv'
    path.write_text('t,F\n0,1000\n0.1,x\n0.2,1000\n')
    with pytest.raises(ParamError, match=r"loadFile = .*bad.csv' is not allowed: .*line 3") as e:
        check({'loadFile': str(path)})
    assert e.value.name == 'loadFile'
    with pytest.raises(ParamError, match='no such file'):
        check({'loadFile': str(tmp_path / 'missing.csv')})
    with pytest.raises(ParamError, match='seatLoad = 50000.0 is not allowed: must be smaller than peakLoad'):
        check({'seatLoad': 5e4})
    with pytest.raises(LoadHistoryError, match='expected 0 <= seat < peak and f > 0'):
        LoadHistory.sine(5.0, 4.0, 1.0)


def test_a_load_option_the_history_overrides_is_refused(tmp_path):
    # --loadFile F --peakLoad 9999: the peak would be the history's; the run would report a peak it never applied
    path = tmp_path / 'passage.csv'
    path.write_text('t,F\n0,1000\n0.1,5000\n0.2,1000\n')
    assert check({'loadFile': str(path)}).history().peak == 5000
    for k, v in (('peakLoad', 9999.0), ('seatLoad', 500.0), ('f', 2.0)):
        with pytest.raises(ParamError, match='%s = %r is not allowed: is not used with loadFile' % (k, v)) as e:
            check({'loadFile': str(path), k: v})
        assert e.value.name == k


@pytest.mark.parametrize('content, where', [(b'\xb7\x01binary', 'byte 0 (0xb7) is not UTF-8'),
                                            (b't,F\n0,1\n\xff\xfe,3\n', 'byte 8 (0xff) is not UTF-8'),
                                            (b't,F\n0,1\x00\n', 'it holds a NUL byte at 7')])
def test_a_binary_history_is_refused_in_one_line_naming_the_byte(tmp_path, content, where):
    # the audit's binary --loadFile gave a UnicodeDecodeError traceback (issue 48, item 1)
    path = tmp_path / 'load.csv'
    path.write_bytes(content)
    with pytest.raises(ParamError, match=r"loadFile = .*load.csv' is not allowed: loadFile .*load.csv: not a text "
                                         r"file: " + re.escape(where)) as e:
        check({'loadFile': str(path)})
    assert '\n' not in str(e.value)
