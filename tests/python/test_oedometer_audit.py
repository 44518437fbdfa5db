"""The failures of the audit of issue 28 on the small oedometer of test_oedometer_experiment (150 x 80 mm,
f = 50 Hz, weak grains): a run killed by SIGKILL during a save and during loading leaves whole states,
says it was killed (run.json) and its outputs are rebuilt from its last state with the state's counts;
identical runs give identical summaries; the summary's numbers keep their definitions; the VTK output has
the contact force network and the frame at the end; every original grain is sand-coloured."""
import json
import os
import shutil
import signal
import subprocess
import time
import xml.etree.ElementTree as ET

import numpy as np
import pytest

yade = pytest.importorskip('yade')
from ballast.experiments.rundir import checkStateFile  # noqa: E402
from ballast.oedometer import Oedometer  # noqa: E402
from ballast.experiments.tracker import COLOR_ORIGINAL  # noqa: E402

F = 50.0  # [Hz]
SMALL = dict(f=F, ft0=5e5, strength=1.5e10, diameter=0.15, height=0.08, vMax=5, samples=1000, progress=60)
SECONDS = ('wallSeconds', 'cpuSeconds', 'wallSecondsByPhase', 'checkSeconds')  # wall-clock, not the run's
TIMEOUT = 300  # [s] a yade process

RUN = '''
import os, signal, sys
from yade import O
from yade.wrapper import Omega
from ballast.oedometer import Oedometer
results, packings, killAtSave = sys.argv[1], sys.argv[2], int(sys.argv[3])
if killAtSave:  # the kth state is cut off half-written, as by a SIGKILL while YADE writes it
    saves, save = [0], Omega.save
    def cut(self, path, *a, **kw):
        save(self, path, *a, **kw)
        saves[0] += 1
        if saves[0] == killAtSave:
            with open(path, 'r+b') as fh:
                fh.truncate(os.path.getsize(path) // 2)
            os.kill(os.getpid(), signal.SIGKILL)
    Omega.save = cut
Oedometer(results=results, runId='killed', packingDir=packings, saveEvery=0.1, %s).run()
''' % ', '.join('%s=%r' % kv for kv in SMALL.items())


def yadeRun(script, args, **kw):
    return subprocess.Popen([shutil.which('yade'), '-n', '-x', str(script)] + [str(a) for a in args],
                            env=dict(os.environ, OMP_NUM_THREADS='1'), stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True, **kw)


@pytest.fixture(scope='module')
def root(tmp_path_factory):
    return tmp_path_factory.mktemp('audit')


@pytest.fixture(scope='module')
def first(root):
    """A run that builds the packing the others reuse, with VTK frames."""
    run = Oedometer(results=str(root / 'first'), runId='first', packingDir=str(root / 'packings'), vtk=0.3,
                    **SMALL)
    return run, run.run()


def summaryWithoutSeconds(s):
    s = {k: v for k, v in s.items() if k not in SECONDS}
    s['params'] = {k: v for k, v in s['params'].items() if k != 'results'}
    return s


def test_summary_numbers_keep_their_definitions(first):
    run, s = first
    assert 0 <= s['BBI'] <= 1 and s['dustPercent'] == pytest.approx(100 * s['massLost'] / s['massInitial'])
    assert s['cycles'] == 1 and isinstance(s['cycles'], int)
    assert s['peakGrainForce'] == s['peakForce'] and s['peakAppliedForce'] <= run.p['Fmax'] * (1 + 1e-9)
    with open(os.path.join(run.out, 'cycles.csv')) as fh:
        rows = [line.split(',') for line in fh.read().split('\n')[1:] if line]
    assert rows and all(float(r[3]) >= 0 for r in rows)  # the resilient displacement
    with open(os.path.join(run.out, 'run.json')) as fh:
        assert json.load(fh)['status'] == 'finished'


def test_vtk_has_the_contact_network_and_the_frame_at_the_end(first):
    run, s = first
    sets = ET.parse(os.path.join(run.out, 'oedometer.pvd')).getroot().findall('./Collection/DataSet')
    last = max(float(d.get('timestep')) for d in sets)
    assert last == pytest.approx(s['loadingTime'], rel=1e-8)  # the .pvd keeps 9 digits
    files = [d.get('file') for d in sets if float(d.get('timestep')) == last]
    assert [os.path.basename(f).split('-')[0] for f in files] == ['grains', 'walls', 'contacts']
    piece = ET.parse(os.path.join(run.out, files[2])).getroot().find('./UnstructuredGrid/Piece')
    cells = {a.get('Name'): np.array(a.text.split(), dtype=float) for a in piece.findall('./CellData/DataArray')}
    assert int(piece.get('NumberOfCells')) == len(cells['Fn']) == len(yade.O.interactions.all(True)) > 0
    from ballast import harvest
    id1, id2, Fn, uN = harvest.contacts()  # the scene is still the one at the end
    np.testing.assert_allclose(cells['Fn'], Fn, rtol=1e-8)
    np.testing.assert_array_equal(cells['id1'], id1)
    types = np.array(piece.find("./Cells/DataArray[@Name='types']").text.split(), dtype=int)
    assert np.all(types == 3)  # VTK_LINE


def test_original_grains_are_sand_coloured(first):
    run = first[0]
    g = run.outputs.grains
    for b in yade.O.bodies:
        if b is not None and isinstance(b.shape, yade.wrapper.Sphere) and b.id < len(g.generation) \
                and g.generation[b.id] == 0 and g.nAbraded[b.id] == 0:
            assert tuple(b.shape.color) == pytest.approx(COLOR_ORIGINAL)


def test_identical_runs_give_identical_summaries(first, root):
    """maxProtrusion was sampled at wall-clock chunks: it differed between identical runs."""
    out = [Oedometer(results=str(root / ('same%d' % k)), runId='same', packingDir=str(root / 'packings'),
                     **SMALL).run() for k in (1, 2)]
    assert out[0]['packingReused'] and out[0]['maxProtrusion'] > 0
    assert summaryWithoutSeconds(out[0]) == summaryWithoutSeconds(out[1])


def checkKilled(out, root, name):
    """A killed run: every state under its final name loads, run.json says running, no summary; the rebuild from
    the last state writes outputs whose counts are the state's (steps continue across the resume)."""
    states = sorted(f for f in os.listdir(out) if f.startswith('state-'))
    assert states and not os.path.exists(os.path.join(out, 'summary.json'))
    for f in states:
        checkStateFile(os.path.join(out, f))
    with open(os.path.join(out, 'run.json')) as fh:
        status = json.load(fh)
    assert status['status'] == 'running' and status['lastState'] in states
    # a copy under another name whose run.json names an older state: the rebuild goes into the copy's name -2 (not
    # the run id the state holds) from the newest intact state (not the one run.json names)
    copy = out + '-copy'
    shutil.copytree(out, copy)
    older = sorted(states, key=lambda f: os.path.getmtime(os.path.join(out, f)))[0]
    with open(os.path.join(copy, 'run.json'), 'w') as fh:
        json.dump(dict(status, lastState=older), fh)
    p = subprocess.run([shutil.which('yade'), '-n', '-x', os.path.join(os.path.dirname(os.path.dirname(
        os.path.dirname(os.path.abspath(__file__)))), 'scripts', 'oedometer.py'), '--rebuild', copy],
        env=dict(os.environ, OMP_NUM_THREADS='1'), capture_output=True, text=True, timeout=TIMEOUT)
    assert p.returncode == 0, p.stdout[-2000:] + p.stderr[-2000:]
    rebuilt = copy + '-2'
    with open(os.path.join(rebuilt, 'summary.json')) as fh:
        s = json.load(fh)
    # the newest state, which a kill between its rename and run.json's update leaves one ahead of run.json's
    byTime = sorted(states, key=lambda f: os.path.getmtime(os.path.join(out, f)))
    assert status['lastState'] in byTime[-2:]
    last = Oedometer.reopen(os.path.join(out, byTime[-1]), readOnly=True)
    assert s['steps'] == yade.O.iter == sum(s['stepsByPhase'].values())  # every step since the start counted
    assert s['nCrushed'] == last.counter('crush', 'nCrushed') and s['nAbraded'] == last.counter('abrasion', 'nAbraded')
    fd = np.loadtxt(os.path.join(rebuilt, 'fd.csv'), delimiter=',', skiprows=1, ndmin=2)
    assert len(fd) == len(last.outputs.rows) and fd[-1, 3] == s['nCrushed']
    with open(os.path.join(rebuilt, 'events.csv')) as fh:
        assert len(fh.readlines()) - 1 == len(last.events())
    with open(os.path.join(rebuilt, 'run.json')) as fh:
        assert json.load(fh)['status'] == 'finished'


def test_sigkill_during_a_save(first, root, tmp_path):
    script = tmp_path / 'run.py'
    script.write_text(RUN)
    results = root / 'killedInSave'
    p = yadeRun(script, [results, root / 'packings', 4])
    p.communicate(timeout=TIMEOUT)
    assert p.returncode == -signal.SIGKILL
    out = str(results / 'killed')
    assert any(f.startswith('.tmp-') for f in os.listdir(out))  # the cut one, never under its final name
    checkKilled(out, root, 'killedInSave')


def test_sigkill_during_loading(first, root, tmp_path):
    script = tmp_path / 'run.py'
    script.write_text(RUN)
    results = root / 'killedInLoading'
    p = yadeRun(script, [results, root / 'packings', 0])
    out = str(results / 'killed')
    t0 = time.time()
    while time.time() - t0 < TIMEOUT:
        if os.path.isdir(out) and len([f for f in os.listdir(out) if f.startswith('state-iter')]) >= 3:
            break
        time.sleep(0.05)
    p.send_signal(signal.SIGKILL)
    p.communicate(timeout=TIMEOUT)
    assert p.returncode == -signal.SIGKILL
    # what a kill between a state's rename and run.json's update leaves (CI met it): run.json one state behind
    with open(os.path.join(out, 'run.json')) as fh:
        status = json.load(fh)
    byTime = sorted((f for f in os.listdir(out) if f.startswith('state-')), key=lambda f: os.path.getmtime(
        os.path.join(out, f)))
    with open(os.path.join(out, 'run.json'), 'w') as fh:
        json.dump(dict(status, lastState=byTime[-2]), fh)
    checkKilled(out, root, 'killedInLoading')


BAD_STATES = '''
import gzip, sys
from ballast.oedometer import Oedometer
good, folder = sys.argv[1], sys.argv[2]
data = open(good, 'rb').read()
inner = gzip.decompress(data)
cases = {'empty': b'', 'truncated': data[:len(data) // 2], 'plain': b'not gzip at all',
         'garbage': gzip.compress(bytes(range(256)) * 64), 'cutInside': gzip.compress(inner[:len(inner) // 3])}
for name, content in cases.items():
    path = '%s/%s.yade.gz' % (folder, name)
    open(path, 'wb').write(content)
    try:
        Oedometer.reopen(path, readOnly=True)
        print('LOADED', name)
    except Exception as e:
        print('ERROR %s %s: %s' % (name, type(e).__name__, str(e).replace(chr(10), ' | ')))
'''


def test_damaged_states_are_refused_naming_the_file_and_the_cause(first, tmp_path):
    script = tmp_path / 'bad.py'
    script.write_text(BAD_STATES)
    p = subprocess.run([shutil.which('yade'), '-n', '-x', str(script), os.path.join(first[0].out, 'state-start.yade.gz'),
                        tmp_path], env=dict(os.environ, OMP_NUM_THREADS='1'), capture_output=True, text=True,
                       timeout=TIMEOUT)
    lines = {l.split()[1]: l for l in p.stdout.splitlines() if l.startswith(('ERROR', 'LOADED'))}
    causes = {'empty': 'empty', 'truncated': 'cut short', 'plain': 'not gzip', 'garbage': 'not a YADE state',
              'cutInside': 'YADE could not read it'}
    for name, cause in causes.items():
        assert name in lines, p.stdout[-3000:] + p.stderr[-3000:]
        assert 'StateFileError' in lines[name] and str(tmp_path / (name + '.yade.gz')) in lines[name], lines[name]
        assert cause in lines[name] and ' | ' not in lines[name], lines[name]


def test_rebuild_takes_no_other_option(tmp_path):
    """--rebuild writes the saved run's outputs as the run was: an option beside it would be ignored, so it is
    refused in one line before any work."""
    p = subprocess.run([shutil.which('yade'), '-n', '-x', os.path.join(os.path.dirname(os.path.dirname(
        os.path.dirname(os.path.abspath(__file__)))), 'scripts', 'oedometer.py'), '--rebuild', str(tmp_path),
        '--ft0', '1e6'], env=dict(os.environ, OMP_NUM_THREADS='1'), capture_output=True, text=True, timeout=TIMEOUT)
    lines = [ln for ln in p.stderr.splitlines() if ln.startswith('oedometer.py:')]
    assert p.returncode == 2 and len(lines) == 1 and '--rebuild takes no other option (got --ft0)' in lines[0]
