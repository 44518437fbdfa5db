"""The set-up's promises: `import ballast` works from any directory, in Debian's /usr/bin/python3 and
in yade, with no environment variable; a second set-up installs nothing and rebuilds nothing."""
import os
import subprocess

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CLEAN_ENV = {k: v for k, v in os.environ.items() if k not in ('PYTHONPATH', 'PYTHONHOME')}
CLEAN_ENV['OMP_NUM_THREADS'] = '1'


def run(cmd, cwd, timeout=120):
    return subprocess.run(cmd, cwd=cwd, env=CLEAN_ENV, capture_output=True, text=True, timeout=timeout)


def test_import_in_debian_python_from_any_directory(tmp_path):
    r = run(['/usr/bin/python3', '-c', 'import ballast, math; '
             'print(ballast.__file__); print(ballast.vonMises([[1.,0,0],[0,0,0],[0,0,0]]))'], tmp_path)
    assert r.returncode == 0, r.stderr
    path, value = r.stdout.split()
    assert path.startswith('/usr/local/lib/python3') and not path.startswith(ROOT)
    assert float(value) == pytest.approx(1.0, abs=1e-15)


def test_import_in_yade_from_any_directory(tmp_path):
    script = tmp_path / 's.py'
    script.write_text('import ballast\nfrom ballast.engines import BallastCrushEngine\n'
                      'e = BallastCrushEngine(ft0=2.0)\nprint("FT0", e.ft0, ballast.__file__)\n')
    r = run(['yade', '-n', '-x', str(script)], tmp_path)
    assert r.returncode == 0, r.stderr
    line = [ln for ln in r.stdout.splitlines() if ln.startswith('FT0')][0]
    assert line.split()[1] == '2.0' and '/usr/local/lib/python3' in line


def test_the_outputs_readers_are_installed(tmp_path):
    """The set-up installs what the outputs are meant for: pandas (the CSV files) and VTK (the .vtu frames)."""
    for p in ('python3-pandas', 'python3-vtk9'):
        assert p in open(os.path.join(ROOT, 'setup.sh')).read().split('PACKAGES=(')[1].split(')')[0].split()
    r = run(['/usr/bin/python3', '-c', 'import pandas, vtk; print(pandas.__version__, vtk.vtkVersion.GetVTKVersion())'],
            tmp_path)
    assert r.returncode == 0, r.stderr


def test_the_test_runner_finds_its_workers(tmp_path):
    """tests/run_all.sh runs pytest with a worker per core (-n auto): the set-up installs pytest-xdist for it."""
    runner = open(os.path.join(ROOT, 'tests', 'run_all.sh')).read()
    assert '-n auto' in runner
    assert 'python3-pytest-xdist' in open(os.path.join(ROOT, 'setup.sh')).read().split('PACKAGES=(')[1].split(')')[0].split()
    r = run(['/usr/bin/python3', '-m', 'pytest', '--version', '-p', 'xdist'], tmp_path)
    assert r.returncode == 0, r.stderr


@pytest.mark.skipif(os.geteuid() != 0, reason='set-up installs as root')
def test_second_setup_installs_and_rebuilds_nothing(tmp_path):
    r = run(['bash', os.path.join(ROOT, 'setup.sh')], tmp_path, timeout=600)
    assert r.returncode == 0, r.stderr
    assert 'installing' not in r.stdout and 'packages present' in r.stdout
    assert 'Building CXX' not in r.stdout and 'Linking' not in r.stdout
    assert 'Installing:' not in r.stdout        # cmake --install copies nothing that is up to date
