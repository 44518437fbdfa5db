"""The box test with clump grains end to end (issue 47): a small bed of clumps under one load cycle that crushes them.
Before the fix of the split's silenced contacts this box exploded: the sleeper was thrown 150 mm up (settlement
-149.65 mm) and 308 crushes went off among 83 clumps, while the same box of spheres settles 41 mm (it punches: the
bed is one layer of 60 mm under 500 kPa). About 50 s of CPU: the bed (83 clumps, two templates) and the cycle."""
import os

import pandas as pd
import pytest

pytest.importorskip('yade')
from ballast.experiments.box import BoxTest  # noqa: E402

BOX = dict(boxLength=0.2, boxWidth=0.1, bedDepth=0.06, layers=1, sleeperWidth=0.08, sleeperHeight=0.05, sleeperMass=5,
           dMin=0.02, dMax=0.03, young=3e9, prepYoung=3e8, f=40, seatLoad=300, peakLoad=4000, cycles=1, ft0=3.5e4,
           rMin=0.008, strength=1.5e10, grain='clump', clumpTemplates=2, progress=60)


def test_a_clump_box_crushes_without_throwing_the_sleeper(tmp_path):
    """The sleeper is never lifted by more than 1 mm above where it was seated (samples every 1/100 cycle), ends
    below it by less than the bed's depth, and the crushes stay below twice the grains (before: 3.7 times); the mass
    ledger closes."""
    test = BoxTest(results=str(tmp_path), runId='clumps', **BOX)
    s = test.run()
    samples = pd.read_csv(os.path.join(test.out, 'samples.csv'))
    print('settlement %.2f mm, lowest %.2f mm, crushes %d of %d grains' % (
        1e3 * s['settlement'], 1e3 * samples['settlement'].min(), s['nCrushed'], s['nGrainsInitial']))
    assert samples['settlement'].min() > -1e-3
    assert 0 < s['settlement'] < BOX['bedDepth']
    assert 0 < s['nCrushed'] < 2 * s['nGrainsInitial']
    assert abs(s['massLedgerError']) < 1e-12
