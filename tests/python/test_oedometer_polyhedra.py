"""The oedometer with grain 'polyhedron' (issue 47, item 4; docs/grains.md, "Polyhedra"), end to end on a dozen grains:
YADE's polyhedra deposited in the facet cylinder, a wall as the loading plate, eq. 8 up to its peak (stopAt 0.5), crushing
by YADE's PolyhedraSplitter through PolyhedronCrushEngine. A soft modulus (young 3e9 Pa) keeps the time step at 1e-5 s
so the run stays within about a minute of CPU; the physics asserted does not depend on it."""
import csv
import json
import math
import os

import numpy as np
import pytest

yade = pytest.importorskip('yade')

from ballast.oedometer import Oedometer   # noqa: E402
from ballast.oedometer.loadcurve import eq8   # noqa: E402

FMAX, F, FT0 = 5e4, 50.0, 4.5e4   # [N], [Hz], [Pa m]
RUN = dict(grain='polyhedron', abrasion=False, diameter=0.12, height=0.05, dMin=0.03, dMax=0.04, fill=0.45, young=3e9,
           Fmax=FMAX, ft0=FT0, f=F, samples=1000, seed=3, stopAt=0.5, segments=12, prepDamping=0.8, prepYoung=3e7,
           pressForce=500.0, seatForce=50.0, progress=60)
TOL_MASS = 1e-12      # [-] relative: the ledger is a sum of YADE's masses, rounding only
# [-] of Fmax: at the peak of eq. 8 (dF/dt = 0) the bottom carries the plate's force and the grains' weight (a few N);
# what is left is the grains' inertia and the vertical part of the facet contacts' normals (YADE's FindNormal fits the
# overlap, not the facet's plane)
TOL_BALANCE = 0.05


@pytest.fixture(scope='module')
def run(tmp_path_factory):
    root = str(tmp_path_factory.mktemp('oedo-poly'))
    exp = Oedometer(results=root, runId='poly', packingDir=os.path.join(root, 'packings'), **RUN)
    s = exp.load()
    return exp, s


def test_outputs_written(run):
    exp, s = run
    for name in ('fd.csv', 'checks.csv', 'events.csv', 'grains.csv', 'psd.csv', 'cycles.csv', 'summary.json',
                 'state-start.yade.gz', 'state-end.yade.gz', 'fd.png', 'grading.png'):
        assert os.path.getsize(os.path.join(exp.out, name)) > 0, name
    with open(os.path.join(exp.out, 'summary.json')) as fh:
        saved = json.load(fh)
    assert saved['params']['grain'] == 'polyhedron' and saved['stoppedBy'] == 'stopAt'
    assert 8 <= saved['nGrainsInitial'] <= 16   # a dozen grains
    fd = np.loadtxt(os.path.join(exp.out, 'fd.csv'), delimiter=',', skiprows=1, ndmin=2)
    # the applied force is eq. 8 (the plate's engine interpolates 4000 samples a cycle)
    assert np.allclose(fd[:, 5], eq8(FMAX, F, fd[:, 0]), atol=1e-3 * FMAX)
    assert fd[-1, 0] == pytest.approx(0.5 / F, abs=0.02 / F)


def test_mass_ledger_closes(run):
    _, s = run
    assert abs(s['massFinal'] + s['massLost'] - s['massInitial']) <= TOL_MASS * s['massInitial']
    # the gap YADE leaves between the pieces is all that is lost: a small fraction
    assert 0 <= s['massLost'] < 1e-3 * s['massInitial']


def test_crushes_booked(run):
    exp, s = run
    with open(os.path.join(exp.out, 'events.csv')) as fh:
        events = [e for e in csv.DictReader(fh) if e['kind'] == 'crush']
    assert s['nCrushed'] >= 1 and len(events) == s['nCrushed']
    checks = np.loadtxt(os.path.join(exp.out, 'checks.csv'), delimiter=',', skiprows=1, ndmin=2)
    assert checks[:, 2].sum() == s['nCrushed']
    for e in events:
        r, value, strength = float(e['radius']), float(e['value']), float(e['strength'])
        assert strength == pytest.approx(FT0 / r, rel=1e-12)   # eq. 4 with m = 1
        assert value > strength
        assert len(e['newIds'].split()) == 4   # the splitter's four pieces, the grain's body one of them
    with open(os.path.join(exp.out, 'grains.csv')) as fh:
        grains = list(csv.DictReader(fh))
    assert len(grains) == s['nGrainsInitial'] + 3 * s['nCrushed']


def test_plate_force_against_bottom_at_peak(run):
    """At the peak of eq. 8 the bottom wall carries the grains' force on the plate plus the grains' weight."""
    exp, s = run
    from yade import O
    F = exp.loading.force()
    bottom = -float(O.forces.f(exp.cylinder.bottom)[2])
    weight = 9.81 * s['massFinal']
    assert F == pytest.approx(FMAX, rel=0.1)
    assert abs(bottom - F - weight) <= TOL_BALANCE * FMAX, (bottom, F, weight)
    assert math.isfinite(s['maxProtrusion'])
