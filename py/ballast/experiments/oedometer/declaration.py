"""The oedometer as a study sees it (no YADE)."""
from ..declaration import Declaration
from .loadcurve import halfLoadTime
from ..parameters import MAX_LOADING_STEPS, MIN_STEPS_PER_CYCLE
from .parameters import MAX_OVERLAP_RATIO, OWNER, PARAMS, check, packingKey

# the results of summary.json and of the per-check log a study tabulates, (name, unit)
RESULTS = [('peakForce', 'N'), ('deltaAtPeak', 'm'), ('deltaAtAppliedPeak', 'm'), ('seatingDelta', 'm'), ('deltaMax', 'm'),
           ('deltaFinal', 'm'), ('nCrushed', '-'), ('Bg', '%'), ('Br', '-'), ('BBI', '-'),
           ('nAbraded', '-'), ('volumeLost', 'm^3'), ('massLost', 'kg'), ('massInitial', 'kg'), ('nGrainsInitial', '-'),
           ('porosity0', '-'), ('wallSeconds', 's'), ('cpuSeconds', 's'), ('steps', '-'),
           ('crushingChecks', '-'), ('crushesPerCrushingCheck', '-'), ('ratioAtCrushMax', '-'), ('ratioAtCrushMean', '-'),
           ('forceAtFirstCrush', 'N'), ('stressRatioAtHalfLoad', '-'), ('crushesAfterPeak', '-')]
STATISTICS = ['deltaAtPeak', 'deltaAtAppliedPeak', 'deltaMax', 'peakForce', 'nCrushed', 'nAbraded', 'massLost', 'Bg', 'Br',
              'BBI', 'crushingChecks', 'crushesPerCrushingCheck', 'ratioAtCrushMax', 'forceAtFirstCrush',
              'stressRatioAtHalfLoad', 'wallSeconds', 'cpuSeconds']


def checkResults(run):
    """What the per-check log and the crushes of a run say (checkstats.checkStats)."""
    from .checkstats import checkStats
    return checkStats(run)


BOUNDS = [
    '`dMin` < `dMax` < `diameter` / 2, `dMax` < `height`, `rMin` <= `dMax` / 2, `Fmin` < `Fmax`, `prepYoung` <= `young`.',
    'The run must end: `cycles` / `f` / dt <= %.0e time steps, dt = `dtSafety` x (`dMin` / 2) sqrt(`density` / '
    '`young`) (YADE\'s PWaveTimeStep of the smallest grain at the start).' % MAX_LOADING_STEPS,
    'A cycle spans at least %d time steps: 1 / `f` >= %d dt.' % (MIN_STEPS_PER_CYCLE, MIN_STEPS_PER_CYCLE),
    '`Fmax` carried by one steel contact of the smallest grain overlaps it by at most %g of its radius (linear law: '
    'u = F / kn, kn = 2 E r Es r / (E r + Es r); Hertz: u = (F / kno)^(2/3), kno = 4/3 E* sqrt(r / 2)).'
    % MAX_OVERLAP_RATIO,
    '`results` and the packing store (`packingDir`, default `<results>/packings`) are created and written to '
    'before the preparation.']

DECLARATION = Declaration(
    name='oedometer', owner=OWNER, params=PARAMS, bounds=BOUNDS,
    title='The oedometer (`Oedometer(...)`, `--name value`, table columns)', check=check, script='scripts/oedometer.py',
    sets={'results': 'results', 'runId': 'runId', 'sampleStore': 'packingDir', 'resume': 'resume'},
    sampleKey=lambda p: packingKey(p)[1],
    cost=lambda p: p['cycles'] / p['f'],          # simulated loading time [s]: the highest f builds the packing
    recordTimes=lambda p: [halfLoadTime(p['f'])],  # the two checks around Fmax/2 (stressRatioAtHalfLoad)
    results=RESULTS, statistics=STATISTICS, derived=checkResults,
    tested={'onset': ('forceAtFirstCrush', 'applied force at the first crush'),
            'network': ('stressRatioAtHalfLoad', 'largest sigma/f_t at Fmax/2 before a crush')},
    response=('deltaAtAppliedPeak', 'deltaAtPeak'),
    brief=lambda s: 'peak F %.0f kN at delta %.2f mm, %s crushed' % (s.get('peakForce', float('nan')) / 1e3,
                                                                    s.get('deltaAtPeak', float('nan')) * 1e3,
                                                                    s.get('nCrushed', '?')))  # the paper's delta at the peak (applied force, else measured)
