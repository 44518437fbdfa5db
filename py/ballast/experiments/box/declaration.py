"""The box test as a study sees it (no YADE)."""
from ..declaration import Declaration
from .parameters import OWNER, PARAMS, bedKey, check

DECLARATION = Declaration(
    name='box', owner=OWNER, params=PARAMS,
    title='The box test (`BoxTest(...)`, `--name value`, table columns)',
    bounds=['`dMin` < `dMax`; the bed at least 2 `dMax` deep, each layer at least `dMax`; the box at least 3 `dMax` '
            'wide; at least 2 `dMax` of ballast beside the sleeper; `seatLoad` < `peakLoad`; at most 1e6 grains.',
            'A cycle spans at least 100 time steps; a run at most 1e9; `Tc` and `abrasionPeriod` within a cycle.',
            '`loadFile`: read and checked with the parameters (the row of a fault named).',
            '`results` and the bed store (`bedDir`, default `<results>/beds`) are created and written to before the '
            'preparation.'],
    check=check, script='scripts/box_test.py', sets={'results': 'results', 'runId': 'runId', 'sampleStore': 'bedDir', 'resume': 'resume'}, sampleKey=lambda p: bedKey(p)[1],
    cost=lambda p: p['cycles'] * p.history().period / p.loadingTimeStep(),
    results=[('settlement', 'm'), ('resilient', 'm'), ('nCrushed', '-'), ('nAbraded', '-'), ('maxStressRatio', '-'),
             ('maxDamage', '-'), ('cpuSecondsPerCycle', 's'), ('cpuSeconds', 's')],
    statistics=['settlement', 'nCrushed'], response=('settlement',),
    # whole: a run's per-cycle table, gradings, crushes and zones are tens of kB for 1 000 cycles; its end state
    # (0.4 MB for 400 grains) is what the next slice of a long run continues from (continueFrom), on any machine;
    # with cycle jumping its jumps.csv; samples.csv (100 rows a cycle) and the other states stay out
    recordFiles=('summary.json', 'row.json', 'cycles.csv', 'grading.csv', 'crushes.csv', 'zones.csv', 'jumps.csv',
                 'state-end.yade.gz'),
    brief=lambda s: '%s cycles, settlement %.3f mm (resilient %.3f mm), %s crushed' % (
        s.get('cycles', '?'), 1e3 * s.get('settlement', float('nan')), 1e3 * s.get('resilient', float('nan')),
        s.get('nCrushed', '?')))
