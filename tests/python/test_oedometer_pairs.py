"""studies/oedometer_pairs.py on committed records: the clump oedometer at the paper's calibration against the
spheres at 8 Hz, paired by seed. What it writes is options.compare of the runs it selected, and its avalanche shares
are those of the records' delta at the applied peak (above 5 mm), worked out here from their summary.json files."""
import glob
import json
import os
import subprocess
import sys

import pytest
from scipy import stats

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CLUMPS = os.path.join(ROOT, 'docs', 'studies', 'clump-oedometer')
SPHERES = os.path.join(ROOT, 'docs', 'studies', 'frequency')


def script(*args):
    return subprocess.run([sys.executable, os.path.join(ROOT, 'studies', 'oedometer_pairs.py'), *args],
                          capture_output=True, text=True, env=dict(os.environ, MPLBACKEND='Agg'))


def delta(pattern):
    """{seed: delta at the applied peak [m]} of the records whose run id matches pattern."""
    out = {}
    for path in glob.glob(os.path.join(pattern, 'summary.json')):
        with open(path) as fh:
            s = json.load(fh)
        out[int(s['params']['seed'])] = s['deltaAtAppliedPeak']
    return out


def test_pairs_of_two_studies_by_seed(tmp_path):
    r = script(CLUMPS + '[ft0=3.1e6]', '--reference', SPHERES + '[f=8]', '--name', 'clumps', '--reference-name',
               'spheres', '--out', str(tmp_path))
    assert r.returncode == 0, r.stderr
    with open(tmp_path / 'comparison.json') as fh:
        c = json.load(fh)['clumps']
    mine = delta(os.path.join(CLUMPS, 'runs', 'seed=*,grain=clump,ft0=3.1e6'))
    ref = delta(os.path.join(SPHERES, 'runs', 'seed=*,f=8'))
    seeds = sorted(set(mine) & set(ref))
    assert c['seeds'] == seeds and c['n'] == len(seeds) >= 2
    a = [mine[s] > 0.005 for s in seeds]
    b = [ref[s] > 0.005 for s in seeds]
    assert c['option']['avalanching'] == pytest.approx(sum(a) / len(a))
    assert c['reference']['avalanching'] == pytest.approx(sum(b) / len(b))
    table = [[sum(a), len(a) - sum(a)], [sum(b), len(b) - sum(b)]]
    assert c['pFisherAvalanching'] == pytest.approx(stats.fisher_exact(table).pvalue, rel=1e-12)
    assert c['meanDifference'] == pytest.approx(sum(mine[s] - ref[s] for s in seeds) / len(seeds), rel=1e-12)
    assert (tmp_path / 'pairs.png').stat().st_size > 0 and 'spheres' in (tmp_path / 'comparison.md').read_text()


def test_a_bad_selection_is_refused_by_name(tmp_path):
    r = script(CLUMPS + '[ft0=3.1e6 x]', '--reference', SPHERES, '--out', str(tmp_path))
    assert r.returncode == 2 and "a selection is PATH[NAME=VALUE ...]" in r.stderr and 'ft0=3.1e6 x' in r.stderr
    r = script(CLUMPS + '[foo=3]', '--reference', SPHERES, '--out', str(tmp_path))
    assert r.returncode == 2 and "no parameter 'foo'" in r.stderr
    assert not (tmp_path / 'comparison.json').exists()
