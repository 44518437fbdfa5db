"""The one cyclic piece every cyclic experiment shares (the oedometer's cycles of eq. 8, the box test, a
later triaxial cell): the cycles.csv schema, the same column names meaning the same quantities in every
experiment, the jump summary, and the checkpoints every saveEvery cycles. Cycles are numbered with the
jumped ones (cycle jumping, :mod:`.cyclejump`). The base drives it (:class:`ballast.experiments.base.Experiment`:
``closeCycle``, ``cycleCheckpoint``); an experiment gives each closed cycle's row.

cycles.csv, one row per simulated cycle (pandas reads it), the shared columns first:

============== ====== ===================================================================================
cycle          -      the cycle's number, the jumped cycles counted
t              s      loading time at the cycle's end (since cycling began, jumped cycles not simulated)
settlement     m      permanent deformation: the loading body's displacement at the cycle's end (the lower
                      load), from the start of cycling
resilient      m      resilient deformation: the largest displacement within the cycle less that at its end
crushes        -      grains crushed in the cycle
abrasions      -      abrasions in the cycle
nCrushed       -      grains crushed since cycling began
nAbraded       -      abrasions since cycling began
maxDamage      -      the largest fatigue damage D of a grain at the cycle's end (0 without fatigue)
maxStressRatio -      the largest sigma/f_t of a grain that can crush, over the crushing checks of the cycle
nGrains        -      grains (and fragments) at the cycle's end
cpuSeconds     s      CPU time of the cycle (NaN for the first cycle of a process that went on from a state)
dt             s      the time step at the cycle's end
stepsPerCycle  -      the time steps the cycle took (NaN for a cycle a state saved before 2026-12 went on in)
inertialMax    -      the largest inertial number of the bed over the cycle (:mod:`.quasistatic`: NaN where the
                      grains carried under 1 % of the peak load)
inertialMedian -      its median over the cycle
responseRatio  -      the load's period over the bed's slowest response time (:mod:`.quasistatic`)
jumped         -      with cycle jumping: the cycles jumped before this row
settlementJumped m    with cycle jumping: the settlement extrapolated over those cycles (settlement laws)
quasiStaticMet -      with quasiStatic: 1 if the cycle kept the option's bounds, 0 if it broke one
============== ====== ===================================================================================

then each experiment's own (the oedometer: Bg; the box: settlementPeak, work, tilt)."""
import math
import os
import re
import time

import numpy as np
import pandas as pd
from yade import O

from .. import runtime
from ..params import validate
from ..runfiles import writeAtomic
from ..settlementlaws import cyclesChanged as changed, settlementJumped
from . import breakage, chain, grains, timestep
from .cyclejump import CycleJumper

COLUMNS = ('cycle', 't', 'settlement', 'resilient', 'crushes', 'abrasions', 'nCrushed', 'nAbraded', 'maxDamage',
           'maxStressRatio', 'nGrains', 'cpuSeconds', 'dt', 'stepsPerCycle', 'inertialMax', 'inertialMedian',
           'responseRatio')
JUMP_COLUMNS = ('jumped', 'settlementJumped')
CHECKPOINT = 'state-cycle%07d.yade.gz'   # the state saved after a cycle (saveEvery), named by the cycles done
WITHIN_CYCLE = 'state-iter%09d.yade.gz'  # a state saved within cycles (saveEvery a fraction), named by the step
SAVER = 'cycleSaver'                     # the label of the checkpoint callback, first in the chain
JUMP_STATE = 'state-jump%04d-%s.yade.gz'   # the states around jump k: 'before' and 'after' it
JUMP_STATE_NAME = re.compile(r'state-jump(\d+)-(?:before|after)\.yade\.gz')   # the same names, read back
JUMPER = 'cycleJumper'   # the label of the callback that makes a planned jump


def table(rows, own=(), jumper=None, choice=None):
    """cycles.csv as a DataFrame: rows (dicts with COLUMNS and the experiment's `own` columns) in the shared order,
    with cycle jumping (a jumper) the cycles jumped before each row and the settlement extrapolated over them, with
    the quasi-static option (its StepChoice) whether each cycle kept its bounds (quasiStaticMet, 1 or 0)."""
    frame = pd.DataFrame(list(rows), columns=list(COLUMNS) + list(own))
    at = len(COLUMNS)
    if jumper is not None:
        frame.insert(at, 'jumped', frame.cycle.astype(int) - np.arange(1, len(frame) + 1))
        frame.insert(at + 1, 'settlementJumped', settlementJumped(frame.cycle, frame.settlement, changed(frame)))
        at += 2
    if choice is not None:   # met[k]: the k-th simulated cycle; the last row's may not be read yet (NaN)
        met = list(choice.met[:len(frame)])
        frame.insert(at, 'quasiStaticMet', met + [math.nan] * (len(frame) - len(met)))
    return frame


def write(path, frame):
    """cycles.csv, atomically (a killed run keeps the cycles it closed)."""
    writeAtomic(path, frame.to_csv(index=False, float_format='%.9g'))


def jumpSummary(frame, jumper):
    """summary.json's word on cycle jumping: the cycles reached, simulated and jumped, the jumps, the extrapolated
    settlement ({} without jumping)."""
    if jumper is None:
        return {}
    n = len(frame)
    s, sj = (float(frame.settlement.iloc[-1]), float(frame.settlementJumped.iloc[-1])) if n else (0.0, 0.0)
    return {'cycles': int(frame.cycle.iloc[-1]) if n else 0, 'cyclesSimulated': n, 'cyclesJumped': int(jumper.jumped),
            'jumps': len(jumper.jumps), 'settlementJumped': sj, 'settlementTotal': s + sj}


def wholeCycles(every):
    """Whether saveEvery [cycles] is a whole number of cycles (checkpoints after cycles close)."""
    return float(every).is_integer()


class CycleRecorder:
    """What a cyclic experiment's recorder shares (the box's, the triaxial test's): rows sampled at simulated times
    (column 0 the time since cycling began, column 1 the cycle count), the current cycle's kept in `samples`, and a
    row of cycles.csv closed by the recorder's own closeCycle(end, p, ownStep) when a sample falls in the next cycle.
    Attributes: t0, period, samples, cycles, start (index of the current cycle's first row), cpu, iter0 (CPU and
    step at its start), jumped (cycles advanced by cycle jumping)."""

    def restored(self):
        """After a restore: the open cycle's CPU counted from here (a process's clock does not carry over; it was
        left out, NaN, in the first cycle of every slice and reopened run)."""
        if self.start is not None:
            self.cpu = time.process_time()

    def cycle(self):
        """Whole cycles since cycling began (a sample at a cycle's end belongs to the cycle it ends)."""
        return int(math.floor((O.time - self.t0) / self.period + 1e-6)) + self.jumped

    def jump(self, cycles):
        """`cycles` more cycles counted as done without being simulated: the current cycle's rows move with them."""
        self.jumped += cycles
        for row in self.samples[self.start:]:
            row[1] += cycles

    def keep(self, row, p, ownStep=None):
        """The sample `row` kept; returns the cycle it closed, or 0."""
        self.samples.append(row)
        if self.start is None:
            self.start, self.cpu, self.iter0 = len(self.samples) - 1, time.process_time(), O.iter
        elif row[1] > self.samples[self.start][1]:   # a cycle ended at this sample: it opens the next one
            self.closeCycle(len(self.samples) - 1, p, ownStep)
            self.samples, self.start = self.samples[-1:], 0
            return int(row[1])
        return 0


class Cyclic:
    """What the base gives a cyclic experiment (a mixin of :class:`ballast.experiments.base.Experiment`): the
    checkpoints every saveEvery cycles and cycle jumping. The experiment calls :meth:`startCycles` when its cycles
    start, :meth:`cycleDone` at each simulated cycle's end, numbers its cycles with the jumped ones and, if it
    counts cycles itself, moves its count on in :meth:`jumped`."""

    SAVER = SAVER   # the checkpoint callback's label (an experiment's older states may name it otherwise)
    jumper = None   # the CycleJumper piece of a run with cycle jumping (startJumping)
    QUASI_STATIC_FINDING = None   # what the quasi-static option's validation on the experiment found, said by warnings

    def warnings(self):
        """With quasiStatic: what its validation on this experiment found (QUASI_STATIC_FINDING; docs/performance.md,
        "Is a cycle quasi-static?"), said when a run with it starts and kept in summary.json."""
        if self.QUASI_STATIC_FINDING is None or not self.p['quasiStatic'] > 0:
            return []
        return ['quasiStatic %g: %s' % (self.p['quasiStatic'], self.QUASI_STATIC_FINDING)]

    def startCycles(self, t0, period):
        """At the start of cycling (loading time t0 [s], cycles of `period` [s]): the checkpoints, then cycle
        jumping (with jump)."""
        self.startSaver(t0, period)
        self.startJumping()

    def startSaver(self, t0, period):
        """With saveEvery: the checkpoint callback, first in the chain so that a state saved before the step begins
        resumes exactly. Every whole number of cycles it wakes after a cycle closed (cycleDone); a fraction of a
        cycle (the long cycle of the oedometer: 0.25 saves four states a cycle) is every saveEvery periods of
        loading time from t0."""
        every = self.p['saveEvery']
        if every > 0 and wholeCycles(every):
            self.addSaver()
        elif every > 0:
            O.engines = [runtime.callback(self, 'checkpoint', virtPeriod=every * period, virtLast=t0,
                                          label=self.SAVER)] + list(O.engines)

    def addSaver(self):
        O.engines = [runtime.callback(self, 'checkpoint', iterPeriod=1, dead=True, label=self.SAVER)] + list(O.engines)

    def cycleDone(self, cycle, settlement, changed, inertialMax=math.nan, responseRatio=math.nan):
        """The experiment's call at the end of each simulated cycle `cycle` (numbered with the jumped ones), with its
        permanent settlement [m], whether a grain crushed or abraded in it and its quasi-static measures: the
        quasi-static option's next step, the checkpoint after every saveEvery cycles and, with jumping, the jumper's
        reading of the cycle; the last two act at the start of the next step."""
        if self.stepChoice is not None:
            self.chooseStep(cycle, inertialMax, responseRatio)
        every = self.p['saveEvery']
        if every and wholeCycles(every) and cycle % every == 0:
            if chain.engine(self.SAVER) is None:   # reopened with saveEvery from a run that had none
                self.addSaver()
            chain.engine(self.SAVER).dead = False
        if self.jumper is not None:
            self.cycleClosed(cycle, settlement, changed)

    def chooseStep(self, cycle, inertialMax, responseRatio):
        """quasiStatic: the next cycle's density step from this one's measures (quasistatic.StepChoice); a cycle that
        broke a bound says so, and which step the next one runs at (the paper's after the inertial bound)."""
        choice, before = self.stepChoice, self.stepChoice.step
        step = choice.cycleClosed(inertialMax, responseRatio)
        if not choice.met[-1]:
            ratio = ('%.3g' % responseRatio if math.isfinite(responseRatio)
                     else 'not measured: no resilient deformation this cycle')
            self.say('cycle %d broke the quasi-static bounds (largest inertial number %.3g, bound %g; response ratio '
                     '%s, at least %g): the next cycle at %s %.3g s' % (
                         cycle, inertialMax, choice.bound, ratio, choice.ratioMin,
                         'the paper\'s step' if step == choice.paper else 'the shorter step', step))
        if step != before:
            timestep.changeDensityStep(step, step / self.p['dtSafety'], choice.loaded)

    def checkpoint(self):
        """The saver's call at the start of a step: a state to go on from, exactly where the run was; after a cycle
        closed state-cycle<N>.yade.gz (N the cycles done), within cycles state-iter<step>.yade.gz."""
        if wholeCycles(self.p['saveEvery']):
            chain.engine(self.SAVER).dead = True
            self.save(os.path.join(self.out, CHECKPOINT % self.cyclesDone()))
        else:
            self.save(os.path.join(self.out, WITHIN_CYCLE % O.iter))

    def cyclesDone(self):
        """Cycles done, simulated and jumped (each experiment counts them)."""
        raise NotImplementedError

    def cycleFrame(self):
        """cycles.csv as it stands, a DataFrame (each experiment's outputs make it)."""
        raise NotImplementedError

    def run(self):
        """prepare() and load() (Experiment.run); with continueFrom, the saved run reopened into this run's folder and
        `cycles` more cycles of it (goOn); with resume, first the run killed in this run's folder taken to its end
        (Experiment.resumeKilled). An experiment without those parameters runs as Experiment.run. Returns the
        summary."""
        resumed = self.resumeKilled()
        if resumed is not None:
            return resumed
        if self.p.get('continueFrom'):
            return self.goOn()
        return super().run()

    def goOn(self):
        """The run saved in continueFrom, reopened with this run's folder and reporting, `cycles` more cycles (a
        long run in slices). ParamError naming the first physics parameter that differs from the saved run's, before
        any step."""
        p = self.p
        saved = type(self).reopen(p['continueFrom'], **{k: p[k] for k in self.REOPEN_PARAMS})
        self.requireSamePhysics(saved, 'continueFrom')
        return saved.load(p['cycles'])

    # ------------------------------------------------------------------ cycle jumping (experiments.cyclejump)
    def startJumping(self):
        """With jump: the jumper (self.jumper, a piece) and, first in the chain, the callback that makes a jump at
        the start of the step after the cycle that planned it (where a saved state resumes exactly)."""
        self.jumper = CycleJumper.of(self.p)
        if self.jumper is not None:
            O.engines = [runtime.callback(self, 'jumpNow', iterPeriod=1, dead=True, label=JUMPER)] + list(O.engines)
            self.adopt()

    def syncJumping(self):
        """At the start of a load(): jumping as the parameters now say (a run reopened may start, tune or stop it;
        the cycles jumped stay counted). Returns True if jumping starts now."""
        if self.jumper is None:
            if self.p['jump']:
                self.startJumping()
                if self.cyclesDone():   # the cycles simulated before: the settlement law's first rows
                    frame = self.cycleFrame()
                    self.jumper.seed(frame.cycle, frame.settlement, changed(frame))
                return True
            return False
        self.jumper.tune(self.p)
        return False

    def cycleClosed(self, cycle, settlement, changed):
        """The experiment's call at the end of each simulated cycle (numbered with the jumped ones), with its
        permanent settlement [m] and whether a grain crushed or abraded in it: the jumper reads the grains' damage
        and plans a jump, made at the next step."""
        ids = grains.kind().ids().tolist()
        if self.jumper.cycleEnded(chain.engine('crush'), ids, cycle, settlement, changed):
            chain.engine(JUMPER).dead = False

    def jumpNow(self):
        """The state before, the jump, the state after (state-jump<K>-before/after.yade.gz), jumps.csv."""
        chain.engine(JUMPER).dead = True
        k = len(self.jumper.jumps) + 1
        before, after = JUMP_STATE % (k, 'before'), JUMP_STATE % (k, 'after')
        self.save(os.path.join(self.out, before))
        e = self.jumper.apply(chain.engine('crush'), before, after)
        self.jumped(e['cycles'])
        self.save(os.path.join(self.out, after))
        if self.p['jumpStates'] == 'last' and k > 1:
            self.forgetJumpStates(self.jumper.jumps[-2])
        self.jumper.writeLog(os.path.join(self.out, 'jumps.csv'))
        self.say('jump %d: cycles %d -> %d (bound: %s), largest damage rate %.3g a cycle, settlement %+.4f mm '
                 'extrapolated' % (k, e['cycle'], e['to'], e['limit'], e['maxRate'], 1e3 * e['settlementJumped']))

    def cutJumps(self):
        """A killed run resumed: jumps.csv back to the jumps of the state it goes on from, and the states the killed
        process saved around later jumps removed (those jumps are taken again under the same numbers, or not)."""
        if self.jumper is None:
            return
        self.jumper.writeLog(os.path.join(self.out, 'jumps.csv'))
        for name in os.listdir(self.out):
            m = JUMP_STATE_NAME.fullmatch(name)
            if m and int(m.group(1)) > len(self.jumper.jumps):
                os.remove(os.path.join(self.out, name))

    def forgetJumpStates(self, jump):
        """Remove the states this run saved around an earlier jump (jumpStates 'last') and their names from its log
        row; those of the run it continues (another folder) stay."""
        for key in ('stateBefore', 'stateAfter'):
            path = os.path.join(self.out, jump[key])
            if jump[key] and path in self.saved:
                if os.path.exists(path):
                    os.remove(path)
                self.saved.remove(path)
                jump[key] = ''

    def jumped(self, cycles):
        """After a jump of `cycles` (subclasses whose own records count cycles move them on)."""


class RecordedCycles:
    """For a cyclic experiment whose recorder counts its cycles (a row each in recorder.cycles, recorder.jumped
    jumped over) and that grades its grains after chosen cycles (self.gradings): the box and the triaxial test. It
    owns their load() (below: the lifecycle here, their own in the hooks). Put before :class:`Cyclic` among the
    bases."""

    def jumped(self, cycles):
        self.recorder.jump(cycles)

    def grade(self, k):
        """The grading after cycle k, once."""
        if all(g['cycle'] != k for g in self.gradings):
            self.gradings.append(breakage.grading(self, k))

    def cyclesDone(self):
        """Cycles done: those simulated (a row each) and those jumped over."""
        return len(self.recorder.cycles) + self.recorder.jumped if self.recorder is not None else 0

    # The lifecycle of load(), the same for both; each says through these hooks what is its own.
    def cyclingStarted(self):
        """Whether the load cycles have begun (else load() prepares the sample if need be and starts them)."""
        raise NotImplementedError

    def prepared(self):
        """Whether the sample is prepared (built, seated, under its load)."""
        raise NotImplementedError

    def stopReason(self):
        """Why the run stops before its target (the box: the sleeper on the floor; the triaxial: the specimen
        failed), or None."""
        raise NotImplementedError

    def loadText(self):
        """The load as load() says it: '<the cycle's load>, dt = ...' follows."""
        raise NotImplementedError

    def stateText(self):
        """The state the progress line gives after 'cycle k of n, '."""
        raise NotImplementedError

    def doneText(self, s):
        """The end as load() says it, from the summary s: 'done: <this>; results in <folder>'."""
        raise NotImplementedError

    def atStop(self):
        """At the stop, before the outputs (the box closes the cycle its sleeper cut short on the floor)."""

    def writeOutputs(self):
        raise NotImplementedError

    def load(self, cycles=None):
        """Run `cycles` more load cycles (default the parameter's), then write every output and save the state.
        Returns the summary."""
        p = self.p
        n = p['cycles'] if cycles is None else validate(p.OWNER + '.load', {'cycles': p.PARAMS['cycles']}, 'cycles',
                                                        cycles)
        if not self.cyclingStarted():
            if not self.prepared():
                self.prepare()
            self.startCycling()
        if self.out is None:   # a reopened run writes into a folder of its own
            self.dir.create()
            self.markRunning(continues=self.dir.previous, continuesState=self.dir.source)
            self.say('run %s goes on from %s -> %s' % (self.runId, self.dir.source or self.dir.previous, self.out))
        if self.stopReason() is not None:
            self.say('load: no cycles: %s' % self.stopReason())
            return self.finishRun(self.writeOutputs)
        self.syncJumping()
        self.startFrames()
        self.target = self.cyclesDone() + n
        return self.goOnToEnd()

    def goOnToEnd(self):
        """The cycles of the load() under way up to its target (saved with the state: a killed run resumed goes on to
        it), then every output written and the state saved. Returns the summary."""
        p, rec, target = self.p, self.recorder, self.target
        tEnd = rec.t0 + (target - rec.jumped) * rec.period
        if self.jumper is not None:
            self.jumper.target = target
        self.say('load: %d cycle(s) of %s, dt = %.3g s (%.3g steps a cycle)' % (
            target - self.cyclesDone(), self.loadText(), O.dt, rec.period / O.dt))
        if self.cyclesDone() < target:   # a run killed after its last cycle: its outputs only
            self.runUntil(lambda: self.cyclesDone() >= target or self.stopReason() is not None,
                          tEnd=tEnd + 2 * rec.period / p['samples'], phase='load', checkEvery=50,
                          simSpan=tEnd - O.time, simStart=O.time,
                          extra=lambda: 'cycle %d of %d, %s' % (self.cyclesDone(), target, self.stateText()))
        self.atStop()
        self.grade(self.cyclesDone())
        if p['vtk'] > 0:
            self.frame()   # the last
        s = self.finishRun(self.writeOutputs)
        self.say('done: %s; results in %s' % (self.doneText(s), self.out))
        return s


def appendSample(exp, row):
    """A row of the experiment's samples.csv (its recorder's COLUMNS), appended as it is taken (a run that goes on
    from a state writes its own from there)."""
    path = os.path.join(exp.out, 'samples.csv')
    new = not os.path.exists(path)
    with open(path, 'a') as fh:
        if new:
            fh.write(','.join(exp.recorder.COLUMNS) + '\n')
        fh.write(','.join('%.9g' % v for v in row) + '\n')
