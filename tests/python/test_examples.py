"""The examples/ a YADE user starts from, each run as a user runs it: the three scenes in yade (one grain
crushed between two walls, grains in a box under a plate, the engines in a triaxial cell), and a small oedometer run read with pandas and
coloured by state for ParaView (ParaView's Python replaced by a stand-in that reads the files with
Debian's VTK, python3-vtk9, and records the calls)."""
import importlib.util
import os
import re
import shutil
import subprocess
import sys
import textwrap

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EXAMPLES = os.path.join(ROOT, 'examples')
ENV = dict(os.environ, OMP_NUM_THREADS='1')


def yade(args, cwd, timeout=600):
    r = subprocess.run(['yade', '-n', '-x'] + [str(a) for a in args], cwd=cwd, env=ENV, capture_output=True, text=True,
                       timeout=timeout)
    assert r.returncode == 0, r.stdout[-2000:] + r.stderr[-2000:]
    return r.stdout


def example(name):
    spec = importlib.util.spec_from_file_location(name, os.path.join(EXAMPLES, name + '.py'))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_every_example_is_tested_and_documented():
    tested = {'single_grain', 'box_under_plate', 'triaxial_cell', 'read_run_with_pandas', 'paraview_colour_by_state',
              'angular_clumps'}
    found = {f[:-3] for f in os.listdir(EXAMPLES) if f.endswith('.py')}
    assert found == tested
    for name in found:
        text = open(os.path.join(EXAMPLES, name + '.py')).read()
        assert text.startswith('"""') and 'examples/%s.py' % name in text   # says how to run it
    readme = open(os.path.join(EXAMPLES, 'README.md')).read()
    assert all(name + '.py' in readme for name in found)


def test_one_grain_crushes_between_two_walls_at_its_strength(tmp_path):
    out = yade([os.path.join(EXAMPLES, 'single_grain.py')], tmp_path)
    # r = 0.02 m, ft0 = 2e5 Pa m: f_t = ft0 / r = 1e7 Pa; checked every step, it crushes as sigma_e passes f_t
    assert 'strength f_t = ft0/r = 1e+07 Pa' in out, out[-1000:]
    m = re.search(r'sigma_e = ([\d.]+) Pa > f_t = ([\d.]+) Pa', out)
    assert m and float(m[2]) == 1e7 and 1 < float(m[1]) / 1e7 < 1.01, out[-1000:]
    assert re.search(r'^6 fragments \[', out, re.M), out[-1000:]


def test_grains_in_a_box_under_a_plate_crush_and_abrade(tmp_path):
    out = yade([os.path.join(EXAMPLES, 'box_under_plate.py')], tmp_path)
    m = re.search(r'box_under_plate: (\d+) steps, plate at z = ([\d.]+) m, (\d+) crushed, (\d+) abraded', out)
    assert m, out[-1000:]
    steps, z, crushed, abraded = int(m[1]), float(m[2]), int(m[3]), int(m[4])
    assert steps == 20000 and 0 < crushed < 64 and abraded > 0
    assert 0.04 < z < 0.085      # the plate rests on the grains (box height 0.08 m), it did not fall through


def test_the_engines_in_a_triaxial_cell(tmp_path):
    out = yade([os.path.join(EXAMPLES, 'triaxial_cell.py'), 4000], tmp_path)
    m = re.search(r'axial strain ([\d.]+), sigma_axial ([\d.e+-]+) Pa, sigma_lateral ([\d.e+-]+) Pa, (\d+) crushed, '
                  r'(\d+) abraded', out)
    assert m, out[-1000:]
    strain, axial, lateral, crushed, abraded = float(m[1]), float(m[2]), float(m[3]), int(m[4]), int(m[5])
    assert 0.001 < strain < 0.05 and lateral == pytest.approx(1e5, rel=0.05) and axial > lateral
    assert crushed + abraded > 0


@pytest.fixture(scope='module')
def run(tmp_path_factory):
    """A small oedometer run with VTK frames, crushes and abrasions (a few seconds)."""
    d = tmp_path_factory.mktemp('oedometer')
    yade([os.path.join(ROOT, 'scripts', 'oedometer.py'), '--diameter', 0.1, '--height', 0.06, '--f', 50, '--young', 3e9,
          '--Fmax', 2e4, '--depTime', 0.3, '--samples', 20, '--vtk', 0.004, '--ft0', 3e5, '--rMin', 0.006,
          '--strength', 1e8, '--results', d, '--runId', 'r', '--packingDir', d / 'packings'], d)
    return str(d / 'r')


def test_reading_a_run_with_pandas(run, capsys):
    frames, summary = example('read_run_with_pandas').main(run)
    fd, events, grains = frames['fd'], frames['events'], frames['grains']
    out = capsys.readouterr().out
    kinds = events['kind'].value_counts().to_dict()
    assert kinds.get('crush', 0) == summary['nCrushed'] > 0 and kinds.get('abrasion', 0) == summary['nAbraded'] > 0
    assert fd['F'].max() == pytest.approx(summary['peakGrainForce'], rel=1e-6)
    assert grains['mass'].sum() == pytest.approx(summary['massFinal'], rel=1e-6)
    assert set(grains['generation']) <= set(range(10)) and grains.index.is_unique
    assert 'events by kind' in out and 'grains by generation' in out and 'mass lost' in out


def test_reading_runs_of_every_experiment_with_pandas(tmp_path, capsys):
    """The same example on a box record, a triaxial record and a single-particle run (each names its experiment in
    summary.json): every CSV as a DataFrame, counts as the summary says; a folder that is not a run, one line."""
    read = example('read_run_with_pandas')
    frames, summary = read.main(os.path.join(ROOT, 'docs', 'studies', 'box', 'runs', 'box-seed1-c100'))
    assert summary['experiment'] == 'box' and len(frames['cycles']) == summary['cycles'] == 100
    assert frames['cycles'].settlement.iloc[-1] == pytest.approx(summary['settlement'], rel=1e-8)
    frames, summary = read.main(os.path.join(ROOT, 'docs', 'studies', 'triax-calib-a', 'runs', 'a-rf30'))
    assert summary['experiment'] == 'triaxial' and frames['cycles'].axialStrain.iloc[-1] == pytest.approx(
        summary['axialStrain'], rel=1e-8)
    yade([os.path.join(ROOT, 'scripts', 'single_particle.py'), '--n', 4, '--results', tmp_path, '--runId', 's'],
         tmp_path)
    frames, summary = read.main(str(tmp_path / 's'))
    assert summary['experiment'] == 'single_particle' and len(frames['strengths']) == summary['n'] == 4
    assert 'single_particle run s' in capsys.readouterr().out
    p = subprocess.run(['/usr/bin/python3', os.path.join(EXAMPLES, 'read_run_with_pandas.py'), str(tmp_path)],
                       capture_output=True, text=True, env=dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path)))
    assert p.returncode == 1 and p.stderr.strip().count('\n') == 0 and 'no summary.json' in p.stderr


STANDIN = '''
"""A stand-in for paraview.simple: reads the files with VTK and records every call in CALLS."""
import vtk
CALLS = []


class Proxy:
    def __init__(self, name, **kw):
        self.__dict__.update(kw)
        CALLS.append((name, kw))

    def __getattr__(self, name):
        def method(*a, **kw):
            CALLS.append((name, a, kw))
        return method


class Arrays:
    def __init__(self, path):
        reader = vtk.vtkXMLUnstructuredGridReader()
        reader.SetFileName(path)
        reader.Update()
        data = reader.GetOutput().GetPointData()
        self.names = [data.GetArrayName(i) for i in range(data.GetNumberOfArrays())]
        self.points = reader.GetOutput().GetNumberOfPoints()

    def keys(self):
        return self.names


def XMLUnstructuredGridReader(FileName):
    p = Proxy('XMLUnstructuredGridReader', FileName=FileName)
    p.PointData = Arrays(FileName[-1])
    p.TimestepValues = list(range(len(FileName)))
    return p


def Glyph(Input, GlyphType):
    return Proxy('Glyph', Input=Input, GlyphType=GlyphType)


def GetActiveViewOrCreate(kind):
    return Proxy('View', kind=kind)


def Show(source, view):
    CALLS.append(('Show', source.GlyphType, source.ScaleArray, source.ScaleFactor))
    return Proxy('Display')


def ColorBy(display, what):
    CALLS.append(('ColorBy', what))


def GetAnimationScene():
    return Proxy('AnimationScene')


def SaveScreenshot(path, view, ImageResolution):
    open(path, 'w').write('png')
    CALLS.append(('SaveScreenshot', path))
'''


@pytest.fixture
def paraview(tmp_path, monkeypatch):
    pkg = tmp_path / 'standin' / 'paraview'
    pkg.mkdir(parents=True)
    (pkg / '__init__.py').write_text('')
    (pkg / 'simple.py').write_text(textwrap.dedent(STANDIN))
    monkeypatch.syspath_prepend(str(tmp_path / 'standin'))
    for m in [m for m in sys.modules if m == 'paraview' or m.startswith('paraview.')]:
        monkeypatch.delitem(sys.modules, m)
    import paraview.simple
    return paraview.simple


@pytest.mark.parametrize('array', ['generation', 'nAbraded'])
def test_colouring_by_state_for_paraview(run, paraview, tmp_path, array):
    png = str(tmp_path / 'grains.png')
    assert example('paraview_colour_by_state').main(run, array, png) == png
    calls = paraview.CALLS
    reader = [c for c in calls if c[0] == 'XMLUnstructuredGridReader'][0][1]
    frames = sorted(f for f in os.listdir(os.path.join(run, 'vtk')) if f.startswith('grains-'))
    assert [os.path.basename(f) for f in reader['FileName']] == frames and len(frames) > 2
    assert ('Show', 'Sphere', ['POINTS', 'r'], 2.0) in calls and ('ColorBy', ('POINTS', array)) in calls
    assert ('SaveScreenshot', png) in calls and os.path.exists(png)
    # the arrays the example relies on are in the grains' files
    names = paraview.Arrays(os.path.join(run, 'vtk', frames[-1])).keys()
    assert {'r', 'generation', 'nAbraded', 'stressRatio', 'damage'} <= set(names)


def test_colouring_by_an_unknown_state_names_the_choices(run, paraview):
    with pytest.raises(SystemExit, match="ARRAY: expected one of generation, nAbraded, stressRatio, damage, got 'colour'"):
        example('paraview_colour_by_state').main(run, 'colour')


@pytest.mark.parametrize('name,arg,words', [('triaxial_cell', 'abc', "invalid int value: 'abc'"),
                                            ('box_under_plate', '-5', 'steps = -5; allowed: an integer >= 1'),
                                            ('single_grain', '7', 'unrecognized arguments: 7')])
def test_an_examples_bad_argument_is_refused_before_work(name, arg, words, tmp_path):
    p = subprocess.run([shutil.which('yade'), '-n', '-x', os.path.join(EXAMPLES, name + '.py'), arg], cwd=tmp_path,
                       capture_output=True, text=True, timeout=120, env=dict(os.environ, OMP_NUM_THREADS='1'))
    errors = [ln for ln in p.stderr.splitlines() if 'error:' in ln]
    assert p.returncode == 2 and len(errors) == 1 and words in errors[0], p.stderr[-1000:]


def test_angular_clump_templates_fill_their_hulls_and_read_as_a_clump_file(tmp_path):
    """The templates hang together (the clump file's reader accepts them), number as asked, and more spheres fill
    more of each hull (sharper corners: 8 against 30 spheres, the same hulls from the same seed); a bad argument is
    refused before any work."""
    from ballast.templatefile import readTemplates
    out = {}
    for n in (8, 30):
        path = tmp_path / ('shapes%d.csv' % n)
        r = subprocess.run([sys.executable, os.path.join(EXAMPLES, 'angular_clumps.py'), str(path), '--templates', '3',
                            '--spheres', str(n), '--seed', '2'], capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
        t = readTemplates(str(path))
        assert [len(radii) for _, _, radii in t] == [n] * 3
        out[n] = [float(m) / 100 for m in re.findall(r'(\d+) % of its hull filled', r.stdout)]
        assert len(out[n]) == 3
    assert all(a < b for a, b in zip(out[8], out[30])), out
    r = subprocess.run([sys.executable, os.path.join(EXAMPLES, 'angular_clumps.py'), str(tmp_path / 'x.csv'),
                        '--flatness', '0'], capture_output=True, text=True)
    assert r.returncode == 2 and '--flatness 0.0: expected in (0, 1]' in r.stderr
