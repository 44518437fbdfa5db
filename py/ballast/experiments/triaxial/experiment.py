"""The large-scale cyclic triaxial test as an experiment on the base (docs/triaxial.md): a cylindrical specimen built
in a mould (:mod:`.specimen`), the mould taken off under a flexible membrane at the confining pressure p'
(:mod:`.membrane`), isotropic consolidation to p' (the top platen pressed at p' over the specimen's cross-section),
then the deviator cycled between qMin and qMax at f: the axial load (p' + q(t)) A on the top platen, A the specimen's
cross-section as the membrane encloses it (the area correction), with the crushing and abrasion engines of the other
experiments and all their options.

    from ballast.experiments.triaxial import TriaxialTest
    test = TriaxialTest(cycles=3)
    test.run()        # prepare() and load(); writes cycles.csv, samples.csv, grading.csv, summary.json, strains.png
    test.load(10)     # ten cycles more
"""
import os

import numpy as np
from yade import O, Vector3, plot

from ... import runtime
from ...params import requireWritableDir
from ...settlementlaws import bedChanged
from .. import breakage, chain, grains, preparation, quasistatic, scene
from ..base import Experiment
from ..cyclic import Cyclic, RecordedCycles, appendSample
from ..parameters import CYCLE_JUMP
from . import monotonic, outputs, specimen
from .membrane import Membrane
from .parameters import OWNER, TriaxialParameters
from .recorder import Recorder
from .strains import axialStrain, volumetricStrain

PRESS, SAMPLER, FRAMES = 'triaxialPress', 'triaxialSampler', 'triaxialFrames'
CONSOLIDATED = (0.02, 1e-5, 1e-5)   # ([s], [-], [-]): at rest when over that time the platen moved less than this
                                    # fraction of the height and the volume changed by less than this fraction
REST = 0.02   # [-] YADE's unbalanced force at rest (the membrane's load, moved from grain to grain every membranePeriod
              # steps, keeps a 1 200-grain specimen near 0.015)
SEAT_TIME = 0.1   # [s] the longest seating: a specimen of spheres creeps under q_min (as a bed under a sleeper does,
                  # docs/box.md), and the cycles' first loading takes up what creep is left
RAMP = 0.02   # [s] the cell pressure and the axial load rise to p' over this time (a cell is filled, not struck)


@runtime.persistent('TriaxialTest')
class TriaxialTest(RecordedCycles, Cyclic, Experiment):
    """A crushable ballast specimen in a triaxial cell under a cyclic deviator. Keyword arguments: any parameter of
    :data:`ballast.experiments.triaxial.parameters.PARAMS`, or parameters=check(...)."""

    NAME = 'triaxial'
    QUASI_STATIC_FINDING = ('its first cycle runs at 4 times the paper\'s step before it has measured anything: over '
                            '5 seeds (p\' 60 kPa, q 45-230 kPa, 5 Hz) cycle 1 strained 15 % less axially, dilated 32 '
                            '% less and was 9 % stiffer than at the paper\'s step; from cycle 2 the axial strain, by '
                            'cycle 10 the volumetric, lay within the seed scatter')
    Parameters = TriaxialParameters
    REOPEN_PARAMS = ('results', 'runId', 'progress', 'vtk', 'cycles', 'saveEvery', 'specimenDir', 'continueFrom',
                     'failureStrain') + tuple(CYCLE_JUMP)

    def __init__(self, parameters=None, **params):
        self.rig = self.membrane = self.recorder = None
        self.porosity = self.specimenFile = None
        self.consolidated = None   # the specimen after consolidation: height, volume, porosity
        self.tConsolidate = None   # [s] when the pressure began to rise
        self.tSeat = None          # [s] when the deviator began to rise to qMin
        self.initial, self.gradings, self.frames = None, [], []
        self.target = None
        self.cycling = False
        self.compression = None    # the monotonic compression under way: t0, H0, V0, rows (monotonic.COLUMNS)
        self.platenForce = None    # the axial load set on the top platen at the last update [N] (kept with the state)
        self.failed = None         # the cycle in which the axial strain passed failureStrain: cycling stopped there
        Experiment.__init__(self, parameters, **params)

    def pieces(self):
        return Experiment.pieces(self) + [self.rig, self.membrane, self.recorder, self.jumper, self.stepChoice]

    def checkOutputs(self):
        Experiment.checkOutputs(self)
        requireWritableDir(OWNER, 'specimenDir', specimen.folder(self.p))

    # ------------------------------------------------------------------ the experiment
    def prepare(self):
        """The specimen in its mould under the top platen, the membrane on and the mould off, consolidated to p', seated
        under qMin."""
        self.openRunDirectory()
        self.rig, self.porosity, self.specimenFile = specimen.prepare(self)
        self.adopt()
        self.consolidate()
        self.seat()
        return self

    def consolidate(self):
        """The membrane at p', the mould taken off, the top platen pressed at p' A until it rests (within
        consolidationTime)."""
        p, rig = self.p, self.rig
        self.membrane = Membrane(rig.base, rig.top, 0.0, p.cell(), p.depth())
        self.adopt()
        t0 = self.tConsolidate = O.time
        self.press()
        rig.removeMould()
        O.engines = O.engines + [runtime.callback(self, 'press', iterPeriod=p['membranePeriod'], label=PRESS)]
        span, move, change = CONSOLIDATED
        platen = preparation.still(rig.top, span, move * self.membrane.height(), after=t0 + RAMP + span, unbalanced=REST)
        volumes = []

        def done():
            volumes.append((O.time, self.membrane.volume))
            old = [v for t, v in volumes if t <= O.time - span]
            return platen() and bool(old) and abs(volumes[-1][1] - old[-1]) < change * old[-1]
        self.runUntil(done, tEnd=t0 + p['consolidationTime'], phase='consolidate', checkEvery=100,
                      extra=lambda: 'height %.4f m, volume %.4g m^3  %s' % (self.membrane.height(), self.membrane.volume,
                                                                         grains.restInfo()))
        H, V = self.membrane.height(), self.membrane.volume
        solid = float(np.sum(grains.volumes()))
        self.consolidated = {'height': H, 'volume': V, 'porosity': 1 - solid / V, 'time': O.time - t0}
        self.say('consolidated at %g kPa in %.3g s: height %.4f m, diameter %.4f m, porosity %.3f (%d grains)' % (
            p['confining'] / 1e3, O.time - t0, H, 2 * np.sqrt(V / (np.pi * H)), self.consolidated['porosity'],
            len(grains.bodies())))

    def seat(self):
        """The deviator raised from 0 to qMin over RAMP, held until the platen rests (at most SEAT_TIME): the cycles start
        from the specimen under qMin, as a laboratory cycle does."""
        p = self.p
        t0 = self.tSeat = O.time
        span, move, _ = CONSOLIDATED
        self.runUntil(preparation.still(self.rig.top, span, move * self.membrane.height(), after=t0 + RAMP + span,
                                        unbalanced=REST), tEnd=t0 + RAMP + SEAT_TIME, phase='seat', checkEvery=100)
        self.say('seated at q = %g kPa in %.3g s: height %.4f m' % (p.seatDeviator() / 1e3, O.time - t0,
                                                                    self.membrane.height()))

    def deviator(self):
        """The deviator applied now [Pa]: 0 while consolidating, rising to qMin while seating, then the sine."""
        if self.cycling:
            return self.p.deviator(O.time - self.recorder.t0)
        if self.tSeat is not None:
            return self.p.seatDeviator() * min(1.0, (O.time - self.tSeat) / RAMP)
        return 0.0

    def press(self):
        """Every membranePeriod steps: the membrane's load for the grains as they are, and the axial load
        (p' + q) A on the top platen, A = the volume the membrane encloses over the platens' distance, less the platen's
        weight (the load the specimen carries is (p' + q) A, as a load cell under the ram would read it)."""
        m = self.membrane
        if self.cycling and self.failing():
            return   # the loads held as they were until cycling stops (runUntil checks every 50 steps)
        m.pressure = self.p['confining'] * min(1.0, (O.time - self.tConsolidate) / RAMP)
        m.update()
        if self.compression is not None:   # the platen moves at its speed: no load on it
            O.forces.setPermF(self.rig.top, Vector3(0, 0, 0))
            return
        area = m.volume / m.height()
        weight = O.bodies[self.rig.top].state.mass * -scene.GRAVITY[2]
        self.platenForce = weight - (m.pressure + self.deviator()) * area
        O.forces.setPermF(self.rig.top, Vector3(0, 0, self.platenForce))

    def failing(self):
        """True once the specimen has failed (failureStrain), checked at every update as well as at every sample: a
        specimen collapsing (a crushing cascade under a high deviator) can pass its whole height between two samples,
        and the membrane has no shape once the platen is through. The failure's row of samples.csv is taken then."""
        if self.failed is None and axialStrain(self.recorder.H0, self.membrane.height()) >= self.p['failureStrain']:
            self.sample()
        return self.failed is not None

    def reopened(self):
        """A scene just loaded: the membrane's and the platen's loads set again as they were when it was saved (YADE
        saves no permanent force; without them the specimen stood unconfined and unloaded until the next update, and
        the cycle after a reopened state strained about twice as much)."""
        if self.membrane is None or not self.membrane.loaded or self.rig is None or self.rig.top is None:
            return
        if self.platenForce is None:   # a state of before the loads were kept: both worked out again now
            self.press()
            return
        self.membrane.restore()
        O.forces.setPermF(self.rig.top, Vector3(0, 0, self.platenForce))

    def startCycling(self):
        """The deviator's cycles from now on, the engines, the recorder, the time-step options, the first state."""
        p = self.p
        t0 = O.time
        self.recorder = Recorder(self.rig.top, self.membrane.height(), self.membrane.volume, t0, p.period())
        self.adopt()
        self.cycling = True
        self.addEngines(t0)
        O.engines = O.engines + [runtime.callback(self, 'sample', virtPeriod=p.period() / p['samples'], virtLast=t0,
                                                  initRun=True, label=SAMPLER)]
        self.startCycles(t0, p.period())
        plot.reset()
        plot.plots = {'axialStrain': ('q',)}   # YADE's live plot: the deviator against the axial strain
        self.startTimeStep(self.rig.top, p.period())
        x, r, m = grains.arrays()
        self.initial = {'massInitial': float(np.sum(m)), 'nGrainsInitial': len(r), 'diameters': grains.sieve()[0].tolist(),
                        'masses': m.tolist()}
        self.gradings = [breakage.grading(self, 0)]
        self.startFrames()
        self.save(os.path.join(self.out, 'state-start.yade.gz'))

    def startFrames(self):
        """With vtk: a VTK frame now and every vtk load cycles (a callback at simulated times; a run reopened with vtk
        gets it then)."""
        if self.p['vtk'] > 0 and chain.engine(FRAMES) is None:
            self.frame()
            O.engines = O.engines + [runtime.callback(self, 'frame', virtPeriod=self.p['vtk'] * self.recorder.period,
                                                      virtLast=O.time, label=FRAMES)]

    def frame(self):
        """A frame of triaxial.pvd (outputs.writeFrame), once at a time."""
        if self.membrane.height() <= 0:
            return   # a specimen collapsed through its height (failing): no membrane to draw
        if not self.frames or self.frames[-1][0] < O.time - self.recorder.t0:
            outputs.writeFrame(self)

    def sample(self):
        """The recorder's sample; at a cycle's end its row, the grading after the cycles of the 1-2-5 series."""
        k = self.recorder.sample(self.p, self.membrane, self.deviator(), self.ownStep())
        row = self.recorder.samples[-1]
        appendSample(self, row)
        if self.failed is None and row[5] >= self.p['failureStrain']:
            self.failed = int(row[1]) + 1   # samples.csv's cycle: the cycles closed by then
            self.say('the specimen failed: axial strain %.2f %% in cycle %d passed failureStrain (%g %%); cycling '
                     'stops' % (100 * row[5], self.failed, 100 * self.p['failureStrain']))
        plot.addData(**dict(zip(('t', 'cycle', 'q', 'qGrains', 'p', 'axialStrain', 'volumetricStrain'), row[:7])))
        if k:
            outputs.writeCycles(self)
            if breakage.gradedCycle(k):
                self.grade(k)
            c = dict(zip(Recorder.CYCLE_COLUMNS, self.recorder.cycles[-1]))
            self.cycleDone(k, c['settlement'], bool(bedChanged(c['crushes'], c['abrasions'])), c['inertialMax'],
                           c['responseRatio'])

    def cycleFrame(self):
        return outputs.cycleTable(self)

    def load(self, cycles=None):
        """Run `cycles` more load cycles (default the parameter's), then write every output and save the state; with
        monotonic, the monotonic compression instead. Returns the summary."""
        return self.compress() if self.p['monotonic'] else RecordedCycles.load(self, cycles)

    def cyclingStarted(self):
        return self.recorder is not None

    def prepared(self):
        return self.rig is not None

    def stopReason(self):
        return None if self.failed is None else 'the specimen failed in cycle %d' % self.failed

    def loadText(self):
        p = self.p
        return 'q %g-%g kPa (%s) of %.3g s under p\' = %g kPa' % (
            p.seatDeviator() / 1e3, p.peakDeviator() / 1e3, p['loadFile'] or 'sine', p.period(), p['confining'] / 1e3)

    def stateText(self):
        last = self.recorder.samples[-1] if self.recorder.samples else (0,) * 10
        return 'axial strain %.3f %%, volumetric %.3f %%, %d crushed' % (100 * last[5], 100 * last[6], last[9])

    def doneText(self, s):
        return '%d cycles, axial strain %.3f %%, volumetric %.3f %%, %d crushed, %d abraded' % (
            self.cyclesDone(), 100 * s['axialStrain'], 100 * s['volumetricStrain'], s['nCrushed'], s['nAbraded'])

    def writeOutputs(self):
        return outputs.write(self)

    def summary(self):
        return outputs.monotonicSummary(self) if self.compression is not None else outputs.summary(self)

    # ------------------------------------------------------------------ the monotonic compression
    def compress(self):
        """The drained monotonic compression (monotonic.py): the consolidated specimen's top platen driven down at
        strainRate times its height (its degrees of freedom blocked: displacement control), the membrane holding p',
        the crushing and abrasion engines on, until the axial strain reaches maxAxialStrain; monotonic.csv,
        monotonic.png, grading.csv and summary.json. Returns the summary."""
        p = self.p
        if self.rig is None:
            self.prepare()
        m, top = self.membrane, O.bodies[self.rig.top]
        t0 = O.time
        duration = p['maxAxialStrain'] / p['strainRate']
        self.compression = {'t0': t0, 'H0': m.height(), 'V0': m.volume, 'rows': []}
        top.state.blockedDOFs = 'xyzXYZ'
        top.state.vel = Vector3(0, 0, -p['strainRate'] * self.compression['H0'])
        top.state.angVel = Vector3(0, 0, 0)
        self.addEngines(t0)
        x, r, mass = grains.arrays()
        self.initial = {'massInitial': float(np.sum(mass)), 'nGrainsInitial': len(r),
                        'diameters': grains.sieve()[0].tolist(), 'masses': mass.tolist()}
        self.gradings = [breakage.grading(self, 0)]
        self.startTimeStep(None)
        O.engines = O.engines + [runtime.callback(self, 'sampleCompression', virtPeriod=duration / monotonic.ROWS,
                                                  virtLast=t0, initRun=True, label=SAMPLER)]
        self.say('monotonic compression at %g /s (%.4g m/s) under p\' = %g kPa to %g %% axial strain, dt = %.3g s' % (
            p['strainRate'], p['strainRate'] * self.compression['H0'], p['confining'] / 1e3,
            100 * p['maxAxialStrain'], O.dt))
        rows = self.compression['rows']
        self.runUntil(lambda: self.axialStrainNow() >= p['maxAxialStrain'], tEnd=t0 + 1.05 * duration,
                      phase='compress', checkEvery=100, simSpan=duration, simStart=t0,
                      extra=lambda: 'axial strain %.2f %%, q %.1f kPa, volumetric %.3f %%' % (
                          100 * self.axialStrainNow(), rows[-1][3] / 1e3 if rows else 0.0,
                          100 * rows[-1][2] if rows else 0.0))
        self.grade(1)
        s = self.finishRun(lambda: outputs.writeMonotonic(self))
        self.say('done: peak q %.1f kPa at %.2f %% axial strain (friction angle %.1f deg), volumetric %.3f %% at the '
                 'end; results in %s' % (s['qPeak'] / 1e3, 100 * s['axialStrainAtPeak'], s['frictionAnglePeak'],
                                          100 * s['volumetricStrainEnd'], self.out))
        return s

    def axialStrainNow(self):
        c = self.compression
        return axialStrain(c['H0'], self.membrane.height())

    def sampleCompression(self):
        """A row of monotonic.csv (monotonic.COLUMNS): the deviator the grains carry on the top platen over the
        area the membrane encloses, less p'; the strains from the boundary; the inertial number of the compression."""
        c, m, p = self.compression, self.membrane, self.p
        H, V = m.height(), m.volume
        area = V / H
        force = O.forces.f(self.rig.top)[2] - O.forces.permF(self.rig.top)[2]   # the grains' push, upward
        q = force / area - m.pressure
        mean = m.pressure + q / 3
        crushed, abraded, _ = breakage.counts()
        inertial = quasistatic.inertialNumber(p, O.bodies[self.rig.top].state.vel[2], H, force, area,
                                              (p['confining'] + p['qMax']) * area, self.ownStep())
        c['rows'].append([O.time - c['t0'], axialStrain(c['H0'], H), volumetricStrain(c['V0'], V), q, mean,
                          q / mean if mean else float('nan'), crushed, abraded, inertial])

    # ------------------------------------------------------------------ saving
    def state(self):
        return dict(self.baseState(), rig=runtime.ref(self.rig), membrane=runtime.ref(self.membrane),
                    recorder=runtime.ref(self.recorder), jumper=runtime.ref(self.jumper),
                    stepChoice=runtime.ref(self.stepChoice), porosity=self.porosity, specimenFile=self.specimenFile,
                    consolidated=self.consolidated, tConsolidate=self.tConsolidate, tSeat=self.tSeat, initial=self.initial, gradings=self.gradings, frames=self.frames, target=self.target,
                    cycling=self.cycling, compression=self.compression, platenForce=self.platenForce, failed=self.failed)

    @classmethod
    def fromState(cls, s, ref):
        exp = cls.__new__(cls)
        exp.setBaseState(s, ref)
        exp.rig, exp.membrane, exp.recorder = ref(s['rig']), ref(s['membrane']), ref(s['recorder'])
        exp.jumper = ref(s['jumper']) if s.get('jumper') is not None else None
        exp.stepChoice = ref(s['stepChoice']) if s.get('stepChoice') is not None else None
        for k in ('porosity', 'specimenFile', 'consolidated', 'tConsolidate', 'tSeat', 'initial', 'gradings', 'frames',
                  'target', 'cycling'):
            setattr(exp, k, s[k])
        exp.compression = s.get('compression')   # states of before the monotonic compression have none
        exp.platenForce = s.get('platenForce')   # states of before it was kept: the next update sets it
        exp.failed = s.get('failed')
        return exp
