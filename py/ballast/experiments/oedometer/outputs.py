"""What a run leaves (docs/oedometer.md, "Output"): fd.csv (F-delta, also in yade.plot), checks.csv
(one line per crushing check), events.csv, grains.csv (per-grain state), summary.json, fd.png and
optional VTK files with a .pvd time series for ParaView (grains, walls and the contact force network per
frame). Grains are coloured by state in YADE's 3D view: original (every grain sand-coloured from the
start of loading), fragment (by generation), abraded.

Every file is written atomically (a temporary name, synced, renamed). fd.csv is also streamed while
loading (a live log, flushed by the OS) and written again atomically from the rows at the end."""
import csv
import io
import json
import math
import os

import numpy as np
from yade import O, plot
from yade.wrapper import Facet, Sphere

from ... import _ballast, grading, harvest, runtime
from ...runfiles import saveFigure, strictJson, writeAtomic
from ...settlementlaws import settlementJumped

FD_COLUMNS = ('t', 'F', 'delta', 'nCrushed', 'nAbraded', 'Fapplied')
CHECK_COLUMNS = ('t', 'iter', 'crushes', 'maxStressRatio', 'maxCrushableRatio', 'inertialNumber')
INERTIAL_BOUND = 1e-3  # [-] the quasi-static regime's inertial number (GDR MiDi 2004): above it a run warns
CYCLE_COLUMNS = ('cycle', 't', 'settlement', 'resilient', 'crushes', 'abrasions', 'Bg', 'maxDamage')
EVENT_COLUMNS = ('kind', 't', 'iter', 'id', 'x', 'y', 'z', 'radius', 'value', 'strength', 'newIds', 'EkBefore',
                 'EeBefore', 'EkAfter', 'EeAfter', 'EkGrown', 'EeGrown')
ENERGY_KEYS = ('energyBefore', 'energyAfter', 'energyGrown')  # [kinetic, elastic] [J] of a replacement
GRAIN_COLUMNS = ('id', 'x', 'y', 'z', 'r', 'mass', 'generation', 'parent', 'nAbraded', 'stressRatio', 'damage')

# colours in the 3D view: original grains, fragments by generation (1, 2, 3+), abraded grains get bluer
COLOR_ORIGINAL = (0.80, 0.75, 0.60)
COLOR_GENERATION = ((1.0, 0.55, 0.0), (0.90, 0.15, 0.10), (0.55, 0.0, 0.35))
COLOR_ABRADED = (0.20, 0.45, 1.0)


class GrainStates:
    """Per-grain state by body id, derived from the engines' events: generation (0 original, 1 a
    fragment, ...), parent id (-1 for originals) and how often the grain was abraded."""

    def __init__(self):
        self.generation = np.zeros(0, dtype=np.int64)
        self.parent = np.zeros(0, dtype=np.int64)
        self.nAbraded = np.zeros(0, dtype=np.int64)
        self.seen = {}  # engine label -> events already taken in

    def _grow(self, n):
        if n > len(self.generation):
            k = n - len(self.generation)
            self.generation = np.concatenate([self.generation, np.zeros(k, dtype=np.int64)])
            self.parent = np.concatenate([self.parent, np.full(k, -1, dtype=np.int64)])
            self.nAbraded = np.concatenate([self.nAbraded, np.zeros(k, dtype=np.int64)])

    def update(self, engines):
        """Take in the new events of the engines; returns the ids whose state changed."""
        self._grow(len(O.bodies))
        changed = []
        for eng in engines:
            events = eng.events
            for e in events[self.seen.get(eng.label, 0):]:
                if e['kind'] == 'crush':
                    self._grow(max(e['newIds']) + 1)
                    for i in e['newIds']:
                        self.generation[i] = self.generation[e['id']] + 1
                        self.parent[i] = e['id']
                    changed.extend(e['newIds'])
                else:
                    self.nAbraded[e['id']] += 1
                    changed.append(e['id'])
            self.seen[eng.label] = len(events)
        return changed

    def color(self, i):
        g = int(self.generation[i])
        base = COLOR_ORIGINAL if g == 0 else COLOR_GENERATION[min(g, len(COLOR_GENERATION)) - 1]
        w = min(int(self.nAbraded[i]), 3) / 4.0  # each abrasion a quarter of the way to blue, at most 3/4
        return tuple((1 - w) * b + w * a for b, a in zip(base, COLOR_ABRADED))


@runtime.persistent('OedometerOutputs')
class Outputs:
    """Writes the run's files into the run directory, reading the run through a :class:`Probe` only.
    Replace it by any registered object with start(probe), bind(probe), finish(summary), rows, state()
    and fromState(s); its callbacks are record(), logCheck(), cycleEnd() and vtk()."""

    RECORDER, CHECKLOG, VTK, CYCLES = 'oedoRecorder', 'oedoCheckLog', 'oedoVtk', 'oedoCycles'

    def __init__(self):
        self.rows, self.checkRows, self.vtkFrames, self.cycleRows = [], [], [], []
        self.grains = GrainStates()
        self.exp = self.fd = None   # the Probe; fd.csv, opened at the first row written

    def state(self):
        return {'rows': runtime.packRows(self.rows), 'checkRows': runtime.packRows(self.checkRows),
                'vtkFrames': self.vtkFrames, 'cycleRows': self.cycleRows}

    @classmethod
    def fromState(cls, s, ref=None):
        obj = cls()
        obj.rows = runtime.unpackRows(s['rows'])
        obj.checkRows = runtime.unpackRows(s['checkRows'])
        obj.vtkFrames = [tuple(f) for f in s['vtkFrames']]
        obj.cycleRows = [tuple(r) for r in s['cycleRows']]
        return obj

    # ------------------------------------------------------------------ while loading
    def start(self, exp):
        """The recorders after the engines: F-delta every T/samples, a line per crushing check, VTK."""
        p = exp.p
        engines = [runtime.callback(self, 'record', virtPeriod=exp.T / p['samples'], initRun=True, label=self.RECORDER)]
        if exp.engine('crush') is not None:  # fires at the steps the crushing engine does
            engines.append(runtime.callback(self, 'logCheck', label=self.CHECKLOG, virtLast=exp.loading.t0,
                                            **p.crushPeriod()))
        # at the end of every cycle (the first step past it; load() records the last one itself)
        engines.append(runtime.callback(self, 'cycleEnd', virtPeriod=exp.T, virtLast=O.time, label=self.CYCLES))
        if p['vtk'] > 0:
            engines.append(runtime.callback(self, 'vtk', virtPeriod=p['vtk'], initRun=True, label=self.VTK))
        O.engines = O.engines + engines
        self.bind(exp)
        self.open()

    def bind(self, exp):
        """Read the run through this Probe (at start and after a restore); the files are written again from the
        rows when the first is due (open). Every grain is painted by its state (originals sand-coloured)."""
        self.exp, self.fd = exp, None
        self.grains = GrainStates()  # generations and abrasions from the engines' events
        self.grains.update(exp.degradingEngines())
        for b in O.bodies:
            if b is not None and isinstance(b.shape, Sphere):
                b.shape.color = self.grains.color(b.id)

    def open(self):
        """fd.csv written from the rows so far, the live plot filled."""
        exp = self.exp
        if exp.p['vtk'] > 0:
            os.makedirs(os.path.join(exp.out, 'vtk'), exist_ok=True)
        # a reopened run writes a new directory: its time series starts with its own frames
        self.vtkFrames = [f for f in self.vtkFrames if os.path.exists(os.path.join(exp.out, f[1]))]
        self.fd = open(os.path.join(exp.out, 'fd.csv'), 'w')
        self.fd.write(','.join(FD_COLUMNS) + '\n')
        for row in self.rows:
            self._writeRow(row)
        plot.reset()
        for row in self.rows:
            plot.addData(**dict(zip(FD_COLUMNS, row)))
        plot.plots = {'delta': ('F',)}  # YADE's live plot (and yade-batch's) show F-delta

    def _writeRow(self, row):
        self.fd.write(fdLine(row))

    def record(self):
        exp = self.exp
        if self.fd is None:
            self.open()
        row = (O.time - exp.loading.t0, exp.loading.force(), exp.loading.delta(), exp.counter('crush', 'nCrushed'),
               exp.counter('abrasion', 'nAbraded'), exp.loading.applied())
        if self.rows and row[0] <= self.rows[-1][0]:
            return
        if self.rows and row[3:5] != self.rows[-1][3:5]:
            self._recolor()
        self.rows.append(row)
        self._writeRow(row)
        plot.addData(**dict(zip(FD_COLUMNS, row)))

    def _recolor(self):
        for i in self.grains.update(self.exp.degradingEngines()):
            b = O.bodies[i]
            if b is not None:
                b.shape.color = self.grains.color(i)

    def settlementJumped(self):
        """Cycle jumping: the settlement [m] extrapolated over the cycles jumped before each row of cycles.csv
        (ballast.settlementlaws.settlementJumped; a row whose crushed or abraded count grew changed the bed)."""
        rows = self.cycleRows
        changed = np.diff([0] + [r[4] + r[5] for r in rows]) > 0
        return settlementJumped([r[0] for r in rows], [r[2] for r in rows], changed)

    def cycleEnd(self):
        """A row of cycles.csv: the cycle just ended, the permanent settlement (delta at the cycle's lowest
        force, its end), the resilient displacement (the largest delta within the cycle minus that: what the
        sample springs back from its deepest point, >= 0 by construction, also in the first cycle, where the
        plate may sink on after the peak), the crushes and abrasions in it, Marsal's B_g after it and the
        largest fatigue damage D of a grain (0 without fatigue)."""
        exp = self.exp
        t = O.time - exp.loading.t0
        simulated = int(round(t / exp.T))
        if simulated < 1:
            return
        k = simulated + exp.cyclesJumped()   # the cycle's number counts the jumped ones
        if self.cycleRows and self.cycleRows[-1][0] >= k:
            return
        a = np.array(self.rows)
        settlement = exp.loading.delta()
        within = a[(a[:, 0] >= (simulated - 1) * exp.T) & (a[:, 0] <= t), 2]
        deepest = max(float(np.max(within, initial=settlement)), settlement)
        crushed, abraded = exp.counter('crush', 'nCrushed'), exp.counter('abrasion', 'nAbraded')
        self.cycleRows.append((k, t, settlement, deepest - settlement, crushed, abraded, grading.marsal(*exp.grading()),
                               exp.counter('crush', 'maxDamage')))
        j = exp.jumper
        if j is not None:
            jumpedSettlement = self.settlementJumped()
        lines = [','.join(CYCLE_COLUMNS + (('jumped', 'settlementJumped') if j is not None else ())) + '\n']
        for i, row in enumerate(self.cycleRows):
            prev = self.cycleRows[i - 1][4:6] if i else (0, 0)
            line = '%d,%.9g,%.9g,%.9g,%d,%d,%.6g,%.6g' % (tuple(row[:4]) + (row[4] - prev[0], row[5] - prev[1],
                                                         row[6], row[7] if len(row) > 7 else 0.0))
            if j is not None:   # with jumping: the cycles jumped before this row, the settlement extrapolated over them
                line += ',%d,%.9g' % (row[0] - (i + 1), jumpedSettlement[i])
            lines.append(line + '\n')
        writeAtomic(os.path.join(exp.out, 'cycles.csv'), ''.join(lines))


    def logCheck(self):
        crush = self.exp.engine('crush')
        done = len(self.checkRows) and self.checkRows[-1][1] == O.iter
        if crush is None or done or crush.nChecks == 0:
            return
        before = self.checkRows[-1][4] if self.checkRows else 0
        self.checkRows.append((O.time - self.exp.loading.t0, O.iter, crush.nCrushed - before, crush.maxStressRatio,
                               crush.nCrushed, crush.maxCrushableRatio, self.exp.inertialNumber()))

    def inertialInfo(self):
        """The progress lines' word on the inertial number: the last check's, and a warning once any passed
        INERTIAL_BOUND."""
        seen = [row[6] for row in self.checkRows if len(row) > 6 and math.isfinite(row[6])]
        if not seen:
            return ''
        worst = max(seen)
        return '  I=%.1e%s' % (seen[-1], '' if worst <= INERTIAL_BOUND else
                               ' (max %.1e > %g: not quasi-static)' % (worst, INERTIAL_BOUND))

    def inertialSummary(self, crushTimes):
        """summary.json's inertialNumber: the largest I at the checks before the first crush, from the first
        to the last crush, and after it (loading times; None where no check fell), and whether any passed
        INERTIAL_BOUND."""
        rows = [(row[0], row[6]) for row in self.checkRows if len(row) > 6 and math.isfinite(row[6])]
        t1, t2 = (min(crushTimes), max(crushTimes)) if len(crushTimes) else (math.inf, math.inf)

        def largest(keep):
            v = [I for t, I in rows if keep(t)]
            return max(v) if v else None
        out = {'bound': INERTIAL_BOUND, 'maxBeforeCrushing': largest(lambda t: t < t1),
               'maxCrushing': largest(lambda t: t1 <= t <= t2), 'maxAfterCrushing': largest(lambda t: t > t2)}
        out['exceeded'] = any(I > INERTIAL_BOUND for _, I in rows)
        return out

    # ------------------------------------------------------------------ per-grain state
    def grainTable(self):
        """Columns of GRAIN_COLUMNS for every sphere (a loop over the grains: at the end and per VTK frame only)."""
        exp = self.exp
        self._recolor()
        bodies = [b for b in O.bodies if b is not None and isinstance(b.shape, Sphere)]
        ids = np.array([b.id for b in bodies], dtype=np.int64)
        x = np.array([tuple(b.state.pos) for b in bodies]).reshape(-1, 3)
        r = np.array([b.shape.radius for b in bodies])
        m = np.array([b.state.mass for b in bodies])
        v = np.array([tuple(b.state.vel) for b in bodies]).reshape(-1, 3)
        ratio = np.zeros(len(ids))
        crush = exp.engine('crush')
        if len(ids):
            # the criterion's stress over f_t now (eqs. 2-4), as the crushing engine sees it if there is one
            if crush is not None:
                se, ft, _ = crush.evaluate(ids, r)
            else:
                se, ft, _ = _ballast.crushCheck(harvest.stresses(ids), r, exp.p['ft0'], exp.p['m'], 0.0)
            ratio = se / ft
        g = self.grains
        g._grow(len(O.bodies))
        return {'id': ids, 'x': x[:, 0], 'y': x[:, 1], 'z': x[:, 2], 'r': r, 'mass': m, 'generation': g.generation[ids],
                'parent': g.parent[ids], 'nAbraded': g.nAbraded[ids], 'stressRatio': ratio, 'velocity': v,
                'damage': crush.fatigueState(ids)[:, 0] if crush is not None else np.zeros(len(ids))}

    # ------------------------------------------------------------------ VTK for ParaView
    def vtk(self):
        """A frame: grains, walls and the contact force network (vtk/*-<iter>.vtu), listed in oedometer.pvd."""
        exp = self.exp
        t = O.time - exp.loading.t0
        if self.vtkFrames and self.vtkFrames[-1][0] >= t:
            return
        n = O.iter
        grains, walls, contacts = ('vtk/%s-%09d.vtu' % (part, n) for part in ('grains', 'walls', 'contacts'))
        writeGrainsVtu(os.path.join(exp.out, grains), self.grainTable())
        writeWallsVtu(os.path.join(exp.out, walls), exp.cylinder.ids, exp.loading.top(), exp.cylinder.Rv)
        writeContactsVtu(os.path.join(exp.out, contacts))
        self.vtkFrames.append((t, grains, walls, contacts))
        writePvd(os.path.join(exp.out, 'oedometer.pvd'), self.vtkFrames)

    # ------------------------------------------------------------------ at the end
    def finish(self, summary):
        """Every output file from the rows, the engines' events and the scene now."""
        exp = self.exp
        if self.fd is None:
            self.open()
        self.fd.close()
        self.fd = None
        out = exp.out
        writeAtomic(os.path.join(out, 'fd.csv'), ','.join(FD_COLUMNS) + '\n' + ''.join(fdLine(r) for r in self.rows))
        # rows of states saved before maxCrushableRatio have 5 entries, before inertialNumber 6
        nan = float('nan')
        writeAtomic(os.path.join(out, 'checks.csv'), ','.join(CHECK_COLUMNS) + '\n' + ''.join(
            '%.9g,%d,%d,%.9g,%.9g,%.6g\n' % (tuple(row[:4]) + (row[5] if len(row) > 5 else nan,
                                                                row[6] if len(row) > 6 else nan))
            for row in self.checkRows))
        events = exp.events()
        buf = io.StringIO(newline='')
        w = csv.writer(buf)
        w.writerow(EVENT_COLUMNS)
        for e in events:
            w.writerow([e['kind'], '%.17g' % (e['t'] - exp.loading.t0), e['iter'], e['id']] +
                       ['%.17g' % v for v in e['pos']] + ['%.17g' % e[k] for k in ('radius', 'value', 'strength')] +
                       [' '.join(str(i) for i in e.get('newIds', []))] +
                       sum([['%.9g' % v for v in e[k]] if k in e else ['', ''] for k in ENERGY_KEYS], []))
        writeAtomic(os.path.join(out, 'events.csv'), buf.getvalue())
        table = self.grainTable()
        writeAtomic(os.path.join(out, 'grains.csv'), ','.join(GRAIN_COLUMNS) + '\n' + ''.join(
            '%d,%.9g,%.9g,%.9g,%.9g,%.9g,%d,%d,%d,%.6g,%.6g\n' % tuple(table[c][k] for c in GRAIN_COLUMNS)
            for k in range(len(table['id']))))
        self.plot(exp, events)
        self.writeGrading(exp, summary)
        if len(self.cycleRows) > 1:
            self.plotCycles(exp)
        writeAtomic(os.path.join(out, 'summary.json'), json.dumps(strictJson(summary), indent=1))  # last: the run's outputs are all there

    def plotCycles(self, exp):
        """cycles.png: permanent settlement and B_g against the number of cycles (log axis)."""
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
        c = np.array(self.cycleRows, dtype=float)
        fig, ax = plt.subplots(figsize=(7, 4.5))
        ax.semilogx(c[:, 0], c[:, 2] * 1e3, 'o-', color='C0', label='permanent settlement')
        if exp.jumper is not None and exp.jumper.jumps:   # the jumped cycles' settlement, extrapolated
            ax.semilogx(c[:, 0], (c[:, 2] + self.settlementJumped()) * 1e3, 'x:', color='C0',
                        label="with the jumped cycles' settlement (a + b ln n)")
            ax.legend(fontsize=8, loc='upper left')
        ax.set_xlabel('load cycles N')
        ax.set_ylabel('settlement [mm]', color='C0')
        ax.grid(alpha=0.3, which='both')
        ax2 = ax.twinx()
        ax2.semilogx(c[:, 0], c[:, 6], 's--', color='C3', label='$B_g$')
        ax2.set_ylabel("Marsal's $B_g$ [%]", color='C3')
        ax.set_title('%s: %d cycles between %g and %g kN at %g Hz%s' % (
            exp.runId, int(c[-1, 0]), exp.p['Fmin'] / 1e3, exp.p['Fmax'] / 1e3, exp.p['f'],
            ' (%d simulated)' % len(c) if len(c) != int(c[-1, 0]) else ''), fontsize=9)
        fig.tight_layout()
        saveFigure(fig, os.path.join(exp.out, 'cycles.png'))

    def writeGrading(self, exp, summary):
        """psd.csv (sieve [mm], % passing before and after loading) and grading.png."""
        before, after = exp.grading()
        writeAtomic(os.path.join(exp.out, 'psd.csv'), 'sieve_mm,passing_before,passing_after\n' + ''.join(
            '%g,%.6g,%.6g\n' % row for row in zip(grading.SIEVES_MM, before, after)))
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(7, 4.5))
        ax.semilogx(grading.SIEVES_MM, before, 'o-', label='before loading')
        ax.semilogx(grading.SIEVES_MM, after, 's-', label='after loading%s' % (
            ' (lost volume as fines)' if summary['lostAsFines'] else ''))
        ax.semilogx([grading.BBI_FINEST_MM, grading.topSize(before)], [0, 100], 'k--', lw=0.8,
                    label='boundary of maximum breakage (BBI)')
        ax.set_xlabel('sieve size [mm]')
        ax.set_ylabel('passing by mass [%]')
        ax.set_ylim(0, 100)
        ax.set_title('grading %s: $B_g$ = %.1f %%, $B_r$ = %.3f, BBI = %.3f'
                     % (exp.runId, summary['Bg'], summary['Br'], summary['BBI']), fontsize=9)
        ax.grid(alpha=0.3, which='both')
        ax.legend(fontsize=8)
        fig.tight_layout()
        saveFigure(fig, os.path.join(exp.out, 'grading.png'))

    def plot(self, exp, events):
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
        p = exp.p
        a = np.array(self.rows)
        fig, (ax, ax2) = plt.subplots(1, 2, figsize=(11, 4.5), gridspec_kw={'width_ratios': [3, 2]})
        ax.plot(a[:, 2] * 1e3, a[:, 1] / 1e3, '-', lw=0.8, color='C0', label='force of the grains on the plate')
        if np.isfinite(a[:, 5]).any():
            ax.plot(a[:, 2] * 1e3, a[:, 5] / 1e3, '-', lw=0.8, color='C1', alpha=0.7, label='applied force (eq. 8)')
        tc = np.array([e['t'] - exp.loading.t0 for e in events if e['kind'] == 'crush'])
        if len(tc):
            ax.plot(np.interp(tc, a[:, 0], a[:, 2]) * 1e3, np.interp(tc, a[:, 0], a[:, 1]) / 1e3, 'x', ms=4, color='C3',
                    label='crushing (%d)' % len(tc))
        ax.set_xlabel('plate displacement $\\delta$ [mm]')
        ax.set_ylabel('force F [kN]')
        ax.set_title('oedometric test %s: seed %d, f = %g Hz, $T_c$ = %s, $f_{t0}$ = %g Pa m, pattern %s\n%s law, %s load%s' % (
            exp.runId, p['seed'], p['f'], ('%g s' % p['Tc']) if p['Tc'] > 0 else 'every step', p['ft0'], p['pattern'],
            p['law'], p['loadMode'], (', fatigue b = %g' % p['fatigueExponent']) if p['fatigue'] else ''), fontsize=8)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8, loc='upper left')
        t = np.linspace(0, a[-1, 0], 400)
        ax2.plot(a[:, 0] * 1e3, a[:, 1] / 1e3, lw=0.8, label='grains on the plate')
        ax2.plot(t * 1e3, exp.loading.target(t) / 1e3, '--', color='k', lw=0.8, label='eq. 8')
        ax2.set_xlabel('loading time t [ms]')
        ax2.set_ylabel('force F [kN]')
        ax2.grid(alpha=0.3)
        ax2.legend(fontsize=8)
        fig.tight_layout()
        saveFigure(fig, os.path.join(exp.out, 'fd.png'))


def fdLine(row):
    return '%.9g,%.9g,%.9g,%d,%d,%.9g\n' % tuple(row)


# ---------------------------------------------------------------------------- VTK XML files
def _array(name, data, ncomp=1, kind='Float64'):
    fmt = '%d' if kind.startswith(('Int', 'UInt')) else '%.9g'
    body = ' '.join(fmt % v for v in np.asarray(data).ravel())
    return '<DataArray type="%s" Name="%s" NumberOfComponents="%d" format="ascii">%s</DataArray>\n' % (
        kind, name, ncomp, body)


def _unstructured(path, points, connectivity, offsets, types, pointData='', cellData=''):
    writeAtomic(path, ''.join([
        '<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">\n'
        '<UnstructuredGrid>\n<Piece NumberOfPoints="%d" NumberOfCells="%d">\n' % (len(points), len(offsets)),
        '<Points>\n' + _array('Points', points, 3) + '</Points>\n',
        '<Cells>\n' + _array('connectivity', connectivity, 1, 'Int64') + _array('offsets', offsets, 1, 'Int64') +
        _array('types', types, 1, 'UInt8') + '</Cells>\n',
        '<PointData>\n%s</PointData>\n<CellData>\n%s</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n'
        % (pointData, cellData)]))


def writeGrainsVtu(path, table):
    """The grains as vertices with their state (ParaView: Glyph, sphere, scaled by radius)."""
    n = len(table['id'])
    data = ''.join(_array(c, table[c], 1, 'Int64' if c in ('id', 'generation', 'parent', 'nAbraded') else 'Float64')
                   for c in ('id', 'r', 'mass', 'generation', 'parent', 'nAbraded', 'stressRatio', 'damage'))
    data += _array('velocity', table['velocity'], 3)
    points = np.column_stack([table['x'], table['y'], table['z']]) if n else np.zeros((0, 3))
    _unstructured(path, points, np.arange(n), np.arange(1, n + 1), np.ones(n, dtype=int), data)


def writeWallsVtu(path, steelIds, plateZ, radius):
    """The cylinder's facets (triangles), its bottom wall and the plate (squares a little wider than the
    cylinder, at their heights)."""
    pts, conn, offsets, types = [], [], [], []

    def cell(vertices, kind):
        conn.extend(range(len(pts), len(pts) + len(vertices)))
        pts.extend(vertices)
        offsets.append(len(pts))
        types.append(kind)
    h = 1.1 * radius
    for i in steelIds:
        b = O.bodies[i]
        if isinstance(b.shape, Facet):
            cell([tuple(b.state.pos + b.state.ori * v) for v in b.shape.vertices], 5)  # VTK_TRIANGLE
        else:  # the bottom wall
            z = b.state.pos[2]
            cell([(-h, -h, z), (h, -h, z), (h, h, z), (-h, h, z)], 9)  # VTK_QUAD
    cell([(-h, -h, plateZ), (h, -h, plateZ), (h, h, plateZ), (-h, h, plateZ)], 9)
    _unstructured(path, np.array(pts), conn, offsets, types)


def contactNetwork():
    """The real contacts as a force network: (points (n, 2, 3) [m], id1, id2, Fn [N], uN [m]). A sphere-sphere
    contact is the line between the two centres; one with a wall or a facet runs from the sphere's centre to
    the contact point. Read in one pass (harvest.contacts), the few wall contacts' points after it."""
    id1, id2, Fn, uN = harvest.contacts()
    pos, sphere = np.zeros((len(O.bodies), 3)), np.zeros(len(O.bodies), dtype=bool)
    for b in O.bodies:
        if b is not None:
            pos[b.id], sphere[b.id] = tuple(b.state.pos), isinstance(b.shape, Sphere)
    points = np.stack([pos[id1], pos[id2]], axis=1) if len(id1) else np.zeros((0, 2, 3))
    for k in np.flatnonzero(~(sphere[id1] & sphere[id2])):
        a, b = int(id1[k]), int(id2[k])
        c = tuple(O.interactions[a, b].geom.contactPoint)
        points[k] = (pos[a], c) if sphere[a] else (c, pos[b])
    return points, id1, id2, Fn, uN


def writeContactsVtu(path):
    """The contact force network: a line (VTK_LINE) per real contact with Fn, uN, id1, id2 as cell data
    (ParaView: Tube, radius and colour by Fn)."""
    points, id1, id2, Fn, uN = contactNetwork()
    n = len(id1)
    cells = (_array('Fn', Fn) + _array('uN', uN) + _array('id1', id1, 1, 'Int64') + _array('id2', id2, 1, 'Int64'))
    _unstructured(path, points.reshape(-1, 3), np.arange(2 * n), np.arange(2, 2 * n + 1, 2), np.full(n, 3), '', cells)


def writePvd(path, frames):
    """ParaView's time series: each frame at its loading time [s], a part per file of the frame (grains, walls,
    contacts; frames of older states have no contacts)."""
    writeAtomic(path, '<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n<Collection>\n' + ''.join(
        '<DataSet timestep="%.9g" part="%d" file="%s"/>\n' % (frame[0], part, name)
        for frame in frames for part, name in enumerate(frame[1:])) + '</Collection>\n</VTKFile>\n')
