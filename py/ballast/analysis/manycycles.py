"""Settlement and breakage against the number of load cycles for several runs (issue 12; docs/oedometer.md,
"Many cycles"): the table, the figure and the compact records of docs/studies/cycles/. Reads each run
with ballast.study.data (its cycles.csv and summary.json); a record is ballast.study.records' with the
summary cut to SUMMARY_KEYS. NumPy, no YADE."""
import csv
import os

from ..runfiles import column
from ..study.data import read_run
from ..study.records import writeRecord
from .figures import writeFigure

SUMMARY_KEYS = ('nCrushed', 'nFatigueCrushed', 'Bg', 'Br', 'BBI', 'cycles', 'cpuSeconds', 'wallSeconds', 'steps',
                'nGrainsInitial', 'nSpheresFinal', 'porosity0')


def keepRecord(run, dest):
    """The compact record of the run folder `run` in the folder dest (records.writeRecord; the summary
    cut to SUMMARY_KEYS and the parameters: a few kB)."""
    return writeRecord(run, dest, 'oedometer', SUMMARY_KEYS)


def label(s):
    p = s['params']
    return 'seed %d, %s' % (p['seed'], ('fatigue b = %g' % p['fatigueExponent']) if p.get('fatigue') else 'no fatigue')


TABLE_COLUMNS = ('run', 'seed', 'fatigue', 'cycles', 'nCrushed', 'nFatigueCrushed', 'Bg', 'settlement1_mm',
                 'settlementN_mm', 'cpuSeconds', 'cpuPerCycle')


def table(runs):
    """One dict per run (TABLE_COLUMNS): seed, fatigue, cycles, crushes, B_g, settlement after the first
    and the last cycle, CPU seconds in all and per cycle."""
    rows = []
    for path in runs:
        run = read_run(path)
        s, settlement = run.summary, column(run.cycles, 'settlement')
        rows.append({'run': os.path.basename(os.path.normpath(path)), 'seed': run.params['seed'],
                     'fatigue': bool(run.params.get('fatigue')), 'cycles': len(settlement), 'nCrushed': s['nCrushed'],
                     'nFatigueCrushed': s.get('nFatigueCrushed', 0), 'Bg': s['Bg'],
                     'settlement1_mm': 1e3 * settlement[0], 'settlementN_mm': 1e3 * settlement[-1],
                     'cpuSeconds': s['cpuSeconds'], 'cpuPerCycle': s['cpuSeconds'] / max(len(settlement), 1)})
    return rows


def writeTable(rows, path):
    with open(path, 'w', newline='') as fh:
        w = csv.DictWriter(fh, fieldnames=TABLE_COLUMNS)
        w.writeheader()
        w.writerows(rows)


def figure(runs, out):
    """Permanent settlement and Marsal's B_g against the cycle number, all on log axes, a line per run; returns out."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.2))
    for path in runs:
        run = read_run(path)
        style = dict(color='C%d' % (run.params['seed'] % 10), ls='--' if run.params.get('fatigue') else '-',
                     marker='o', ms=3, label=label(run.summary))
        cycle = column(run.cycles, 'cycle')
        a1.semilogx(cycle, 1e3 * column(run.cycles, 'settlement'), **style)
        a2.semilogx(cycle, column(run.cycles, 'Bg'), **style)
    # log axes: a quiet sample settles by tenths of a millimetre, an avalanche by tens
    a1.set_yscale('log')
    a2.set_yscale('symlog', linthresh=0.1)
    a1.set_ylabel('permanent settlement [mm] (log)')
    a2.set_ylabel("Marsal's $B_g$ [%] (log above 0.1 %)")
    for a in (a1, a2):
        a.set_xlabel('load cycle N')
        a.grid(alpha=0.3, which='both')
        a.legend(fontsize=8)
    fig.suptitle('many load cycles between 150 and 1500 kN at 8 Hz (paper-size oedometer)', fontsize=10)
    return writeFigure(fig, out, dpi=120)
