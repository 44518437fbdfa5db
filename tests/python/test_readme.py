"""The README's YADE examples run as they are written: the engines block in a yade process (one
grain crushed into six fragments: volume and mass lost by hand), and the experiment block's
constructor with its parameters."""
import math
import os
import re
import shutil
import subprocess

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
R, DENSITY = 0.02, 2600.0   # [m], [kg/m^3]: the grain of the example, ballastMaterial()'s density


def block(after):
    """The first ```python block after the heading line `after`."""
    with open(os.path.join(ROOT, 'README.md')) as fh:
        text = fh.read()
    return re.search(r'```python\n(.*?)```', text[text.index(after):], re.S).group(1)


@pytest.mark.skipif(shutil.which('yade') is None, reason='needs yade')
def test_use_in_yade_block_runs_verbatim(tmp_path):
    from ballast import keptVolumeFraction
    script = tmp_path / 'example.py'
    script.write_text(block('## Use in YADE'))
    p = subprocess.run([shutil.which('yade'), '-n', '-x', str(script)], capture_output=True, text=True, timeout=120,
                       cwd=str(tmp_path), env=dict(os.environ, OMP_NUM_THREADS='1'))
    assert p.returncode == 0, p.stdout[-2000:] + p.stderr[-2000:]
    line = [l for l in p.stdout.splitlines() if re.match(r'^\d+ \S+ \S+ \d+$', l)][-1].split()
    nCrushed, volumeLost, massLost, nAbraded = int(line[0]), float(line[1]), float(line[2]), int(line[3])
    assert nCrushed == 1 and nAbraded == 0
    lost = (1 - keptVolumeFraction(6)) * 4 / 3 * math.pi * R ** 3
    assert volumeLost == pytest.approx(lost, rel=1e-9)
    assert massLost == pytest.approx(DENSITY * lost, rel=1e-9)


def test_experiment_block_parameters_are_accepted():
    pytest.importorskip('yade')
    from ballast.oedometer import Oedometer
    code = block('The experiment is the library')
    ctor = re.search(r'^run = (Oedometer\(.*?\))', code, re.M).group(1)
    run = eval(ctor, {'Oedometer': Oedometer})
    assert (run.p['seed'], run.p['f'], run.p['pattern']) == (2, 4.0, 14)
    assert 'run.prepare()' in code and 'run.load()' in code and 'run.summary()' in code
    with pytest.raises(ValueError, match='f = -4'):
        Oedometer(seed=2, f=-4)
