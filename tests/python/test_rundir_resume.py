"""ballast.experiments.rundir.resumableState: the state a killed run goes on from, found whatever run.json says
(damaged, silent, or naming a state that is cut short), the newest intact one; never a finished run; a folder whose
states are all damaged refused; the temporary files of a save a kill cut off removed."""
import gzip
import json
import os

import pytest

pytest.importorskip('yade')
from ballast.experiments.rundir import resumableState  # noqa: E402

XML = b'<?xml version="1.0" encoding="UTF-8"?>\n<boost_serialization signature="serialization::archive">' + b'x' * 4000


def state(folder, name, t, whole=True):
    path = folder / name
    with gzip.open(path, 'wb') as fh:
        fh.write(XML)
    if not whole:   # a save cut off: the gzip stream without its end
        data = path.read_bytes()
        path.write_bytes(data[:len(data) // 2])
    os.utime(path, (t, t))
    return path


def runJson(folder, text):
    (folder / 'run.json').write_text(text if isinstance(text, str) else json.dumps(text))


def test_a_damaged_run_json_goes_on_from_the_newest_intact_state(tmp_path):
    for k in (1, 2, 3):
        state(tmp_path, 'state-cycle%07d.yade.gz' % k, 1000 + k)
    (tmp_path / '.tmp-123-state-cycle0000004.yade.gz').write_bytes(b'half')
    for text in ('{not json', '', '[1, 2]'):
        runJson(tmp_path, text)
        path, why = resumableState(str(tmp_path))
        assert os.path.basename(path) == 'state-cycle0000003.yade.gz'
        assert why == 'run.json is missing or damaged: going on from state-cycle0000003.yade.gz'
    assert not (tmp_path / '.tmp-123-state-cycle0000004.yade.gz').exists()
    runJson(tmp_path, {'status': 'running'})
    assert resumableState(str(tmp_path))[1].startswith('run.json names no last state')


def test_a_last_state_cut_short_is_skipped_for_the_one_before(tmp_path):
    state(tmp_path, 'state-cycle0000001.yade.gz', 1001)
    state(tmp_path, 'state-cycle0000002.yade.gz', 1002)
    state(tmp_path, 'state-cycle0000003.yade.gz', 1003, whole=False)
    runJson(tmp_path, {'status': 'running', 'lastState': 'state-cycle0000003.yade.gz'})
    path, why = resumableState(str(tmp_path))
    assert os.path.basename(path) == 'state-cycle0000002.yade.gz'
    assert 'state-cycle0000003.yade.gz is not a loadable state: the gzip data is cut short' in why
    runJson(tmp_path, {'status': 'running', 'lastState': 'state-cycle0000001.yade.gz'})   # what run.json names first
    assert os.path.basename(resumableState(str(tmp_path))[0]) == 'state-cycle0000001.yade.gz'


def test_finished_runs_and_folders_without_an_intact_state_are_not_resumed(tmp_path):
    state(tmp_path, 'state-end.yade.gz', 1000)
    runJson(tmp_path, {'status': 'finished'})
    assert resumableState(str(tmp_path)) == (None, 'the run finished')
    runJson(tmp_path, '{damaged')
    (tmp_path / 'summary.json').write_text('{}')
    assert resumableState(str(tmp_path)) == (None, 'the run finished')
    broken = tmp_path / 'broken'
    broken.mkdir()
    state(broken, 'state-cycle0000001.yade.gz', 1000, whole=False)
    runJson(broken, {'status': 'running', 'lastState': 'state-cycle0000001.yade.gz'})
    path, why = resumableState(str(broken))
    assert path is None and why.endswith('no intact state in it') and 'cut short' in why
    assert resumableState(str(tmp_path / 'none')) == (None, 'no such folder')
