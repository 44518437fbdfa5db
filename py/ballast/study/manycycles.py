"""Settlement and breakage against the number of load cycles for several runs (issue 12): the figure
and the compact records of docs/studies/cycles/. Reads each run's cycles.csv (NumPy, by column name)
and summary.json; no YADE."""
import csv
import json
import os
import shutil

import numpy as np

RECORD_FILES = ('cycles.csv', 'summary.json', 'psd.csv')  # what a run keeps in the repository (a few kB)
SUMMARY_KEYS = ('nCrushed', 'nFatigueCrushed', 'Bg', 'Br', 'BBI', 'cycles', 'cpuSeconds', 'wallSeconds', 'steps',
                'nGrainsInitial', 'nSpheresFinal', 'porosity0')


def readRun(path):
    """(cycles as a NumPy record array by column name, the summary) of a run folder or record."""
    cycles = np.atleast_1d(np.genfromtxt(os.path.join(path, 'cycles.csv'), delimiter=',', names=True))
    with open(os.path.join(path, 'summary.json')) as fh:
        s = json.load(fh)
    return cycles, s


def keepRecord(run, dest):
    """Copies a run's compact record (RECORD_FILES, the summary stripped of its bulky parts) to dest."""
    os.makedirs(dest, exist_ok=True)
    for f in RECORD_FILES:
        src = os.path.join(run, f)
        if f == 'summary.json':
            with open(src) as fh:
                s = json.load(fh)
            keep = {k: s[k] for k in SUMMARY_KEYS if k in s}
            keep['params'] = s['params']
            with open(os.path.join(dest, f), 'w') as fh:
                json.dump(keep, fh, indent=1)
        else:
            shutil.copyfile(src, os.path.join(dest, f))


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
        c, s = readRun(path)
        rows.append({'run': os.path.basename(os.path.normpath(path)), 'seed': s['params']['seed'],
                     'fatigue': bool(s['params'].get('fatigue')), 'cycles': len(c), 'nCrushed': s['nCrushed'],
                     'nFatigueCrushed': s.get('nFatigueCrushed', 0), 'Bg': s['Bg'],
                     'settlement1_mm': 1e3 * c['settlement'][0], 'settlementN_mm': 1e3 * c['settlement'][-1],
                     'cpuSeconds': s['cpuSeconds'], 'cpuPerCycle': s['cpuSeconds'] / max(len(c), 1)})
    return rows


def writeTable(rows, path):
    with open(path, 'w', newline='') as fh:
        w = csv.DictWriter(fh, fieldnames=TABLE_COLUMNS)
        w.writeheader()
        w.writerows(rows)


def figure(runs, out):
    """Permanent settlement and Marsal's B_g against the cycle number, all on log axes, a line per run."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.2))
    for k, path in enumerate(runs):
        c, s = readRun(path)
        style = dict(color='C%d' % (s['params']['seed'] % 10), ls='--' if s['params'].get('fatigue') else '-',
                     marker='o', ms=3, label=label(s))
        a1.semilogx(c['cycle'], 1e3 * c['settlement'], **style)
        a2.semilogx(c['cycle'], c['Bg'], **style)
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
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)
