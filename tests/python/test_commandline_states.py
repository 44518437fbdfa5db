"""A state a command line is to go on from (--continueFrom) that is empty, not a YADE state, or of another experiment
is refused in one line with exit status 2, before any work, as a bad parameter is (no traceback)."""
import gzip
import json
import os
import subprocess

import pytest

pytest.importorskip('yade')
from yade import O, utils  # noqa: E402

from ballast import runtime  # noqa: E402

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'scripts', 'box_test.py')


def refused(path, tmp_path):
    env = dict(os.environ, OMP_NUM_THREADS='1')
    env.pop('YADE_BATCH', None)
    r = subprocess.run(['yade', '-n', '-x', SCRIPT, '--continueFrom', str(path), '--results', str(tmp_path / 'out')],
                       capture_output=True, text=True, env=env, timeout=300)
    assert r.returncode == 2, r.stdout[-2000:] + r.stderr[-2000:]
    assert 'Traceback' not in r.stdout + r.stderr
    return r.stderr.strip().splitlines()[-1]


def test_damaged_states_are_refused_in_one_line(tmp_path):
    empty = tmp_path / 'empty.yade.gz'
    empty.write_bytes(b'')
    assert refused(empty, tmp_path).startswith('box_test.py: bad state: box.reopen: %s is not a loadable state: the '
                                               'file is empty' % empty)
    garbage = tmp_path / 'garbage.yade.gz'
    with gzip.open(garbage, 'wb') as fh:
        fh.write(b'not a state\n')
    assert 'is not a loadable state: its content is not a YADE state' in refused(garbage, tmp_path)


def test_a_state_of_another_experiment_is_named_as_such(tmp_path):
    O.reset()
    O.bodies.append(utils.sphere((0, 0, 0), 0.01))
    O.tags[runtime.TAG] = json.dumps({'format': runtime.FORMAT, 'token': 't',
                                      'objects': {'a': {'type': 'Oedometer', 'state': {}}}})
    path = tmp_path / 'oedometer.yade.gz'
    O.save(str(path))
    O.reset()
    assert refused(path, tmp_path) == ('box_test.py: bad state: box.reopen: %s is a state of another experiment (it '
                                       'holds a saved Oedometer, not a BoxTest)' % path)
