"""The cyclic triaxial test as a study sees it (no YADE)."""
from ..declaration import Declaration
from .parameters import OWNER, PARAMS, check, specimenKey

DECLARATION = Declaration(
    name='triaxial', owner=OWNER, params=PARAMS,
    title='The cyclic triaxial test (`TriaxialTest(...)`, `--name value`, table columns)',
    bounds=['`dMin` < `dMax`; the specimen at least 4 `dMax` across, 2/3 to 3 times as high as wide, each layer at '
            'least `dMax`; `qMin` < `qMax`; `membraneCell` between `dMin` / 20 and `dMax`; at most 1e6 grains.',
            'A cycle spans at least 100 time steps; a run at most 1e9; `Tc` and `abrasionPeriod` within a cycle.',
            '`reference`: each file read and checked with the parameters (the line of a fault named).',
            '`results` and the specimen store (`specimenDir`, default `<results>/specimens`) are created and written '
            'to before the preparation.'],
    check=check, script='scripts/triaxial.py',
    sets={'results': 'results', 'runId': 'runId', 'sampleStore': 'specimenDir'}, sampleKey=lambda p: specimenKey(p)[1],
    cost=lambda p: p['cycles'] * p.period() / p.loadingTimeStep(),
    results=[('axialStrain', '-'), ('volumetricStrain', '-'), ('resilientModulus', 'Pa'), ('nCrushed', '-'),
             ('nAbraded', '-'), ('maxStressRatio', '-'), ('maxDamage', '-'), ('cpuSecondsPerCycle', 's'),
             ('cpuSeconds', 's')],
    statistics=['axialStrain', 'volumetricStrain', 'nCrushed'], response=('axialStrain',),
    recordFiles=('summary.json', 'row.json', 'cycles.csv', 'grading.csv', 'jumps.csv', 'state-end.yade.gz'),
    brief=lambda s: '%s cycles, axial strain %.3f %%, volumetric %.3f %%, %s crushed' % (
        s.get('cycles', '?'), 100 * s.get('axialStrain', float('nan')), 100 * s.get('volumetricStrain', float('nan')),
        s.get('nCrushed', '?')))
