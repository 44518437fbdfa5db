"""The oedometer as a study sees it (no YADE)."""
from ..declaration import Declaration
from .loadcurve import halfLoadTime
from .parameters import OWNER, PARAMS, check, packingKey

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
    """What the per-check log and the crushes of a run say (ballast.analysis.checks.checkStats)."""
    from ...analysis.checks import checkStats
    return checkStats(run)


DECLARATION = Declaration(
    name='oedometer', owner=OWNER, params=PARAMS, check=check, script='scripts/oedometer.py',
    sets={'results': 'results', 'runId': 'runId', 'sampleStore': 'packingDir'},
    sampleKey=lambda p: packingKey(p)[1],
    cost=lambda p: p['cycles'] / p['f'],          # simulated loading time [s]: the highest f builds the packing
    recordTimes=lambda p: [halfLoadTime(p['f'])],  # the two checks around Fmax/2 (stressRatioAtHalfLoad)
    results=RESULTS, statistics=STATISTICS, derived=checkResults,
    response=('deltaAtAppliedPeak', 'deltaAtPeak'))  # the paper's delta at the peak (applied force, else measured)
