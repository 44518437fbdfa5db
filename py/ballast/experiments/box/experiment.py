"""The box test as an experiment on the base (docs/box.md): a steel box, a ballast bed placed and
compacted in layers (:mod:`.bed`), a sleeper section seated on it and loaded cycle after cycle by the
sine between the seating and the peak load (or a CSV history, :mod:`.loadhistory`), with the crushing
and abrasion engines of the oedometer and all their options.

    from ballast.experiments.box import BoxTest
    test = BoxTest(cycles=3)
    test.run()            # prepare() and load(); writes cycles.csv, samples.csv, grading.csv, crushes.csv, figures
    test.load(10)         # ten cycles more

The sleeper is a rigid block (a YADE Box) free to settle and, with tilt, to rotate about the box's
width axis; the load acts at its centre through YADE's InterpolatingDirectedForceEngine (no Python per
step). Its permanent settlement is read at the end of each cycle (at the seating load), its resilient
deflection as the largest settlement of the cycle less that.
"""
import os

import numpy as np
from yade import O, Vector3, plot, utils
from yade.wrapper import FrictMat, InterpolatingDirectedForceEngine

from ... import runtime
from ...params import requireWritableDir
from .. import breakage, chain, grains, preparation, scene
from ..parameters import CYCLE_JUMP
from ...settlementlaws import bedChanged
from ..base import Experiment
from ..cyclic import Cyclic, RecordedCycles, appendSample
from . import bed, outputs
from .parameters import OWNER, BoxParameters
from .recorder import LOAD, Recorder

RECORDER, FRAMES = 'boxRecorder', 'boxFrames'
SEAT_STILL = (0.01, 2e-6)     # ([s], [m]): seated when the sleeper moved less than this over that time
SEAT_TIME = (0.02, 0.2)       # [s] shortest and longest seating (a bed of spheres creeps under a sleeper: docs/box.md)


SETTLEMENT_RANGE = 0.25   # [-] of the bed's depth: a settlement beyond it is a punch, not a settlement
TILT_RANGE = 0.05         # [rad] (3 degrees): a tilt beyond it is an overturn


@runtime.persistent('BoxTest')
class BoxTest(RecordedCycles, Cyclic, Experiment):
    """A sleeper section on a crushable ballast bed in a box under repeated loads. Keyword arguments: any
    parameter of :data:`ballast.experiments.box.parameters.PARAMS`, or parameters=check(...)."""

    NAME = 'box'
    QUASI_STATIC_FINDING = ('validated on the default box at 3 Hz for the permanent settlement (within the seed '
                            'scatter of the paper\'s step through cycle 5, 5 seeds, no grain crushed); the resilient '
                            'deflection came out 14 % larger on average (10-29 % in 4 of 5 pairs) and the tilt larger '
                            'too: not for the resilient deflection; at ft0 3.63e5 it crushed the grain the paper\'s '
                            'step crushed (2 seeds of 5), but on 1 of 5 beds 3 grains under the sleeper that the '
                            'paper\'s step did not crush, in cycle 1: not validated for crushing')
    Parameters = BoxParameters
    SAVER = 'boxSaver'   # the checkpoint callback's label in the states box tests have saved (records go on from them)
    # where and how it reports, and how its cycles are simulated (cycle jumping)
    # bedDir: a reopened run has its bed; where beds are stored (another machine's path) changes nothing in it
    REOPEN_PARAMS = ('results', 'runId', 'progress', 'vtk', 'cycles', 'saveEvery', 'continueFrom', 'resume',
                     'bedDir') + tuple(CYCLE_JUMP)

    def __init__(self, parameters=None, **params):
        self.rig = self.recorder = self.jumper = None
        self.bedTop = self.porosity = self.bedFile = None
        self.nEscaped, self.nCrib, self.initial, self.gradings, self.frames = 0, 0, None, [], []
        self.onFloor = False   # the sleeper reached the box's floor: the run stops there
        self.rangeWarnings = []   # where the run left the range a box test is for (said once each, in the summary)
        self.target = None     # the cycles done when the load() under way ends
        Experiment.__init__(self, parameters, **params)

    def savedParams(self, values, units):
        """States saved before 2026-12 (units 1) had vtk a flag (frames at the graded cycles): now a frame every cycle
        or none."""
        if units < 2:
            values['vtk'] = 1.0 if values['vtk'] else 0.0
        return values

    def pieces(self):
        return Experiment.pieces(self) + [self.rig, self.recorder, self.jumper, self.stepChoice]

    # ------------------------------------------------------------------ the experiment
    def prepare(self):
        """The box, the bed in layers and the sleeper seated on it under the seating load."""
        self.openRunDirectory()
        self.rig, self.bedTop, self.porosity, self.nEscaped, self.bedFile = bed.prepare(self)
        self.adopt()
        self.seat()
        return self

    def checkOutputs(self):
        """Before any work: the results folder and the bed store can be created and written to."""
        Experiment.checkOutputs(self)
        requireWritableDir(OWNER, 'bedDir', bed.folder(self.p))

    def seat(self):
        """The sleeper on the highest grain under its footprint, the engines, the time step, the seating load."""
        p, rig = self.p, self.rig
        lo, hi = grains.bounds()   # the grains' own extent: a clump is not its equivalent sphere
        w, h, L = p['sleeperWidth'], p['sleeperHeight'], p.sleeperLength()
        foot = (lo[:, 0] < w / 2) & (hi[:, 0] > -w / 2)
        z0 = float(np.max(hi[foot, 2]))
        rig.sleeperMat = FrictMat(young=p['steelYoungRatio'] * p['young'], poisson=p['steelPoisson'],
                                  frictionAngle=p['sleeperFriction'], density=p['sleeperMass'] / (w * h * L),
                                  label='sleeper')
        O.materials.append(rig.sleeperMat)
        b = utils.box((0, 0, z0 + h / 2), (w / 2, L / 2, h / 2), material=rig.sleeperMat, color=(.5, .5, .45),
                      mask=scene.STEEL_MASK)
        b.state.blockedDOFs = 'xyXYZ'   # seated level (as placed on a levelled bed); tilt frees Y once cycling starts
        b.state.isDamped = False  # the load on it is what acts on it, as on the oedometer's plate
        rig.sleeper = O.bodies.append(b)
        chain.newton().damping = p['damping']
        history = p.history()
        chain.insertBeforeNewton([InterpolatingDirectedForceEngine(
            ids=[rig.sleeper], times=[O.time, O.time + 1.0], magnitudes=[history.seat, history.seat],
            direction=Vector3(0, 0, -1), wrap=True, label=LOAD)])
        O.dt = p['dtSafety'] * utils.PWaveTimeStep()
        self.say('seat: sleeper %.3g x %.3g x %.3g m, %.4g kg, on the bed at %.4f m (%d grains, porosity %.3f), %g N'
                 % (w, L, h, p['sleeperMass'], z0, len(lo), self.porosity, history.seat))
        if p['cribDepth'] > 0:
            self.nCrib = bed.crib(self, z0)
        t0 = O.time
        self.runUntil(preparation.still(rig.sleeper, *SEAT_STILL, after=t0 + SEAT_TIME[0]), tEnd=t0 + SEAT_TIME[1],
                      phase='seat', checkEvery=100)
        self.recorder = Recorder(rig.sleeper, None, None, history.period)
        self.adopt()

    def startCycling(self):
        """The load cycle from now on, the crushing and abrasion engines, the recorder, the fast-step options, the
        first state saved. The seating ran without the engines: the bed at the start of cycling is the reference
        of the mass ledger and the gradings."""
        p, rec = self.p, self.recorder
        rec.t0, rec.z0 = O.time, rec.underside()
        self.addEngines(rec.t0)
        history = p.history()
        if p['tilt']:
            O.bodies[rec.sleeper].state.blockedDOFs = 'xyXZ'
        times, forces = history.table()
        load = chain.engine(LOAD)
        load.times, load.magnitudes = [rec.t0 + t for t in times], forces
        O.engines = O.engines + [runtime.callback(self, 'sample', virtPeriod=history.period / p['samples'],
                                                  virtLast=rec.t0, initRun=True, label=RECORDER)]
        self.startCycles(rec.t0, history.period)
        plot.reset()
        plot.plots = {'settlement': ('F',)}   # YADE's live plot: the load against the settlement
        self.startTimeStep(rec.sleeper, history.period)
        x, r, m = grains.arrays()
        self.initial = {'massInitial': float(np.sum(m)), 'nGrainsInitial': len(r), 'diameters': grains.sieve()[0].tolist(),
                        'masses': m.tolist(), 'zBase': rec.z0, 'ids': grains.kind().ids().tolist()}
        self.gradings = [breakage.grading(self, 0)]
        self.frames = []
        self.startFrames()
        self.save(os.path.join(self.out, 'state-start.yade.gz'))

    def sample(self):
        """The recorder's sample (a callback at simulated times); after the cycles of the 1-2-5 series (1, 2, 5,
        10, 20, ...) the grading and a VTK frame."""
        p = self.p
        if getattr(self, '_peak', None) is None:   # the load history is read once a process (loadFile: a CSV)
            self._peak = p.history().peak
        k = self.recorder.sample(p, p['sleeperWidth'] * p.sleeperLength(), self._peak, self.ownStep())
        row = self.recorder.samples[-1]
        if not self.onFloor and self.recorder.underside() < self.p['dMin'] / 2:
            # YADE has no contact between a box and a wall: the sleeper would fall through the floor
            self.onFloor = True
            self.say('the sleeper reached the box\'s floor (settlement %.1f mm in cycle %d): the bed under it is gone; '
                     'the run stops here' % (1e3 * row[4], row[1] + 1))
        appendSample(self, row)
        plot.addData(**dict(zip(('t', 'cycle', 'F', 'Fgrains', 'settlement'), row[:5])))
        if k:
            outputs.writeCycles(self)   # a killed run keeps its cycles (written atomically)
            if breakage.gradedCycle(k):
                self.grade(k)
            row = dict(zip(Recorder.CYCLE_COLUMNS, self.recorder.cycles[-1]))
            self.warnOutOfRange(row)
            self.cycleDone(k, row['settlement'], bool(bedChanged(row['crushes'], row['abrasions'])), row['inertialMax'],
                           row['responseRatio'])

    def warnOutOfRange(self, row):
        """Once each: a settlement beyond SETTLEMENT_RANGE of the bed's depth or a tilt beyond TILT_RANGE, where the
        sleeper punches into the bed or overturns and a box test no longer measures a sleeper on ballast."""
        p = self.p
        checks = (('settlement', row['settlement'] > SETTLEMENT_RANGE * p['bedDepth'],
                   'settlement %.1f mm is more than %d %% of the bed\'s depth (%.0f mm): the sleeper punches into the '
                   'bed' % (1e3 * row['settlement'], 100 * SETTLEMENT_RANGE, 1e3 * p['bedDepth'])),
                  ('tilt', abs(row['tilt']) > TILT_RANGE,
                   'tilt %.3f rad is beyond %g rad: the sleeper overturns' % (row['tilt'], TILT_RANGE)))
        for what, out, words in checks:
            if out and not any(w.startswith(what) for w in self.rangeWarnings):
                self.rangeWarnings.append('%s (cycle %d); a box test is for a sleeper seated on its bed' % (
                    words, row['cycle']))
                self.say('warning: ' + self.rangeWarnings[-1])

    def startFrames(self):
        """With vtk: a VTK frame now and every vtk load cycles (a callback at simulated times from the start of
        cycling; a run reopened with vtk gets it then)."""
        p, rec = self.p, self.recorder
        if p['vtk'] > 0 and chain.engine(FRAMES) is None:
            self.frame()
            O.engines = O.engines + [runtime.callback(self, 'frame', virtPeriod=p['vtk'] * rec.period,
                                                      virtLast=O.time, label=FRAMES)]

    def frame(self):
        """A frame of boxes.pvd (outputs.writeFrame), once at a time."""
        if not self.frames or self.frames[-1][0] < O.time - self.recorder.t0:
            outputs.writeFrame(self)

    def cycleFrame(self):
        return outputs.cycleTable(self)

    def cyclingStarted(self):
        return self.recorder is not None and self.recorder.t0 is not None

    def prepared(self):
        return self.recorder is not None

    def stopReason(self):
        return 'the sleeper is on the floor' if self.onFloor else None

    def loadText(self):
        h = self.p.history()
        return '%s, %.4g-%.4g N, %.3g s each' % (h.source, h.seat, h.peak, self.recorder.period)

    def stateText(self):
        last = self.recorder.samples[-1] if self.recorder.samples else (0,) * 8
        return 'settlement %.2f mm, %d crushed, %d abraded' % (1e3 * last[4], last[6], last[7])

    def atStop(self):
        if self.onFloor and self.recorder.partial is None:
            self.sample()   # a last sample at the stop, and the cycle it cut short closed with it
            self.recorder.closePartial(self.p, self.ownStep())

    def doneText(self, s):
        return '%d cycles%s, settlement %.2f mm (resilient %.3f mm), %d crushed, %d abraded' % (
            s['cycles'], ' and cycle %d cut short on the floor' % self.recorder.partial if self.recorder.partial else '',
            1e3 * s['settlement'], 1e3 * s['resilient'], s['nCrushed'], s['nAbraded'])

    def writeOutputs(self):
        return outputs.write(self)

    def resumed(self, state):
        """Experiment.resumeKilled's last step: this run, reopened from `state` in the folder of its killed
        process, cuts samples.csv back to the state's time (the rows after it are taken again) and goes on to the
        target of the load() it was in (a state saved before that load() set one: `cycles` more)."""
        outputs.cutSamples(self, O.time - self.recorder.t0)
        if self.target is None:
            self.target = self.cyclesDone() + self.p['cycles']
        self.say('resume: run %s goes on in %s from %s (cycle %d of %d)' % (
            self.runId, self.out, os.path.basename(state), self.cyclesDone(), self.target))
        return self.goOnToEnd()

    def summary(self):
        return outputs.summary(self)

    # ------------------------------------------------------------------ saving
    def state(self):
        return dict(self.baseState(), rig=runtime.ref(self.rig), recorder=runtime.ref(self.recorder),
                    jumper=runtime.ref(self.jumper), stepChoice=runtime.ref(self.stepChoice),
                    bedTop=self.bedTop, porosity=self.porosity, nEscaped=self.nEscaped, nCrib=self.nCrib,
                    bedFile=self.bedFile, onFloor=self.onFloor, warnings=self.rangeWarnings, target=self.target,
                    initial=self.initial,
                    gradings=self.gradings, frames=self.frames)

    @classmethod
    def fromState(cls, s, ref):
        exp = cls.__new__(cls)
        exp.setBaseState(s, ref)
        exp.rig, exp.recorder = ref(s['rig']), ref(s['recorder'])
        exp.jumper = ref(s['jumper']) if s.get('jumper') is not None else None   # none before cycle jumping existed
        exp.stepChoice = ref(s['stepChoice']) if s.get('stepChoice') is not None else None   # none before 2026-12
        for k in ('bedTop', 'porosity', 'nEscaped', 'bedFile', 'initial', 'gradings', 'frames'):
            setattr(exp, k, s[k])
        exp.nCrib = s.get('nCrib', 0)   # states saved before crib ballast existed have none
        exp.onFloor = s.get('onFloor', False)
        exp.rangeWarnings = s.get('warnings', [])   # states of before the warnings have none
        exp.target = s.get('target')   # none in states saved before a killed run could resume
        return exp
