"""The oedometric test of sections 4-5 as an experiment on the base
:class:`ballast.experiments.base.Experiment`: parameters (checked when it is built), then prepare()
(the packing), load() (the load cycle of eq. 8 with both engines) and summary().

    from ballast.oedometer import Oedometer
    run = Oedometer(seed=2, f=4, pattern=14)
    run.prepare()
    run.load()
    run.summary()

The pieces are registered objects (:mod:`ballast.runtime`) that can be replaced without editing the
package: ``packing`` (default :class:`StoredPacking`; returns the :class:`Rig`), ``load``
(:class:`PlateLoad`, :class:`ServoLoad` or :class:`DisplacementLoad` by ``loadMode``), ``outputs``
(:class:`Outputs`, which reads the run through a :class:`Probe`).

The run saves itself at the start and at the end of loading (and every ``saveEvery``).
``Oedometer.reopen(path)`` loads such a state in any process and gives the experiment back, ready to
``load()`` on (``readOnly=True``: to inspect it, writing nothing); a plain ``O.load(path)`` followed by
``O.run()`` rebuilds it at its first callback.

A run keeps ``run.json`` in its folder: ``"status": "running"`` from the start (with the last state
saved), ``"finished"`` once every output is written. A run killed on the way (``running``, no
summary.json) gets its outputs up to its last state back with ``Oedometer.rebuild(runDir)``
(``yade -x -n scripts/oedometer.py --rebuild RUNDIR``): into a new folder <run id>-2.
"""
import math
import os

import numpy as np
from yade import O

from ... import runtime
from ...names import fmtTime
from ...params import validate
from ...runfiles import writeAtomic
from ..parameters import CYCLE_JUMP, POLYHEDRON_COST
from .. import chain, grains
from ...settlementlaws import bedChanged
from ..base import Experiment
from ..cyclic import Cyclic
from ..rundir import resumableState
from .loading import MODES
from .outputs import Outputs
from .packing import StoredPacking
from .parameters import OWNER, PARAMS, OedometerParameters
from . import summary
from .probe import Probe, counter, degradingEngines, engine

CONTAINMENT, CYCLE_CLOSED = 'oedoContainment', 'oedoJumpCycle'


@runtime.persistent('Oedometer')
class Oedometer(Cyclic, Experiment):
    """One realization of the paper's oedometric test. Keyword arguments: any parameter of
    :data:`ballast.oedometer.parameters.PARAMS` (a bad value raises ParamError here) or
    ``parameters=check(...)`` (checked already), and the pieces ``packing``, ``load``, ``outputs``."""

    NAME = 'oedometer'
    Parameters = OedometerParameters
    # parameters a reopened run may change: where and how it reports, not the physics
    REOPEN_PARAMS = ('results', 'runId', 'progress', 'vtk', 'saveEvery', 'timing', 'cycles', 'resume') + tuple(CYCLE_JUMP)

    def __init__(self, packing=None, load=None, outputs=None, parameters=None, **params):
        self.packing = packing if packing is not None else StoredPacking()
        self.outputs = outputs if outputs is not None else Outputs()
        self.rig = self.initial = self.probe = None
        self.loading = load
        self.maxProtrusion, self.nEscaped = 0.0, 0
        self.jumper = None           # cycle jumping (jump): experiments.cyclejump
        self.lastClosed = 0          # the last cycle handed to cycleDone
        self.stoppedBy = None        # why the last load() ended: 'cycles', 'stopAt', 'quiet' or 'force'
        Experiment.__init__(self, parameters, **params)
        if self.loading is None:
            self.loading = MODES[self.p['loadMode']]()
            self.adopt()

    def __repr__(self):
        return '<Oedometer %s: %s>' % (self.runId, ', '.join('%s=%r' % (k, self.p[k]) for k in ('seed', 'f', 'Tc', 'ft0',
                                                                                                'pattern')))

    @property
    def T(self):
        return self.p.T

    @property
    def cylinder(self):
        return self.rig.cylinder if self.rig is not None else None

    def pieces(self):
        return Experiment.pieces(self) + [self.packing, self.loading, self.outputs, self.rig, self.jumper,
                                          self.stepChoice]

    # ------------------------------------------------------------------ the experiment
    def checkOutputs(self):
        """Before any work: the results folder and the packing store can be created and written to."""
        Experiment.checkOutputs(self)
        if hasattr(self.packing, 'checkOutputs'):
            self.packing.checkOutputs(self)

    def warnings(self):
        """What the run should know of its parameters, said when it starts and kept in summary.json: density scaling
        (quasiStatic or densityStep) changes whether this oedometer avalanches (docs/performance.md)."""
        p = self.p
        said = ['%s %g: density scaling changes whether the oedometer avalanches (seed 2 at 8 Hz with Fmin 150 kN: 212 '
                'grains crushed in cycle 1 under quasiStatic 1e-3, 1 at the paper\'s step; over 20 seeds it moved the '
                'share of avalanching runs by 10-25 points; with the first cycle at the paper\'s step, quasiStaticStart '
                '1, 3 of 5 quiet beds avalanched within 5 cycles, against 1 at the paper\'s step: docs/performance.md); '
                'for studies of means that accept it, not for reproducing a realization' % (k, p[k])
                for k in ('quasiStatic', 'densityStep') if p[k] > 0]
        if p['grain'] == 'polyhedron':
            said.append("grain 'polyhedron': YADE's polyhedra cost %s; for small samples (docs/grains.md)"
                        % POLYHEDRON_COST)
        return said

    def prepare(self):
        """The packing (built, or loaded from the store), settled in the cylinder."""
        self.openRunDirectory()
        self.adopt()
        self.rig = self.packing.prepare(self)
        self.adopt()
        return self

    def load(self, cycles=None):
        """Load until the run has `cycles` cycles in all (eq. 8, then between Fmax and Fmin; a state saved
        mid-run goes on to that number), or, if it has them already, one more; `cycles` given: that many
        more. Then write every output and save the state. Returns the summary."""
        p = self.p
        if cycles is not None:
            cycles = validate(OWNER + '.load', {'cycles': PARAMS['cycles']}, 'cycles', cycles)
        if self.initial is None:
            if self.rig is None:
                self.prepare()
            self.startLoading()
        if self.syncJumping():   # a run reopened with jump
            self.probe.jumper = self.jumper
        if chain.engine(CYCLE_CLOSED) is None:   # a state saved before every run read its closed cycles
            self.readCycles()
        t0 = self.loading.t0
        done = math.floor((O.time - t0 + 0.5 * O.dt) / self.T) + self.cyclesJumped()
        total = done + cycles if cycles is not None else (p['cycles'] if done < p['cycles'] else done + 1)
        tStart, tEnd = O.time, t0 + (total - self.cyclesJumped()) * self.T
        if self.jumper is not None:
            self.jumper.target = total
        self.stoppedBy = 'cycles'
        if p['stopAt'] > 0 and done == 0:  # an early stop, a step past the crushing check after stopAt T
            stop = t0 + p['stopAt'] * self.T + 1.5 * (p['Tc'] or O.dt)
            if stop < tEnd:
                tEnd, self.stoppedBy = stop, 'stopAt'
        # each jump brings the end nearer by the cycles it jumped
        end = tEnd if self.jumper is None or self.stoppedBy == 'stopAt' else (
            lambda: t0 + (total - self.cyclesJumped()) * self.T)
        self.runUntil(self.stopCondition(), tEnd=end, phase='load', simSpan=tEnd - tStart, simStart=tStart,
                      extra=lambda: 'cycle %d/%d  F=%.0f kN  delta=%.1f mm  crushed %d  abraded %d' % (
                          min(math.floor((O.time - t0) / self.T) + 1 + self.cyclesJumped(), total), total,
                          self.loading.force() / 1e3, self.loading.delta() * 1e3, self.counter('crush', 'nCrushed'),
                          self.counter('abrasion', 'nAbraded')) + self.outputs.inertialInfo())
        return self.finish()

    def readCycles(self):
        """The callback after outputs.cycleEnd, which closes the cycle's row, at the same steps: the cycle closed
        goes to the checkpoints and the jumper (cyclic.Cyclic.cycleDone)."""
        rows = chain.engine(self.outputs.CYCLES)
        O.engines = O.engines + [runtime.callback(self, 'cycleEnded', virtPeriod=self.T, virtLast=rows.virtLast,
                                                  label=CYCLE_CLOSED)]

    def cyclesJumped(self):
        """Cycles advanced by cycle jumping, not simulated (0 without jump)."""
        return self.jumper.jumped if self.jumper is not None else 0

    def cyclesDone(self):
        """Cycles closed, simulated and jumped."""
        rows = self.outputs.cycleRows
        return int(rows[-1][0]) if rows else 0

    def cycleFrame(self):
        return self.outputs.cycleTable()

    def cycleEnded(self):
        """After outputs.cycleEnd at each cycle's end: the row just closed, once, to cyclic.Cyclic.cycleDone."""
        rows = self.outputs.cycleRows
        if not rows or rows[-1][0] <= self.lastClosed:
            return
        self.lastClosed = rows[-1][0]
        totals = [(r[4], r[5]) for r in rows[-2:]]   # crushed and abraded so far, after the cycle before and this one
        if len(totals) == 1:
            totals.insert(0, (0, 0))
        crushed, abraded = zip(*totals)
        last = tuple(rows[-1]) + (math.nan,) * (16 - len(rows[-1]))   # rows of older states lack the measures
        self.cycleDone(rows[-1][0], rows[-1][2], bool(bedChanged(crushed, abraded, totals=True)[-1]), last[13], last[15])

    def stopCondition(self):
        """The load phase's end test (checked every 200 steps): the displacement load has reached Fmax, or
        (stopQuiet) after the peak of eq. 8 the applied load is below stopQuiet Fmax and no grain has
        crushed for quietTime. Sets stoppedBy ('force', 'quiet'; summary.json says it)."""
        p, t0 = self.p, self.loading.t0
        last = {'n': self.counter('crush', 'nCrushed'), 't': O.time}

        def done():
            if self.loading.done():
                self.stoppedBy = 'force'
                return True
            if p['stopQuiet'] <= 0:
                return False
            n = self.counter('crush', 'nCrushed')
            if n != last['n']:
                last['n'], last['t'] = n, O.time
            t = O.time - t0
            if (t > p.peakTime() and self.loading.target(t) < p['stopQuiet'] * p['Fmax']
                    and O.time - last['t'] >= p['quietTime']):
                self.stoppedBy = 'quiet'
                return True
            return False
        return done

    def finish(self, atEnd=True):
        """The last row, the state at the end, every output file, run.json 'finished'; returns the summary.
        atEnd=False (rebuild): the outputs of the state as it is, without a last row or frame."""
        if atEnd:
            self.outputs.record()  # the last row, at the end of the cycle
            self.outputs.cycleEnd()
            if self.p['vtk'] > 0:
                self.outputs.vtk()  # the frame at the end of the cycle
            self.checkContainment()
        s = self.finishRun(self.writeOutputs)
        self.say('done in %s: peak F %.0f kN at delta %.2f mm, delta max %.2f mm, %d crushed, %d abraded, %d '
                 'steps; results in %s%s' % (fmtTime(s['wallSeconds']), s['peakForce'] / 1e3, s['deltaAtPeak'] * 1e3,
                                             s['deltaMax'] * 1e3, s['nCrushed'], s['nAbraded'], s['steps'], self.out,
                                             ''.join('; ' + w for w in self.containmentWarnings())))
        return s

    def containmentWarnings(self):
        """What makes the run no oedometer, found while it ran (kept in summary.json's warnings): grains whose centre
        left the cylinder."""
        if self.nEscaped == 0:
            return []
        return ['%d grain(s) left the cylinder (their centres past its wall, the bottom or the plate): the forces and '
                'deltas are not an oedometer\'s' % self.nEscaped]

    def writeOutputs(self):
        """Every output file (outputs.finish) and timing.txt; returns the summary."""
        s = self.summary()
        self.outputs.finish(s)
        if self.p['timing']:
            self._writeTiming()
        return s

    def savedParams(self, values, units):
        """States saved before 2026-12 (units 1) gave saveEvery and vtk in seconds of loading: f of them a cycle."""
        if units < 2:
            for k in ('saveEvery', 'vtk'):
                values[k] = values[k] * values['f']
        return values

    def rebuildHint(self, path):
        return 'Oedometer.rebuild(%r) writes them' % path

    def startLoading(self):
        """The start of load(): seat the plate, add the engines and the recorders, save the state."""
        p = self.p
        self.loading.start(p, self.rig)
        self.addEngines(self.loading.t0)
        self.startTimeStep(self.loading.plate, self.T)
        x, r, m = grains.arrays()
        d = grains.sieve()[0]   # the grading's sizes (grains.kind)
        self.initial = {'massInitial': float(np.sum(m)), 'nGrainsInitial': len(r),
                        'volumeGrains': float(np.sum(grains.volumes())), 'diameters': d.tolist(), 'masses': m.tolist()}
        self.startJumping()
        self.probe = Probe(p, self.loading, self.rig, self.dir, self.initial, self.jumper, self.stepChoice)
        self.outputs.start(self.probe)
        self.readCycles()
        # containment at simulated times (the recorder's period): the same in every identical run
        O.engines = O.engines + [runtime.callback(self, 'checkContainment', virtPeriod=self.T / p['samples'],
                                                  label=CONTAINMENT)]
        self.startSaver(self.loading.t0, self.T)
        if p['timing']:
            O.timingEnabled = True
        self.say('load: plate at %.4f m on %d grains (%.1f kg, porosity %.3f), F = Fmax/2 [sin(2 pi f t - pi/2) + 1],'
                 ' Fmax = %.4g N, f = %g Hz, dt = %.2e s' % (self.loading.z0, len(r), self.initial['massInitial'],
                                                            self.porosity0(), p['Fmax'], p['f'], O.dt))
        self.save(os.path.join(self.out, 'state-start.yade.gz'))

    # ------------------------------------------------------------------ engines and grains
    engine, degradingEngines, counter = staticmethod(engine), staticmethod(degradingEngines), staticmethod(counter)

    def events(self):
        """The events of both engines, in time order."""
        return self.probe.events()

    def grading(self):
        """Percentage passing each sieve before loading and now (Probe.grading)."""
        return self.probe.grading()

    def porosity0(self):
        """Porosity under the plate at the start of loading [-]."""
        return 1 - self.initial['volumeGrains'] / (math.pi * self.cylinder.Rin ** 2 * self.loading.z0)

    def checkContainment(self):
        """Largest protrusion of a grain out of the cylinder (past its flat inner faces, at diameter/2; the
        bottom; the plate) and the number of grains whose centre left it. Called at simulated times (every
        T/samples) and at the end."""
        x, r, _ = grains.arrays()
        if len(r) == 0:
            return
        cyl = self.cylinder
        c = O.bodies[cyl.ids[0]].state.pos - cyl.pos0[0]
        rho = np.hypot(x[:, 0] - c[0], x[:, 1] - c[1])
        zTop = self.loading.top()
        prot = np.maximum.reduce([rho + r - cyl.Rin, c[2] - (x[:, 2] - r), x[:, 2] + r - zTop])
        self.maxProtrusion = max(self.maxProtrusion, float(prot.max()))
        self.nEscaped = max(self.nEscaped, int(np.sum((rho > cyl.Rin) | (x[:, 2] < c[2]) | (x[:, 2] > zTop))))

    # ------------------------------------------------------------------ results
    def summary(self):
        """What summary.json holds (summary.summary)."""
        return summary.summary(self)

    def _writeTiming(self):
        import contextlib
        import io
        from yade import timing
        buf = io.StringIO()
        with contextlib.redirect_stdout(buf):
            timing.stats()
        writeAtomic(os.path.join(self.out, 'timing.txt'), buf.getvalue())

    # ------------------------------------------------------------------ saving and reopening
    def state(self):
        """Everything the experiment needs to go on after O.load(): JSON-able."""
        return dict(self.baseState(), packing=runtime.ref(self.packing), loading=runtime.ref(self.loading),
                    outputs=runtime.ref(self.outputs), rig=runtime.ref(self.rig), initial=self.initial,
                    maxProtrusion=self.maxProtrusion, nEscaped=self.nEscaped, stoppedBy=self.stoppedBy,
                    jumper=runtime.ref(self.jumper), lastClosed=self.lastClosed,
                    stepChoice=runtime.ref(self.stepChoice))

    @classmethod
    def fromState(cls, s, ref):
        exp = cls.__new__(cls)
        exp.setBaseState(s, ref)
        exp.packing, exp.loading, exp.outputs, exp.rig = (ref(s[k]) for k in ('packing', 'loading', 'outputs', 'rig'))
        exp.initial, exp.maxProtrusion, exp.nEscaped = s['initial'], s['maxProtrusion'], s['nEscaped']
        exp.stoppedBy = s.get('stoppedBy')  # states saved before the stop conditions: unknown
        exp.jumper = ref(s['jumper']) if s.get('jumper') is not None else None   # none before cycle jumping
        exp.stepChoice = ref(s['stepChoice']) if s.get('stepChoice') is not None else None   # none before 2026-12
        rows = exp.outputs.cycleRows   # states saved before the closed cycle was kept: the last row's
        exp.lastClosed = s.get('lastClosed', rows[-1][0] if rows else 0)
        exp.probe = None
        return exp

    def restored(self):
        """After the runtime rebuilt the scene's objects: the pieces read this run again, and Newton scales
        densities again if the run does (YADE's O.load leaves it off)."""
        self.loading.bind(self.p)
        self.resumeDensityScaling()
        if self.initial is not None:
            self.probe = Probe(self.p, self.loading, self.rig, self.dir, self.initial, self.jumper, self.stepChoice)
            self.outputs.bind(self.probe)

    def reopened(self):
        self.restored()
        # a folder already there is a killed run's own (resumeKilled's into=): it is marked once its physics is checked
        if not self.dir.readOnly and self.dir.path is None:
            self.dir.create()
            self.markRunning(continues=self.dir.previous, continuesState=self.dir.source, fromIter=O.iter)
        self.say('reopened %s at t = %.6f s (loading time %.6f s) -> %s' % (
            self.dir.wanted, O.time, O.time - self.loading.t0, self.out or 'read only, no run directory'))

    def resumed(self, state):
        """Experiment.resumeKilled's last step: this run, reopened from `state` in the folder of its killed process,
        loads on to the cycles it was going to (fd.csv, the check log and the frames are written again from the rows
        saved with the state, so the rows after it are taken again, not doubled)."""
        self.say('resume: run %s goes on in %s from %s (loading time %.6f s of %.6f s)' % (
            self.runId, self.out, os.path.basename(state), O.time - self.loading.t0,
            (self.p['cycles'] - self.cyclesJumped()) * self.T))
        return self.load()

    @classmethod
    def rebuild(cls, runDir, **overrides):
        """The outputs of a killed run (run.json 'running', no summary.json) up to its newest intact state:
        reopened and finished as it is (no last row), into a new folder RUNDIR-2 beside it (whatever run id the
        state holds). runDir: the run's folder or a state file. Returns the experiment. RuntimeError where the
        folder holds no state to rebuild from (a finished run, damaged states: why, in one line)."""
        if os.path.isfile(runDir):
            state, folder = runDir, os.path.dirname(os.path.abspath(runDir))
        else:
            folder = os.path.abspath(runDir)
            state, why = resumableState(folder, preferLast=False)
            if state is None:
                raise RuntimeError('nothing to rebuild in %s: %s' % (runDir, why))
        where = {'results': os.path.dirname(folder), 'runId': os.path.basename(folder)}
        exp = cls.reopen(state, **dict(where, **overrides))
        exp.finish(atEnd=False)
        return exp


__all__ = ['Oedometer', 'PARAMS']
