"""The Debian package: `cpack -G DEB` of setup.sh's build (CMakeLists.txt; it installs under /usr)
gives yade-ballast_<version>_<arch>.deb, whose control file depends on Debian's yade and the Boost libraries the binding links, which apt accepts
next to the installed yade (a simulated install), and whose files, unpacked into a temporary root,
give a working `from ballast import BallastCrushEngine` in yade. Nothing is installed on this machine:
the /usr/local install the other tests use stays as it is."""
import os
import re
import shutil
import subprocess

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BUILD = os.path.join(ROOT, 'build')    # setup.sh's: the .deb packs the build the other tests run (no second compile)
SITE = 'usr/lib/python3/dist-packages'
ENV = {k: v for k, v in os.environ.items() if k not in ('PYTHONPATH', 'PYTHONHOME')}
ENV['OMP_NUM_THREADS'] = '1'

pytestmark = pytest.mark.skipif(not (shutil.which('cpack') and shutil.which('dpkg-deb')), reason='needs cpack and dpkg-deb')


def run(cmd, cwd=ROOT, timeout=1800, env=ENV):
    r = subprocess.run([str(c) for c in cmd], cwd=cwd, env=env, capture_output=True, text=True, timeout=timeout)
    assert r.returncode == 0, '%s\n%s\n%s' % (' '.join(map(str, cmd)), r.stdout[-3000:], r.stderr[-3000:])
    return r.stdout


@pytest.fixture(scope='module')
def deb(tmp_path_factory):
    out = tmp_path_factory.mktemp('deb')
    assert os.path.exists(os.path.join(BUILD, 'CPackConfig.cmake')), 'build/ is made by setup.sh before the tests'
    run(['cpack', '-G', 'DEB', '-B', out], cwd=BUILD)
    debs = [f for f in os.listdir(out) if f.endswith('.deb')]
    assert len(debs) == 1, debs
    return out / debs[0]


def control(deb):
    text = run(['dpkg-deb', '-f', deb])
    return dict(re.findall(r'^(\S+): (.*)$', text, re.M))


def test_the_package_is_named_and_depends_on_debians_yade(deb):
    c = control(deb)
    version = re.search(r'project\(ballast VERSION ([\d.]+)', open(os.path.join(ROOT, 'CMakeLists.txt')).read())[1]
    arch = run(['dpkg', '--print-architecture']).strip()
    assert deb.name == 'yade-ballast_%s_%s.deb' % (version, arch)
    assert (c['Package'], c['Version'], c['Architecture']) == ('yade-ballast', version, arch)
    depends = [d.strip() for d in c['Depends'].split(',')]
    assert 'yade' in depends and 'python3-numpy' in depends
    # the Boost.Python libraries the binding links, by their Debian names
    libs = run(['ldd', os.path.join(BUILD, '_ballast.so')])
    for lib in ('python', 'numpy'):
        soname = re.search(r'libboost_%s3\d*\.so\.([\d.]+)' % lib, libs)[1]
        assert 'libboost-%s%s' % (lib, soname) in depends
    assert 'python3-pandas' in c['Recommends'] and 'python3-vtk9' in c['Recommends']


def test_the_package_holds_the_python_package_and_the_examples(deb):
    files = set(re.findall(r' \./(\S+)$', run(['dpkg-deb', '-c', deb]), re.M))
    src = os.path.join(ROOT, 'py', 'ballast')
    modules = {os.path.relpath(os.path.join(d, f), src) for d, _, fs in os.walk(src) for f in fs if f.endswith('.py')}
    assert {'%s/ballast/%s' % (SITE, m) for m in modules} <= files
    assert '%s/ballast/_ballast.so' % SITE in files
    examples = {f for f in os.listdir(os.path.join(ROOT, 'examples')) if f.endswith(('.py', '.md'))}
    assert {'usr/share/doc/yade-ballast/examples/%s' % f for f in examples} <= files
    assert not [f for f in files if f.startswith('usr/local') or '__pycache__' in f]


@pytest.mark.skipif(not shutil.which('apt-get'), reason='needs apt-get')
def test_apt_would_install_it_next_to_debians_yade(deb):
    out = run(['apt-get', 'install', '--simulate', '--no-install-recommends', str(deb)], cwd=deb.parent)
    assert re.search(r'^Inst yade-ballast ', out, re.M), out
    assert not re.search(r'^(Remv|Inst) yade ', out, re.M)   # Debian's yade stays as it is


def test_yade_imports_the_unpacked_package(deb, tmp_path):
    root = tmp_path / 'root'
    run(['dpkg-deb', '-x', deb, root])
    script = tmp_path / 'imp.py'
    script.write_text('import ballast\nfrom ballast import BallastCrushEngine\ne = BallastCrushEngine(ft0=2.0)\n'
                      'print("FT0", e.ft0, ballast.__file__, ballast._ballast.__file__)\n')
    out = run(['yade', '-n', '-x', script], cwd=tmp_path, env=dict(ENV, PYTHONPATH=str(root / SITE)))
    line = [ln for ln in out.splitlines() if ln.startswith('FT0')][0].split()
    assert line[1] == '2.0'
    assert all(p.startswith(str(root / SITE / 'ballast')) for p in line[2:])
