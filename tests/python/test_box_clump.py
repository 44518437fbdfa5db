"""The box test with clump grains end to end (issue 47): a small bed of clumps under one load cycle that crushes them,
then a slice going on from its end state (as the clump box study's slices do). Before the fix of the split's silenced
contacts this box exploded: the sleeper was thrown 150 mm up (settlement -149.65 mm) and 308 crushes went off among 83
clumps, while the same box of spheres settles 41 mm (it punches: the bed is one layer of 60 mm under 500 kPa). About
50 s of CPU: the bed (83 clumps, two templates) and the cycle; the slice about 20 s more."""
import os

import pandas as pd
import pytest

pytest.importorskip('yade')
from ballast.experiments.box import BoxTest  # noqa: E402
from yade import O  # noqa: E402

BOX = dict(boxLength=0.2, boxWidth=0.1, bedDepth=0.06, layers=1, sleeperWidth=0.08, sleeperHeight=0.05, sleeperMass=5,
           dMin=0.02, dMax=0.03, young=3e9, prepYoung=3e8, f=40, seatLoad=300, peakLoad=4000, cycles=1, ft0=3.5e4,
           rMin=0.008, strength=1.5e10, grain='clump', clumpTemplates=2, progress=60)


@pytest.fixture(scope='module')
def run(tmp_path_factory):
    test = BoxTest(results=str(tmp_path_factory.mktemp('clumpbox')), runId='clumps', **BOX)
    return test, test.run()


def test_a_clump_box_crushes_without_throwing_the_sleeper(run):
    """The sleeper is never lifted by more than 1 mm above where it was seated (samples every 1/100 cycle), ends
    below it by less than the bed's depth, and the crushes stay below twice the grains (before: 3.7 times); the mass
    ledger closes."""
    test, s = run
    samples = pd.read_csv(os.path.join(test.out, 'samples.csv'))
    print('settlement %.2f mm, lowest %.2f mm, crushes %d of %d grains' % (
        1e3 * s['settlement'], 1e3 * samples['settlement'].min(), s['nCrushed'], s['nGrainsInitial']))
    assert samples['settlement'].min() > -1e-3
    assert 0 < s['settlement'] < BOX['bedDepth']
    assert 0 < s['nCrushed'] < 2 * s['nGrainsInitial']
    assert abs(s['massLedgerError']) < 1e-12


def test_a_slice_goes_on_from_a_clump_state(run, tmp_path):
    """continueFrom the clump box's end state: the scene comes back as clumps (the kind and every grain's stored
    volume, O.tags), the first cycle's row as recorded, a second cycle run on with its crushes counted on from the
    first's, and the mass ledger closed from the bed's mass at the start of the first slice, not of this one."""
    from ballast import grainkinds
    test, s = run
    slice2 = BoxTest(results=str(tmp_path), runId='slice2', continueFrom=os.path.join(test.out, 'state-end.yade.gz'),
                     **dict(BOX, cycles=1))
    s2 = slice2.run()
    kind = grainkinds.current()
    assert kind.name == 'clump'
    ids = kind.ids()
    assert sum(1 for i in ids if O.bodies[int(i)].isClump) > 0
    cyc = pd.read_csv(os.path.join(str(tmp_path), 'slice2', 'cycles.csv')).drop(columns='cpuSeconds')
    old = pd.read_csv(os.path.join(test.out, 'cycles.csv')).drop(columns='cpuSeconds')
    assert list(cyc.cycle) == [1, 2] and s2['cycles'] == 2
    pd.testing.assert_frame_equal(cyc.iloc[:1], old, check_dtype=False)   # a one-row column of 0 reads as int
    assert s2['nCrushed'] == s['nCrushed'] + cyc.crushes.iloc[1] and s2['nCrushed'] == cyc.nCrushed.iloc[1]
    assert s2['massInitial'] == s['massInitial'] and abs(s2['massLedgerError']) < 1e-12 * s['massInitial']
    assert s2['massGrains'] + s2['massLost'] == pytest.approx(s['massGrains'] + s['massLost'], rel=1e-12)
