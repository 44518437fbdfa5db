"""Tests of ballast.runfiles: atomic writes, and the sha1 that identifies the code of a run (the
script and the installed ballast package); strict JSON; the state a killed run left."""
import json
import os

import numpy as np
import pytest

import ballast
from ballast import runfiles as files


def test_write_atomic_replaces_whole_files_and_leaves_no_temporary(tmp_path):
    p = str(tmp_path / 'status.csv')
    files.writeAtomic(p, 'a\n')
    files.writeAtomic(p, b'b\n')
    assert open(p).read() == 'b\n' and os.listdir(str(tmp_path)) == ['status.csv']


def test_code_sha1_changes_with_the_script_and_reads_the_package():
    a = files.codeSha1('print(1)\n')
    assert a == files.codeSha1('print(1)\n') and a != files.codeSha1('print(2)\n')
    assert a == files.sha1(files.sha1('print(1)\n') + files.packageSha1())


def test_package_sha1_covers_the_python_files_and_the_compiled_core(tmp_path, monkeypatch):
    """A copy of the installed package hashes alike; one byte more in any .py or in _ballast*.so,
    or another file name, changes it; other files do not count."""
    import shutil
    top = os.path.dirname(ballast.__file__)
    copy = tmp_path / 'ballast'
    shutil.copytree(top, str(copy), ignore=shutil.ignore_patterns('__pycache__'))
    monkeypatch.setattr(ballast, '__file__', str(copy / '__init__.py'))
    h = files.packageSha1()
    (copy / 'notes.txt').write_text('not code')
    assert files.packageSha1() == h
    so = [n for n in os.listdir(str(copy)) if n.startswith('_ballast') and n.endswith('.so')]
    assert so
    for name in (so[0], 'params.py', os.path.join('study', 'runner.py')):
        with open(str(copy / name), 'ab') as fh:
            fh.write(b'\n')
        assert files.packageSha1() != h, name
        h = files.packageSha1()
    os.rename(str(copy / 'scenes.py'), str(copy / 'scenes2.py'))
    assert files.packageSha1() != h


def test_read_files_gives_every_file_below_a_directory(tmp_path):
    (tmp_path / 'vtk').mkdir()
    (tmp_path / 'fd.csv').write_text('t,F\n')
    (tmp_path / 'vtk' / 'a.vtu').write_bytes(b'\0\1')
    assert files.readFiles(str(tmp_path)) == {'fd.csv': b't,F\n', os.path.join('vtk', 'a.vtu'): b'\0\1'}


def test_strict_json_writes_what_is_not_a_finite_number_as_null():
    value = {'a': float('nan'), 'b': [1.5, float('inf'), (np.float64('-inf'), 2)], 'c': {'d': True, 'e': 3, 'f': 'x'}}
    text = json.dumps(files.strictJson(value))
    assert json.loads(text, parse_constant=lambda c: pytest.fail(c)) == {
        'a': None, 'b': [1.5, None, [None, 2]], 'c': {'d': True, 'e': 3, 'f': 'x'}}
    assert 'NaN' in json.dumps(value)   # what Python's json writes without it


def test_a_killed_run_state_is_the_last_state_of_a_run_still_marked_running(tmp_path):
    d = str(tmp_path)
    assert files.runStatus(d) is None and files.killedRunState(d) is None and files.killedRunState(str(tmp_path / 'none')) is None
    (tmp_path / 'run.json').write_text('{"status": "runn')   # cut short
    assert files.runStatus(d) is None
    (tmp_path / 'run.json').write_text('{"status": "running"}')   # no state saved yet
    assert files.runStatus(d) == {'status': 'running'} and files.killedRunState(d) is None
    (tmp_path / 'run.json').write_text('{"status": "running", "lastState": "state-cycle0000050.yade.gz"}')
    assert files.killedRunState(d) is None   # named, not there
    (tmp_path / 'state-cycle0000050.yade.gz').write_bytes(b'x')
    assert files.killedRunState(d) == os.path.join(d, 'state-cycle0000050.yade.gz')
    (tmp_path / 'run.json').write_text('{"status": "finished", "lastState": "state-cycle0000050.yade.gz"}')
    assert files.killedRunState(d) is None


def test_log_axes_are_labelled_in_plain_numbers_on_both_axes():
    """plainLogTicks(ax, 'xy'): within 2.5 decades the ticks 1, 2, 3, 5 of each decade and the decades are labelled
    in plain numbers (not 2x10^0), the others left blank; over more, the decades only."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    from ballast.runfiles import plainLogTicks
    fig, ax = plt.subplots()
    ax.loglog([20, 50], [30, 100])
    ax.set_xlim(20, 50)
    ax.set_ylim(30, 100)
    plainLogTicks(ax, 'xy')
    fig.canvas.draw()

    def shown(axis):
        lo, hi = axis.get_view_interval()
        ticks = [t for t in axis.get_major_ticks() + axis.get_minor_ticks() if lo * (1 - 1e-9) <= t.get_loc() <= hi * (1 + 1e-9)]
        return sorted({float(t.label1.get_text()) for t in ticks if t.label1.get_text()})
    assert shown(ax.yaxis) == [30.0, 50.0, 100.0] and shown(ax.xaxis) == [20.0, 30.0, 50.0]
    ax.set_xlim(1, 2)   # within one decade matplotlib ticks 1.2, 1.4, ...: 1.6 and 1.8 are no 2 (a failed run's 2 cycles)
    fig.canvas.draw()
    assert shown(ax.xaxis) == [1.0, 2.0]
    ax.set_ylim(1, 1e4)   # four decades: the decades only
    fig.canvas.draw()
    assert shown(ax.yaxis) == [1.0, 10.0, 100.0, 1000.0, 10000.0]
    plt.close(fig)
