"""ballast.experiments.single_particle.calibration: ft0, m and the Weibull modulus recovered from
synthetic strengths drawn from known values, written as the oedometer reads them; malformed input
refused naming the file and the row (no YADE)."""
import json
import math
import os
import subprocess

import numpy as np
import pytest

from ballast.experiments.single_particle import calibration
from ballast.experiments.single_particle.closedform import crushingForce
from ballast.oedometer import check as oedometerCheck
from ballast.params import ParamError

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def synthetic(path, n=300, ft0=3.1e6, m=1.0, k=5.0, criterion='vonMises', seed=3):
    """Grains of 20.5-44.5 mm whose criterion stress at failure is ft0 r^-m w, w Weibull(k): force by the
    closed form of each grain's strength."""
    rng = np.random.default_rng(seed)
    d = rng.uniform(0.0205, 0.0445, n)
    F = crushingForce(criterion, d / 2, ft0, m) * rng.weibull(k, n)
    with open(path, 'w') as fh:
        fh.write('grain,diameter_mm,force_kN\n')
        for i, (di, Fi) in enumerate(zip(d, F)):
            fh.write('%d,%.6f,%.6f\n' % (i, 1e3 * di, 1e-3 * Fi))
    return d, F


@pytest.mark.parametrize('criterion', ['vonMises', 'maxContactForce'])
def test_synthetic_parameters_recovered_within_their_intervals(tmp_path, criterion):
    path = str(tmp_path / 'measured.csv')
    synthetic(path, criterion=criterion)
    fit = calibration.calibrate(*calibration.readMeasured(path), criterion)
    assert fit['n'] == 300
    assert fit['ft0Low'] < 3.1e6 < fit['ft0High'] and fit['mLow'] < 1.0 < fit['mHigh']
    assert fit['weibullModulusLow'] < 5.0 < fit['weibullModulusHigh']
    files = calibration.write(fit, str(tmp_path / 'out'))
    with open(files[0]) as fh:
        assert json.load(fh)['criterion'] == criterion
    row = open(files[1]).read().splitlines()[-1].split()
    p = oedometerCheck({'ft0': row[1], 'm': row[2], 'weibullModulus': row[3], 'criterion': row[4]}, text=True)
    assert p['ft0'] == pytest.approx(fit['ft0'], rel=1e-8) and p['criterion'] == criterion


def test_no_scatter_gives_modulus_zero(tmp_path):
    d = np.array([0.021, 0.03, 0.04, 0.044])
    fit = calibration.calibrate(d, crushingForce('vonMises', d / 2, 2e6, 1.2), 'vonMises')
    assert fit['ft0'] == pytest.approx(2e6, rel=1e-9) and fit['m'] == pytest.approx(1.2, rel=1e-9)
    assert fit['weibullModulus'] == 0.0
    # the strength at the grains' size: at the geometric mean radius, by eq. 4 with the exact law
    rRef = math.exp(np.mean(np.log(d / 2)))
    assert fit['rRef'] == pytest.approx(rRef, rel=1e-12)
    assert fit['ftRef'] == pytest.approx(2e6 / rRef ** 1.2, rel=1e-9)


def test_the_strength_at_the_grains_size_is_what_the_data_determine(tmp_path):
    """ft0 (r = 1 m) is uncertain by m's uncertainty times ln(1 m / r); at the geometric mean radius only by the
    scatter: its interval holds the true f_t there and is several times narrower than ft0's."""
    path = str(tmp_path / 'measured.csv')
    synthetic(path, n=40, ft0=3.1e6, m=1.0, k=5.0, seed=11)
    d, F = calibration.readMeasured(path)
    fit = calibration.calibrate(d, F, 'vonMises')
    true = 3.1e6 / fit['rRef']
    assert fit['ftRefLow'] < true < fit['ftRefHigh']
    relRef = fit['ftRefHigh'] / fit['ftRefLow']
    rel0 = fit['ft0High'] / fit['ft0Low']
    assert math.log(rel0) > 3 * math.log(relRef), (rel0, relRef)
    # the same law reported at a given size: f_t there equals ft0 / r^m of the fit
    at = calibration.calibrate(d, F, 'vonMises', rRef=0.02)
    assert at['ftRef'] == pytest.approx(at['ft0'] / 0.02 ** at['m'], rel=1e-4)


def test_a_folder_is_refused(tmp_path):
    with pytest.raises(calibration.CalibrationError, match='a folder, not a CSV file'):
        calibration.readMeasured(str(tmp_path))


@pytest.mark.parametrize('text,words', [
    ('diameter,force\n0.03,1e5\n0.04,x\n0.02,5e4\n', r'measured.csv:3: force = .x. is not allowed: expected a finite number > 0'),
    ('diameter,force\n0.03,1e5\n-0.04,2e5\n0.02,5e4\n', r'measured.csv:3: diameter = .-0.04. is not allowed'),
    ('diameter,force\n0.03,1e5\n0.04,nan\n0.02,5e4\n', r'measured.csv:3: force'),
    ('size,force\n0.03,1e5\n0.04,2e5\n0.02,5e4\n', r"measured.csv:1: column 'size' is not allowed"),
    ('grain,force\n1,1e5\n2,2e5\n3,5e4\n', r'measured.csv:1: expected one diameter column'),
    ('diameter,diameter_mm,force\n0.03,30,1e5\n', r'measured.csv:1: expected one diameter column'),
    ('diameter,force\n0.03,1e5\n', r'1 grain\(s\); a fit needs at least 3'),
    ('', r'measured.csv: empty'),
    # a grain number left of an unnamed header (was read as the diameter, the diameter as the force)
    (',diameter,force\n1,0.03,1e5\n2,0.04,2e5\n3,0.02,5e4\n', r'measured.csv:1: column 1 has no name'),
    ('diameter,force\n1,0.03,1e5\n2,0.04,2e5\n3,0.02,5e4\n', r'measured.csv:2: 3 fields, the header has 2'),
    ('diameter,force\n0.03,1e5\n0.04,2e5,\n0.02,5e4\n', r'measured.csv:3: 3 fields, .*: a trailing comma\?'),
    # units: mm under a [m] header, kN under a [N] header
    ('diameter,force\n30,1e5\n40,2e5\n20,5e4\n', r'measured.csv:2: diameter = 30 is 30 m, .*in mm\? name the column diameter_mm'),
    ('diameter_mm,force\n30,15\n40,20\n20,5\n', r'measured.csv:2: force = 15 on a 30 mm grain .*in kN\? name the column force_kN'),
])
def test_malformed_input_names_the_file_and_the_row(tmp_path, text, words):
    path = tmp_path / 'measured.csv'
    path.write_text(text)
    with pytest.raises(calibration.CalibrationError, match=words):
        calibration.readMeasured(str(path))


def test_a_fit_outside_the_model_is_refused_naming_the_parameter():
    d = np.array([0.021, 0.03, 0.04, 0.044])
    with pytest.raises(ParamError, match='m = .* is not allowed') as e:   # m = 5: the engine allows [0, 3]
        calibration.calibrate(d, crushingForce('vonMises', d / 2, 2e6, 5.0), 'vonMises')
    assert e.value.name == 'm'


def test_the_command_writes_the_table_and_exits_2_on_bad_input(tmp_path):
    path = str(tmp_path / 'measured.csv')
    synthetic(path, n=50)
    script = os.path.join(ROOT, 'scripts', 'single_particle.py')
    ok = subprocess.run(['/usr/bin/python3', script, 'calibrate', path, '--out', str(tmp_path / 'c')],
                        capture_output=True, text=True, timeout=120)
    assert ok.returncode == 0, ok.stderr
    assert 'yade -n -x scripts/oedometer.py --ft0' in ok.stdout and os.path.isfile(tmp_path / 'c' / 'calibration.table')
    bad = subprocess.run(['/usr/bin/python3', script, 'calibrate', str(tmp_path / 'none.csv')],
                         capture_output=True, text=True, timeout=120)
    assert bad.returncode == 2 and 'none.csv: no such file' in bad.stderr and len(bad.stderr.splitlines()) == 1
