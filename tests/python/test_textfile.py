"""ballast.textfile: the one strict reader of the text files users give (tables, load histories, measured curves,
calibration CSVs): UTF-8 text back as it is, anything else refused naming the file and the byte (no YADE)."""
import re

import pytest

from ballast import textfile
from ballast.experiments.single_particle.calibration import CalibrationError, readMeasured


def test_utf8_text_comes_back_as_it_is(tmp_path):
    path = tmp_path / 'a.csv'
    path.write_bytes('t,F\r\n0,1 \u00b5\n'.encode('utf-8'))
    assert textfile.read(str(path)) == 't,F\r\n0,1 \u00b5\n'


@pytest.mark.parametrize('content, where', [(b'ab\xe9c', 'byte 2 (0xe9) is not UTF-8'), (b'abc\x00', 'it holds a NUL byte at 3'),
                                            (b'\x1f\x8b\x08\x00', 'byte 1 (0x8b) is not UTF-8')])
def test_anything_else_is_refused_naming_the_file_and_the_byte(tmp_path, content, where):
    path = tmp_path / 'b.csv'
    path.write_bytes(content)
    with pytest.raises(textfile.NotText, match='b.csv: not a text file: ' + re.escape(where)):
        textfile.read(str(path))
    with pytest.raises(CalibrationError, match='b.csv: not a text file: ' + re.escape(where)):   # a calibration CSV likewise
        readMeasured(str(path))
