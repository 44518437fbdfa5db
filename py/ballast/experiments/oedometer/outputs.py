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
import time

import numpy as np
from yade import O, plot
from yade.wrapper import Facet

from ... import _ballast, grading, harvest, runtime
from ...runfiles import strictJson, writeAtomic
from .. import cyclic, quasistatic
from ..quasistatic import INERTIAL_BOUND
from ..grains import bodies as grainBodies, kind as grainKind
from ..tracker import GrainStates
from . import figures
from ..vtk import unstructuredGrid, writeContactsVtu, writeGrainsVtu, writePvd

FD_COLUMNS = ('t', 'F', 'delta', 'nCrushed', 'nAbraded', 'Fapplied')
CHECK_COLUMNS = ('t', 'iter', 'crushes', 'maxStressRatio', 'maxCrushableRatio', 'inertialNumber')
EVENT_COLUMNS = ('kind', 't', 'iter', 'id', 'x', 'y', 'z', 'radius', 'value', 'strength', 'newIds', 'EkBefore',
                 'EeBefore', 'EkAfter', 'EeAfter', 'EkGrown', 'EeGrown')
ENERGY_KEYS = ('energyBefore', 'energyAfter', 'energyGrown')  # [kinetic, elastic] [J] of a replacement
GRAIN_COLUMNS = ('id', 'x', 'y', 'z', 'r', 'mass', 'generation', 'parent', 'nAbraded', 'stressRatio', 'damage')


@runtime.persistent('OedometerOutputs')
class Outputs:
    """Writes the run's files into the run directory, reading the run through a :class:`Probe` only.
    Replace it by any registered object with start(probe), bind(probe), finish(summary), rows, state()
    and fromState(s); its callbacks are record(), logCheck(), cycleEnd() and vtk()."""

    RECORDER, CHECKLOG, VTK, CYCLES = 'oedoRecorder', 'oedoCheckLog', 'oedoVtk', 'oedoCycles'

    def __init__(self):
        self.rows, self.checkRows, self.vtkFrames, self.cycleRows = [], [], [], []
        self.cpu = None   # process CPU [s] at the current cycle's start (a process's clock: not saved)
        self.cycleIter = None   # O.iter at the current cycle's start
        self.grains = GrainStates()
        self.exp = self.fd = None   # the Probe; fd.csv, opened at the first row written

    def state(self):
        return {'rows': runtime.packRows(self.rows), 'checkRows': runtime.packRows(self.checkRows),
                'vtkFrames': self.vtkFrames, 'cycleRows': self.cycleRows, 'cycleIter': self.cycleIter}

    @classmethod
    def fromState(cls, s, ref=None):
        obj = cls()
        obj.rows = runtime.unpackRows(s['rows'])
        obj.checkRows = runtime.unpackRows(s['checkRows'])
        obj.vtkFrames = [tuple(f) for f in s['vtkFrames']]
        obj.cycleRows = [tuple(r) for r in s['cycleRows']]
        obj.cycleIter = s.get('cycleIter')   # states saved before the steps per cycle: unknown for the open cycle
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
            engines.append(runtime.callback(self, 'vtk', virtPeriod=p['vtk'] * exp.T, initRun=True, label=self.VTK))
        O.engines = O.engines + engines
        self.cycleIter = O.iter
        self.bind(exp)
        self.open()

    def bind(self, exp):
        """Read the run through this Probe (at start and after a restore); the files are written again from the
        rows when the first is due (open). Every grain is painted by its state (originals sand-coloured)."""
        self.exp, self.fd, self.cpu = exp, None, time.process_time()
        self.grains = GrainStates()  # generations and abrasions from the engines' events
        self.grains.update(exp.degradingEngines())
        for b in grainBodies():
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

    def cycleTable(self):
        """cycles.csv as a DataFrame: the shared schema (experiments.cyclic), then Marsal's B_g after each cycle."""
        nan = math.nan
        rows, prev = [], (0, 0)
        for row in self.cycleRows:
            row = list(row) + [0.0] * (len(row) < 8)   # states saved before maxDamage: 7 entries
            row += [nan] * (16 - len(row))             # before the shared schema: 8, before the quasi-static measures: 11
            rows.append(dict(zip(cyclic.COLUMNS + ('Bg',), (
                row[0], row[1], row[2], row[3], row[4] - prev[0], row[5] - prev[1], row[4], row[5], row[7], row[8],
                row[9], row[10], row[11], row[12], row[13], row[14], row[15], row[6]))))
            prev = row[4:6]
        return cyclic.table(rows, ('Bg',), self.exp.jumper, self.exp.stepChoice)

    def cycleEnd(self):
        """A row of cycles.csv (experiments.cyclic): the cycle just ended, the permanent settlement (delta at the
        cycle's lowest force, its end), the resilient displacement (the largest delta within the cycle minus that:
        what the sample springs back from its deepest point, >= 0 by construction, also in the first cycle, where
        the plate may sink on after the peak), the crushes and abrasions, the largest fatigue damage D of a grain
        (0 without fatigue), the largest sigma/f_t of a crushable grain at the cycle's checks, the grains, the CPU
        time, and Marsal's B_g after it."""
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
        checks = [row for row in self.checkRows if (simulated - 1) * exp.T <= row[0] <= t]
        ratios = [row[5] for row in checks if len(row) > 5]
        inertialMax, inertialMedian = quasistatic.cycleStats([row[6] for row in checks if len(row) > 6])
        p = exp.p
        mass = O.bodies[exp.loading.plate].state.mass + quasistatic.bedMass(p, grainKind().masses(grainKind().ids()),
                                                                            exp.ownStep())
        cpu = time.process_time()
        self.cycleRows.append((k, t, settlement, deepest - settlement, crushed, abraded, grading.marsal(*exp.grading()),
                               exp.counter('crush', 'maxDamage'), max(ratios) if ratios else math.nan,
                               len(grainBodies()), cpu - self.cpu if self.cpu is not None else math.nan, O.dt,
                               O.iter - self.cycleIter if self.cycleIter is not None else math.nan, inertialMax,
                               inertialMedian, quasistatic.responseRatio(exp.T, mass, p['Fmax'] - p['Fmin'],
                                                                         deepest - settlement)))
        self.cpu, self.cycleIter = cpu, O.iter
        cyclic.write(os.path.join(exp.out, 'cycles.csv'), self.cycleTable())

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
        kind = grainKind()   # what a grain is: its ids, centre, equivalent radius, mass
        ids = kind.ids()
        x, r, m = kind.centres(ids), kind.radii(ids), kind.masses(ids)
        v = np.array([tuple(O.bodies[int(i)].state.vel) for i in ids]).reshape(-1, 3)
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
        figures.fdFigure(exp, self.rows, events)
        before, after = exp.grading()
        writeAtomic(os.path.join(out, 'psd.csv'), 'sieve_mm,passing_before,passing_after\n' + ''.join(
            '%g,%.6g,%.6g\n' % row for row in zip(grading.SIEVES_MM, before, after)))
        figures.gradingFigure(exp, summary, before, after)
        if len(self.cycleRows) > 1:
            figures.cyclesFigure(exp, self.cycleTable())
        writeAtomic(os.path.join(out, 'summary.json'), json.dumps(strictJson(summary), indent=1))  # last: the run's outputs are all there

def fdLine(row):
    return '%.9g,%.9g,%.9g,%d,%d,%.9g\n' % tuple(row)


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
    unstructuredGrid(path, np.array(pts), conn, offsets, types)
