"""End-to-end tests of scripts/oedometer.py (the paper's oedometric test, sections 4-5), run as the
user runs it: `yade -n -x scripts/oedometer.py --<reduced parameters>` in a subprocess writing to
a temporary directory, then the result files are read and physical invariants asserted.

Reduced test: a 150 mm cylinder 80 mm high (about 20 grains of the paper's sizes), one loading
cycle with the paper's Fmax = 1500 kN (so the stresses are higher than in the paper's 300 mm
cylinder and grains crush readily). Two loading runs share one packing: a run with unreachable
strengths at f = 20 Hz (no grain may degrade, the force must follow eq. 8; driven through a
yade-batch table) and one with low strengths at f = 50 Hz (grains must crush and abrade). About
30 s of CPU in all on an idle 2-core machine.
"""
import csv
import glob
import json
import math
import os
import shutil
import subprocess

import numpy as np
import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPT = os.path.join(ROOT, 'scripts', 'oedometer.py')
TIMEOUT = 300  # [s] per yade run: a hang fails the test instead of blocking CI

# the reduced test
DIAMETER, HEIGHT, SEGMENTS = 0.15, 0.08, 48   # [m], [m], [-]
F_STRONG, F_WEAK, FMAX = 20.0, 50.0, 1.5e6   # [Hz], [Hz], [N]
SMALL = ['--diameter', str(DIAMETER), '--height', str(HEIGHT), '--vMax', '5', '--samples', '1000', '--progress', '60']
DENSITY = 2600.0                              # [kg/m^3] the script's default ballast density

# tolerances, each with its reason
TOL_MASS = 1e-9         # [-] relative: the mass ledger is exact arithmetic, rounding only
TOL_FORCE_RMS = 0.03    # [-] of Fmax: RMS of F - eq. 8 over the cycle without crushing (servo lag, grain slips)
TOL_FORCE_BAND = 0.05   # [-] of Fmax: band around eq. 8 ...
FRACTION_IN_BAND = 0.95  # ... holding at least this fraction of the samples once loading started
TOL_PEAK = 0.02         # [-] of Fmax: the largest measured force reaches eq. 8's peak
TOL_OUTSIDE = 1e-3      # [m] a grain may press into the steel by its elastic overlap (about 0.1 mm), not more


def yadeEnv():
    env = dict(os.environ, OMP_NUM_THREADS='1')
    env.pop('YADE_BATCH', None)
    probe = subprocess.run(['/usr/bin/python3', '-c', 'import ballast._ballast'], env=env, capture_output=True)
    build = os.path.join(ROOT, 'build', 'py')
    if probe.returncode != 0 and os.path.isdir(build):  # not installed: use the build tree
        env['PYTHONPATH'] = build + os.pathsep + env.get('PYTHONPATH', '')
    return env


ENV = yadeEnv()
pytestmark = pytest.mark.skipif(shutil.which('yade') is None, reason='needs yade')


def yade(args, env=None, cwd=None):
    return subprocess.run(['yade', '-n', '-x', SCRIPT] + [str(a) for a in args], env=env or ENV, cwd=cwd,
                          capture_output=True, text=True, timeout=TIMEOUT)


def runDirs(results):
    return [d for d in glob.glob(os.path.join(results, '*')) if os.path.basename(d) != 'packings']


def load(outDir):
    with open(os.path.join(outDir, 'summary.json')) as fh:
        s = json.load(fh)
    with open(os.path.join(outDir, 'fd.csv')) as fh:
        header = fh.readline().strip()
    fd = np.loadtxt(os.path.join(outDir, 'fd.csv'), delimiter=',', skiprows=1, ndmin=2)
    with open(os.path.join(outDir, 'events.csv')) as fh:
        events = list(csv.DictReader(fh))
    grains = np.loadtxt(os.path.join(outDir, 'grains.csv'), delimiter=',', skiprows=1, ndmin=2)
    return s, header, fd, events, grains


def eq8(t, f):
    return FMAX / 2 * (np.sin(2 * np.pi * f * t - np.pi / 2) + 1)


@pytest.fixture(scope='module')
def root(tmp_path_factory):
    return str(tmp_path_factory.mktemp('oedometer'))


@pytest.fixture(scope='module')
def strong(root):
    """Unreachable strengths, parameters from a yade-batch table (readParamsFromTable), results and
    packing directories from the command line: no grain may crush or abrade."""
    table = os.path.join(root, 'strong.table')
    with open(table, 'w') as fh:
        fh.write('seed! f! ft0 strength diameter height\n1 %g 1e12 1e15 %g %g\n' % (F_STRONG, DIAMETER, HEIGHT))
    env = dict(ENV, YADE_BATCH=table + ':2')  # what yade-batch sets for the row on line 2
    results = os.path.join(root, 'strong')
    p = yade(SMALL + ['--results', results, '--packingDir', os.path.join(root, 'packings')], env=env)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    dirs = runDirs(results)
    assert len(dirs) == 1, dirs
    return (dirs[0],) + load(dirs[0])


@pytest.fixture(scope='module')
def weak(root, strong):
    """Low strengths on the packing the strong run stored: grains must crush and abrade."""
    results = os.path.join(root, 'weak')
    p = yade(SMALL + ['--f', F_WEAK, '--ft0', 5e5, '--strength', 1.5e10, '--results', results, '--runId', 'weak',
                      '--packingDir', os.path.join(root, 'packings')])
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    return (os.path.join(results, 'weak'),) + load(os.path.join(results, 'weak'))


# ------------------------------------------------------------------------------------ outputs
def test_batch_table_names_the_run_and_sets_parameters(strong):
    outDir, s, header, fd, events, grains = strong
    # yade-batch's run id: the description (the !-columns) then O.tags['id']
    assert os.path.basename(outDir).startswith('seed=1,f=%g.' % F_STRONG)
    assert s['params']['f'] == F_STRONG and s['params']['ft0'] == 1e12 and s['params']['strength'] == 1e15
    assert s['params']['diameter'] == DIAMETER and s['params']['height'] == HEIGHT
    for name in ('fd.csv', 'events.csv', 'summary.json', 'fd.png', 'grains.csv'):
        assert os.path.getsize(os.path.join(outDir, name)) > 0, name
    for key in ('peakForce', 'deltaAtPeak', 'deltaMax', 'nCrushed', 'nAbraded', 'volumeLost', 'massInitial', 'massFinal',
                'massLost', 'wallSeconds', 'steps'):
        assert key in s, key
    assert header == 't,F,delta,nCrushed,nAbraded'


def test_fd_covers_one_cycle(strong):
    _, s, _, fd, _, _ = strong
    t = fd[:, 0]
    T = 1 / F_STRONG
    assert t[0] == pytest.approx(0.0, abs=1e-12)
    assert np.all(np.diff(t) > 0)
    assert t[-1] == pytest.approx(T, rel=1e-3)  # one full cycle, load and unload
    assert len(t) >= 900  # samples = 1000 per cycle


def test_force_follows_eq8(strong):
    """Without crushing the plate force on the grains follows eq. 8: RMS error within 3 % of Fmax,
    95 % of the samples within 5 % of Fmax once loading started (t > 5 % of the cycle; before that
    the plate is still seating on the grains), and the peak within 2 % of Fmax."""
    _, s, _, fd, _, _ = strong
    t, Fm = fd[:, 0], fd[:, 1]
    err = np.abs(Fm - eq8(t, F_STRONG)) / FMAX
    loaded = t > 0.05 / F_STRONG
    assert math.sqrt(np.mean(err[loaded]**2)) <= TOL_FORCE_RMS
    assert np.mean(err[loaded] <= TOL_FORCE_BAND) >= FRACTION_IN_BAND
    assert s['peakForce'] == pytest.approx(FMAX, abs=TOL_PEAK * FMAX)
    assert np.all(Fm >= 0)  # a plate only pushes


def test_plate_moves_down_under_load(strong):
    _, s, _, fd, _, _ = strong
    delta = fd[:, 2]
    assert s['deltaMax'] > 0
    assert s['deltaMax'] == pytest.approx(np.max(delta), rel=1e-9)
    assert s['deltaAtPeak'] == pytest.approx(delta[np.argmax(fd[:, 1])], rel=1e-9)
    assert s['deltaMax'] < HEIGHT  # the plate stays above the bottom


def test_no_degradation_with_unreachable_strength(strong):
    _, s, _, fd, events, grains = strong
    assert s['nCrushed'] == 0 and s['nAbraded'] == 0
    assert events == []
    assert np.all(fd[:, 3] == 0) and np.all(fd[:, 4] == 0)
    assert s['massLost'] == 0.0 and s['volumeLost'] == 0.0
    assert s['massFinal'] == pytest.approx(s['massInitial'], rel=TOL_MASS)
    assert len(grains) == s['nGrainsInitial']


# ------------------------------------------------------------------------------------ crushing
def test_low_strength_crushes_and_abrades(weak):
    _, s, _, fd, events, grains = weak
    assert s['nCrushed'] >= 1
    assert s['nAbraded'] >= 1
    assert fd[-1, 3] == s['nCrushed'] and fd[-1, 4] == s['nAbraded']
    assert np.all(np.diff(fd[:, 3]) >= 0) and np.all(np.diff(fd[:, 4]) >= 0)  # counters only grow
    kinds = [e['kind'] for e in events]
    assert kinds.count('crush') == s['nCrushed'] and kinds.count('abrasion') == s['nAbraded']


def test_events_obey_the_criteria(weak):
    """Eq. 1 with eq. 4 (m = 1): a crushed grain had sigma_e > f_t = ft0 / r; eq. 6: an abraded
    grain had p0 > strength; neither below rMin; pattern 6 adds 6 fragments per crushed grain."""
    _, s, _, _, events, _ = weak
    ft0, strength, rMin = s['params']['ft0'], s['params']['strength'], s['params']['rMin']
    for e in events:
        r, value, limit = float(e['radius']), float(e['value']), float(e['strength'])
        assert r >= rMin
        assert 0 <= float(e['t']) <= 1 / F_WEAK * (1 + 1e-9)
        if e['kind'] == 'crush':
            assert limit == pytest.approx(ft0 / r, rel=1e-9)
            assert value > limit
            assert len(e['newIds'].split()) == 6
        else:
            assert limit == pytest.approx(strength, rel=1e-12)
            assert value > limit


def test_mass_ledger(weak):
    """massInitial = massFinal + massLost, to rounding; the lost mass is the lost volume times the
    density; the grains left weigh massFinal."""
    _, s, _, _, _, grains = weak
    assert s['massLost'] > 0
    assert s['massInitial'] == pytest.approx(s['massFinal'] + s['massLost'], rel=TOL_MASS)
    assert s['massLost'] == pytest.approx(DENSITY * s['volumeLost'], rel=1e-6)
    assert np.sum(grains[:, 5]) == pytest.approx(s['massFinal'], rel=1e-6)
    # one grain out, six fragments in, per crush (pattern 6); abrasion keeps the count
    assert len(grains) == s['nGrainsInitial'] + 5 * s['nCrushed']


def test_packing_reused(strong, weak):
    assert not strong[1]['packingReused']
    assert weak[1]['packingReused']
    assert weak[1]['packingFile'] == strong[1]['packingFile']
    assert weak[1]['nGrainsInitial'] == strong[1]['nGrainsInitial']
    assert weak[1]['massInitial'] == pytest.approx(strong[1]['massInitial'], rel=1e-12)


@pytest.mark.parametrize('which', ['strong', 'weak'])
def test_no_grain_leaves_the_cylinder(which, request):
    """During the run (checked by the script at every chunk) and at the end (grains.csv): no
    centre outside the steel and no grain pressing into it by more than an elastic overlap."""
    _, s, _, _, _, grains = request.getfixturevalue(which)
    assert s['nEscaped'] == 0
    assert s['maxProtrusion'] <= TOL_OUTSIDE
    Rv = DIAMETER / 2 / math.cos(math.pi / SEGMENTS)  # the facets' corners
    x, y, z, r = grains[:, 1], grains[:, 2], grains[:, 3], grains[:, 4]
    zPlate = s['plateHeight0'] - s['deltaFinal']
    assert np.all(np.hypot(x, y) + r <= Rv + TOL_OUTSIDE)
    assert np.all(z - r >= -TOL_OUTSIDE)
    assert np.all(z + r <= zPlate + TOL_OUTSIDE)


# ------------------------------------------------------------------------------------ parameters
def test_help_lists_the_parameters():
    p = yade(['--help'])
    assert p.returncode == 0
    for name in ('--f ', '--pattern', '--ft0', '--rMin', '--Tc', '--strength', '--gamma', '--seed', '--results'):
        assert name in p.stdout, name
    assert '[Pa m]' in p.stdout and '[Hz]' in p.stdout


@pytest.mark.parametrize('args,name', [
    (['--f', '-1'], 'f'),
    (['--pattern', '5'], 'pattern'),
    (['--rMin', '0.05'], 'rMin'),          # larger than the largest grain (dMax/2 = 22.25 mm)
    (['--ft0', 'abc'], 'ft0'),
    (['--gamma', '1.2'], 'gamma'),
])
def test_bad_parameter_stops_before_any_work(args, name, tmp_path):
    results = str(tmp_path / 'results')
    p = yade(args + ['--results', results])
    assert p.returncode != 0
    assert ('bad parameter %s:' % name) in p.stderr
    assert not os.path.exists(results)  # nothing written: stopped before any work


def test_bad_table_cell_names_the_column(tmp_path):
    table = str(tmp_path / 'bad.table')
    with open(table, 'w') as fh:
        fh.write('seed pattern\n1 planar5\n')
    p = yade(['--results', str(tmp_path / 'results')], env=dict(ENV, YADE_BATCH=table + ':2'))
    assert p.returncode != 0
    assert 'bad parameter pattern:' in p.stderr
