"""Tests of ballast.study.attempts: the line of a log that says why a run failed, how far a running run has come
(from the tail of its newest log), and the work a dead runner left: removed, or kept to go on from when its run
saved a state, and taken up again only by the same row (no yade)."""
import json
import os

from ballast.runfiles import writeAtomic
from ballast.study import attempts


def test_last_error_prefers_the_bad_parameter_line(tmp_path):
    log = tmp_path / 'x.log'
    log.write_text('start\noedometer.py: bad parameter f: f = -1 is not allowed\nTraceback ...\n  File x\nexit\n')
    assert attempts.lastError(str(log)) == 'oedometer.py: bad parameter f: f = -1 is not allowed'
    log.write_text('Traceback (most recent call last):\n  File "x"\nValueError: no\n\n')
    assert attempts.lastError(str(log)) == 'ValueError: no'
    assert attempts.lastError(str(tmp_path / 'none.log')) == ''


def test_a_running_runs_progress_is_read_from_the_tail_of_its_newest_log(tmp_path):
    work = tmp_path / 'work'
    assert attempts.runProgress(str(work), 'r') == ''   # no work directory yet
    old, new, other = (work / 'r.abc', work / 'r.xyz', work / 'r2.abc')
    for d in (old, new, other):
        d.mkdir(parents=True)
    (work / 'r.lock').write_text('')
    assert attempts.runProgress(str(work), 'r') == ''   # started, no log yet
    line = '[box %6.1fs] load     t=0.1 s  step %d  dt=7.69e-07 s  %5.1f%% of loading  ETA %s  cycle 3 of 10\n'
    (old / 'run.log').write_text(line % (1, 10, 99.0, '0s'))
    os.utime(old / 'run.log', (1, 1))   # an earlier attempt's log, older
    (other / 'run.log').write_text(line % (1, 10, 50.0, '9m'))   # another run whose id starts alike
    # a long log: 10 000 lines, the last progress line before a line that is none
    (new / 'run.log').write_text(''.join(line % (k, k, 100 * k / 1e4, '%dm' % (10000 - k)) for k in range(10000)) + 'fabric\n')
    assert attempts.runProgress(str(work), 'r') == '100.0% of loading, ETA 1m'   # line 9 999 (%5.1f)
    (new / 'run.log').write_text('[box 0.2s] prepare  t=0 s  step 0\n')   # no progress line in its tail
    assert attempts.runProgress(str(work), 'r') == ''
    # a phase that ends on a condition prints no percentage: its own state, not the phase before's stale ETA
    (new / 'run.log').write_text(
        '[box 117.7s] deposit  t=1.3948 s  step 219761  dt=6.35e-06 s   98.0% of phase  ETA 1s  unbalanced 0.963\n'
        '[box 637.9s] settle   t=1.9522 s  step 543227  dt=1.92e-07 s  unbalanced 0.621  v_rms 0.018 m/s\n')
    assert attempts.runProgress(str(work), 'r') == 'settle: unbalanced 0.621 v_rms 0.018 m/s'


def attempt(work, runId, row, state='state-1.gz'):
    """The work folder a dead runner's attempt left: its row and a run that saved `state` (None: none yet)."""
    path = os.path.join(work, runId + '.dead1234')
    runDir = os.path.join(path, 'results', runId)
    os.makedirs(runDir)
    writeAtomic(os.path.join(path, 'row.json'), json.dumps(row))
    writeAtomic(os.path.join(runDir, 'run.json'), json.dumps(dict({'status': 'running'}, **(
        {'lastState': state} if state else {}))))
    if state:
        writeAtomic(os.path.join(runDir, state), 'saved')
    return path


def test_a_killed_run_with_a_saved_state_is_kept_and_goes_on_only_from_its_own_row(tmp_path):
    work, keep, row = str(tmp_path / 'work'), str(tmp_path / 'resume'), {'seed': '1', 'f': '2'}
    attempt(work, 'a', row)
    attempt(work, 'b', row, state=None)   # killed before it saved a state: nothing to go on from
    records = {r['runId']: r for r in attempts.clearWork(work, keep=keep)}
    assert records['a']['error'].endswith('; kept to go on from its state-1.gz') and records['a']['kept'] == 'state-1.gz'
    assert 'kept' not in records['b']['error'] and records['b']['kept'] is None
    assert os.listdir(work) == [] and sorted(os.listdir(keep)) == ['a']
    assert attempts.takeKept(keep, 'a', dict(row, f='3'), str(tmp_path / 'r1')) is None   # the row changed: dropped
    assert os.listdir(keep) == [] and not os.path.exists(str(tmp_path / 'r1'))
    attempt(work, 'a', row)
    attempts.clearWork(work, keep=keep)
    assert attempts.takeKept(keep, 'a', row, str(tmp_path / 'r2')) == 'state-1.gz'
    assert os.path.isfile(str(tmp_path / 'r2' / 'a' / 'state-1.gz')) and os.listdir(keep) == []
    attempt(work, 'c', row)
    assert attempts.clearWork(work)[0]['runId'] == 'c' and not os.path.exists(os.path.join(keep, 'c'))   # no keep: removed
