"""The single-particle test as a study sees it (no YADE)."""
from ..declaration import Declaration
from .parameters import OWNER, PARAMS, check

DECLARATION = Declaration(
    name='single_particle', owner=OWNER, params=PARAMS,
    title='The single-particle test (`SingleParticle(...)`, `--name value`, table columns)',
    bounds=['`dMin` < `dMax`; `n` or `diameters`, not both.',
            'The platens close the smallest grain by `maxStrain` in 100 to 1e8 time steps of `dtSafety` x (d / 2) '
            'sqrt(`density` / `young`): a quasi-static test that ends.',
            '`results` is created and written to before the preparation.'], check=check, script='scripts/single_particle.py',
    sets={'results': 'results', 'runId': 'runId', 'sampleStore': None},
    cost=lambda p: p.grainCount() / p['speed'],
    results=[('n', '-'), ('nCrushed', '-'), ('forceOverD2Min', 'Pa'), ('forceOverD2Max', 'Pa'), ('inertiaRatioMax', '-'),
             ('cpuSeconds', 's')],
    statistics=['nCrushed', 'forceOverD2Min', 'forceOverD2Max'], response=('forceOverD2Max',))
