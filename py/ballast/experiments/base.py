"""The base of every experiment: parameters declared once and checked once (a frozen
:class:`ballast.params.Parameters`), a run directory, phases with progress, a lifecycle and saving and
reopening through :mod:`ballast.runtime`.

    exp = SomeExperiment(seed=2)     # a bad value raises ParamError here, before any work
    exp.prepare()                    # the sample
    exp.run() / exp.load()           # the experiment's own loading; writes the run directory
    exp.runUntil(lambda: ..., tEnd)  # or step the scene until a condition, with progress lines
    exp.summary()                    # what summary.json holds
    exp.save(path); SomeExperiment.reopen(path, readOnly=True)

Every file is written atomically (a temporary name in the same folder, synced, then renamed:
:func:`ballast.runfiles.writeAtomic`; states by :meth:`Experiment.save`), so a killed run leaves
whole files or none. An experiment that calls :meth:`Experiment.markRunning` and
:meth:`Experiment.markFinished` keeps ``run.json`` in its folder: ``{"status": "running", ...}`` from
the start, ``"finished"`` once every output is written; ``running`` in a folder whose process is gone
is a killed run.

A subclass gives ``NAME``, ``Parameters`` (its Parameters class), ``REOPEN_PARAMS`` (what a reopened
run may change: where and how it reports, not the physics), ``prepare()``, ``summary()``, and its
state (``state()``, ``fromState()``); its pieces are registered objects of their own. One that declares
``resume`` goes on with a killed run (:meth:`Experiment.resumeKilled`) and gives ``resumed(state)``. A cyclic
experiment is also a :class:`ballast.experiments.cyclic.Cyclic` (checkpoints every saveEvery cycles, cycle
jumping, the cycles.csv schema). The run's folder and the check of a state file: :mod:`.rundir`.
"""
import gzip
import math
import os
import shutil
import socket
import time

from yade import O

from .. import grainkinds, runtime
from ..engines import BallastAbrasionEngine, BallastCrushEngine, PolyhedronCrushEngine
from ..names import runDirName
from ..engineparams import CRUSH
from ..params import ParamError, requireWritableDir
from ..runfiles import runStatus, syncDir
from . import chain, quasistatic, timestep
from .phases import Phases
from .rundir import RunDirectory, StateFileError, checkStateFile, processAlive, resumableState

PARAM_UNITS = 2   # the saved parameters' units: 2 since saveEvery and vtk count load cycles (2026-12)
LOADED_STIFFNESS_MARGIN = 2.0  # [-] densityStep: the loading body's contacts may stiffen this much as grains crush


class Experiment:
    """See the module doc."""

    NAME = 'experiment'
    Parameters = None
    REOPEN_PARAMS = ()

    def __init__(self, parameters=None, **params):
        if parameters is not None and (params or not isinstance(parameters, self.Parameters)):
            raise TypeError('%s: give parameters=%s(...) (checked already) or the parameters by name, not both'
                            % (self.NAME, self.Parameters.__name__))
        self.p = parameters if parameters is not None else self.Parameters.check(params)
        self.phases = Phases(self.p['progress'], self.NAME)
        self.dir = RunDirectory(self.p['results'], self.p['runId'])
        self.saved = []              # state files written so far
        self.wallBefore, self.cpuBefore = 0.0, 0.0  # of the runs this one continues
        self.started, self.cpuStarted = time.time(), time.process_time()
        self.adopt()

    # ------------------------------------------------------------------ the scene
    def pieces(self):
        """The registered objects the experiment consists of (subclasses add theirs)."""
        return [self, self.phases, self.dir]

    def adopt(self):
        """Register the experiment and its pieces in the current scene."""
        for obj in self.pieces():
            if obj is not None:
                runtime.register(obj)

    def newScene(self):
        """O.reset() for a piece that builds a scene; the experiment lives in the new one, with the grain kind of its
        `grain` parameter chosen before any grain exists (the sphere, the default, leaves the scene as before)."""
        O.reset()
        self.adopt()
        grainkinds.use(self.p.get('grain', grainkinds.DEFAULT))

    @property
    def runId(self):
        return self.dir.runId

    @property
    def out(self):
        return self.dir.path

    def checkOutputs(self):
        """Before any work: the results folder can be created and written to."""
        requireWritableDir(self.Parameters.OWNER, 'results', self.p['results'])

    def openRunDirectory(self):
        """At the start of prepare(): the outputs checked, the run's folder made, run.json 'running'."""
        if self.out is None:
            self.checkOutputs()
            self.dir.create()
            self.markRunning()
            self.say('run %s -> %s' % (self.runId, self.out))
            for w in self.warnings():
                self.say('warning: ' + w)

    def warnings(self):
        """What a run should know of its parameters (an option that changes the answer where it was validated), said
        when it starts and kept in summary.json: none here; an experiment adds its own."""
        return []

    def run(self):
        """The whole experiment: prepare(), then load() (each experiment's own); returns the summary."""
        self.prepare()
        return self.load()

    def runUntil(self, condition=None, tEnd=None, phase='run', checkEvery=200, **progress):
        """Step the scene until condition() is true (checked every checkEvery steps in the step loop, so where
        it stops never depends on the machine) or O.time reaches tEnd [s], with progress lines. progress:
        simSpan, simStart, extra, afterChunk (see Phases.run)."""
        if condition is None and tEnd is None:
            raise ParamError('tEnd', '%s.runUntil: give a condition or tEnd [s], else it never ends' % self.NAME)
        if self.jumper is not None:   # the jumps shorten what is simulated: no share of it, no time left
            progress.pop('simSpan', None)
        self.phases.run(phase, condition, tEnd=tEnd, checkEvery=checkEvery, **progress)

    def addEngines(self, t0):
        """BallastCrushEngine and BallastAbrasionEngine after NewtonIntegrator, as the parameters say (crush,
        abrasion and every declaration of the engines the experiment reuses); crushing checked at times
        t0 + k Tc [s]."""
        p = self.p
        extra = []
        if p['crush']:
            # every engine parameter the experiment declares (its PARAMS reuse CRUSH's declarations);
            # the engine scales O.dt with the drop of PWaveTimeStep() after a replacement (eq. 5)
            own = {k: p[k] for k in CRUSH if k in p}
            if p.get('grain') == 'polyhedron':   # YADE's PolyhedraSplitter, woken and booked by the engine
                crush = PolyhedronCrushEngine(mask=0, label='crush', scaledPWaveStep=p.scaledPWaveStep(),
                                              **p.crushPeriod(), **own)
                crush.floor()
            else:
                crush = BallastCrushEngine(mask=0, label='crush', scaledPWaveStep=p.scaledPWaveStep(), **p.crushPeriod(),
                                           **own)
            # checks at loading times k T_c (not at scene times, which include the preparation): where they fall
            # in the load cycle is then set by T_c and f alone (docs/oedometer.md, "Crushing period")
            crush.virtLast = t0
            extra.extend(crush.engines() if isinstance(crush, PolyhedronCrushEngine) else [crush])
        if p['abrasion']:
            extra.append(BallastAbrasionEngine(strength=p['strength'], gamma=p['gamma'], rMin=p['rMin'], mask=0,
                                               iterPeriod=p['abrasionPeriod'], scaledPWaveStep=p.scaledPWaveStep(),
                                               label='abrasion'))
        O.engines = O.engines + extra

    def say(self, msg):
        self.phases.say(msg)

    def seconds(self):
        """(wall, CPU) seconds of this run and those it continues."""
        return (self.wallBefore + time.time() - self.started, self.cpuBefore + time.process_time() - self.cpuStarted)

    # ------------------------------------------------------------------ saving and reopening
    def save(self, path):
        """O.save(path): the scene with the state of the experiment, its pieces and the engines. Written to a
        temporary name in the same folder, synced, then renamed: a state file is whole or absent."""
        self.saved.append(path)
        folder, name = os.path.split(os.path.abspath(path))
        tmp = os.path.join(folder, '.tmp-%d-%s' % (os.getpid(), name))  # the same suffix: YADE compresses by it
        try:
            if path.endswith('.gz'):   # YADE's gzip: 5 x the time of level 1 for a state 5 % smaller
                raw = tmp[:-3]
                try:
                    O.save(raw)
                    with open(raw, 'rb') as src, open(tmp, 'wb') as dst, \
                            gzip.GzipFile(filename='', mode='wb', compresslevel=1, fileobj=dst, mtime=0) as gz:
                        shutil.copyfileobj(src, gz, 1 << 22)
                finally:
                    if os.path.exists(raw):
                        os.remove(raw)
            else:
                O.save(tmp)
            fd = os.open(tmp, os.O_RDONLY)
            try:
                os.fsync(fd)
            finally:
                os.close(fd)
            os.replace(tmp, path)
        finally:
            if os.path.exists(tmp):
                os.remove(tmp)
        syncDir(folder)
        if self.status == 'running' and self.dir.path is not None:
            self.dir.writeStatus(self.status, lastState=os.path.basename(path), iter=O.iter, time=O.time)

    status = None  # 'running' between markRunning and markFinished
    jumper = None  # the CycleJumper piece of a run with cycle jumping (startJumping)

    def markRunning(self, **info):
        """run.json says 'running' (with the process, so that a killed run is told from a live one)."""
        self.status = 'running'
        self.dir.writeStatus('running', experiment=self.NAME, pid=os.getpid(), host=socket.gethostname(), **info)

    def markFinished(self, **info):
        """run.json says 'finished': every output is written."""
        self.status = 'finished'
        self.dir.writeStatus('finished', **info)

    def finishRun(self, write):
        """The end every run has: its state saved (state-end.yade.gz), then write() writes every output and returns
        the summary, then run.json 'finished'. Hours of loading are in the state: if the outputs fail, say how to get
        them back (rebuildHint) and raise."""
        end = os.path.join(self.out, 'state-end.yade.gz')
        self.save(end)
        try:
            s = write()
        except Exception as e:
            self.say('the outputs could not be written (%s: %s); the loaded state is saved: %s' % (
                type(e).__name__, e, self.rebuildHint(end)))
            raise
        self.markFinished(summary='summary.json')
        return s

    def rebuildHint(self, path):
        """How to get a run's outputs back from its state at `path` (finishRun's message)."""
        return '%s.reopen(%r) gives the run back' % (type(self).__name__, path)

    def startTimeStep(self, loaded=None, period=None):
        """The time-step options at the start of loading (experiments.timestep): the stiffness stepper, or density
        scaling: every grain its own P-wave step densityStep / dtSafety, and the body that loads the grains
        (`loaded`: a plate, a sleeper; None: kinematic platens) from the stiffness K of its contacts: a body of mass
        M on springs K is stable below 2 sqrt(M / K); taken as sqrt(M / (LOADED_STIFFNESS_MARGIN K)), as more
        contacts form under it when grains crush (None if it is not dynamic or touches nothing). With quasiStatic
        (a cyclic experiment, load cycles of `period` [s]) the step is the quasi-static option's (quasistatic.StepChoice),
        chosen again at every cycle's end."""
        p = self.p
        if p['timeStep'] == 'stiffness':
            timestep.startStiffnessStep(p['dtSafety'])
        step = p['densityStep']
        if p.get('quasiStatic', 0) > 0:
            self.stepChoice = quasistatic.StepChoice(p.startTimeStep(), p['quasiStatic'], p['quasiStaticRatio'], period,
                                                     p['abrasionPeriod'], p['quasiStaticStart'])
            self.adopt()
            step = self.stepChoice.step
        if step > 0:
            own = {}
            if loaded is not None:
                b = O.bodies[loaded]
                K = sum(i.phys.kn for i in b.intrs() if i.isReal)
                own[loaded] = math.sqrt(b.state.mass / (LOADED_STIFFNESS_MARGIN * K)) if b.dynamic and K > 0 else None
            if self.stepChoice is not None:
                self.stepChoice.loaded = own
            timestep.startDensityScaling(self, step, step / p['dtSafety'], own)

    stepChoice = None   # the quasi-static option's piece (quasiStatic > 0)

    def ownStep(self):
        """The grains' own P-wave step [s] under density scaling now (0: none): the quasi-static option's, else
        densityStep / dtSafety."""
        return quasistatic.ownStep(self.p, self.stepChoice)

    def savedParams(self, values, units):
        """The parameters of a saved state in today's units (units: PARAM_UNITS when it was saved; subclasses convert
        what changed)."""
        return values

    def baseState(self):
        wall, cpu = self.seconds()
        return {'params': dict(self.p), 'paramUnits': PARAM_UNITS, 'saved': self.saved, 'wallSeconds': wall,
                'cpuSeconds': cpu, 'phases': runtime.ref(self.phases), 'dir': runtime.ref(self.dir)}

    def setBaseState(self, s, ref):
        self.p = self.Parameters.fromSaved(self.savedParams(dict(s['params']), s.get('paramUnits', 1)))
        self.phases, self.dir = ref(s['phases']), ref(s['dir'])
        self.saved = list(s['saved'])
        self.wallBefore, self.cpuBefore = s['wallSeconds'], s['cpuSeconds']
        self.started, self.cpuStarted = time.time(), time.process_time()

    @classmethod
    def fromScene(cls, readOnly=False, source=None, into=None, **overrides):
        """The experiment saved in the current scene, rebuilt (ballast.runtime.restore). It writes into a new
        run directory (<results>/<run id>-2, ... unless results or runId are given) when it first writes;
        readOnly=True: never (for inspecting a finished run). source: the state file it came from; run.json of the
        run that goes on names it (continuesState) and the saved run's folder (continues). into: the folder of a
        killed run that goes on (resumeKilled), written into from the start, before reopened() writes anything."""
        bad = sorted(k for k in overrides if k not in cls.REOPEN_PARAMS)
        if bad:
            raise TypeError('%s.reopen: %s cannot be changed in a saved run (only %s)' % (
                cls.NAME, ', '.join(bad), ', '.join(cls.REOPEN_PARAMS)))
        found = [o for o in runtime.restore().values() if isinstance(o, cls)]
        if len(found) != 1:
            raise RuntimeError('%s: this scene holds %d saved %s experiments (O.tags[%r]); expected one' % (
                cls.NAME, len(found), cls.NAME, runtime.TAG))
        exp = found[0]
        old = exp.dir
        exp.p = exp.p.replace(**overrides)
        if readOnly or 'results' in overrides or 'runId' in overrides:
            exp.dir = RunDirectory(exp.p['results'], overrides.get('runId', old.wanted), readOnly)
            exp.dir.previous = old.previous or old.path   # the saved run's folder (a restored one holds it as previous)
            runtime.unregister(old)
            exp.adopt()
        if into is not None:
            exp.dir.goOnIn(into)
        exp.dir.source = source
        exp.phases.progressSeconds = exp.p['progress']
        exp.reopened()
        return exp

    def reopened(self):
        """After fromScene (subclasses: say where the run goes on)."""

    def requireSamePhysics(self, saved, how):
        """ParamError naming the first parameter beyond REOPEN_PARAMS whose value differs from the saved run's."""
        for k in self.Parameters.PARAMS:
            if k not in self.REOPEN_PARAMS and saved.p[k] != self.p[k]:
                raise ParamError(k, '%s: %s = %r is not allowed with %s: the saved run has %s = %r' % (
                    self.Parameters.OWNER, k, self.p[k], how, k, saved.p[k]))

    def resumeKilled(self):
        """With resume: the run killed in <results>/<runId> (run.json 'running') reopened from the last state it
        saved, in its own folder, and taken to the end it was going to (the subclass's resumed(state)). Returns
        the summary, or None when that folder holds no killed run with a saved state (this run then starts afresh).
        ParamError when that run's process is alive on this machine or its physics is not this run's."""
        p = self.p
        if not p.get('resume'):
            return None
        folder = os.path.join(p['results'], runDirName(p['runId']))
        doc = runStatus(folder) or {}   # a live run first, whether or not it has saved a state yet
        if doc.get('status') == 'running' and doc.get('host') == socket.gethostname() and processAlive(doc.get('pid')):
            raise ParamError('resume', '%s: resume = 1 is not allowed: the run in %s is alive (pid %d); stop it first' % (
                self.Parameters.OWNER, folder, doc['pid']))
        state, why = resumableState(folder)
        if state is None:
            if why in ('no such folder', 'the run finished') or not any(
                    n.startswith('state-') for n in os.listdir(folder)):
                self.say('resume: no killed run with a saved state in %s (%s): the run starts afresh' % (folder, why))
                return None
            raise ParamError('resume', '%s: resume = 1 is not allowed: the killed run in %s cannot go on: %s' % (
                self.Parameters.OWNER, folder, why))
        if why:
            self.say('resume: %s' % why)
        exp = type(self).reopen(state, into=folder, **{k: p[k] for k in self.REOPEN_PARAMS})
        self.requireSamePhysics(exp, 'resume (the killed run has other values)')
        exp.markRunning(resumedFrom=os.path.basename(state))
        exp.cutJumps()
        return exp.resumed(state)

    # ------------------------------------------------------------------ density scaling (experiments.timestep)
    def densityGuard(self):
        """YADE does not save NewtonIntegrator.densityScaling: a scene saved with density scaling holds this
        callback alive, first in the chain, so that the first step after O.load runs it, and with it the
        runtime's restore (restored() calls resumeDensityScaling) before Newton moves anything; then it
        sleeps until the next save."""
        chain.engine(timestep.GUARD).dead = True

    def beforeSave(self):
        """The runtime's call before O.save: the density guard awake in the saved scene."""
        guard = chain.engine(timestep.GUARD)
        if guard is not None:
            guard.dead = False

    def restored(self):
        """After the runtime rebuilt the scene's objects (subclasses that override it call this too)."""
        self.resumeDensityScaling()

    def resumeDensityScaling(self):
        """After a restore: Newton scales densities again if this run does (YADE's O.load leaves it off)."""
        if chain.engine(timestep.GUARD) is not None:
            timestep.enableDensityScaling()

    @classmethod
    def reopen(cls, path, readOnly=False, into=None, **overrides):
        """O.load(path) of a state saved by a run, and its experiment back (see fromScene)."""
        who = '%s.reopen' % cls.NAME
        checkStateFile(path, who)
        try:
            O.load(path)
        except Exception as e:  # YADE's messages name neither the file nor the cause
            raise StateFileError('%s: %s is not a loadable state: YADE could not read it (%s: %s; an XML state cut short '
                                 'or damaged inside its compression?)' % (who, path, type(e).__name__, e or 'no message')) \
                from None
        saved = runtime.savedTypes()
        from . import declaration, names   # an experiment's saved type is its declaration's owner (BoxTest, ...)
        owners = {declaration(n).owner for n in names()}
        others = sorted(t for t in saved if t in owners and t != cls.persistentType)
        if cls.persistentType not in saved and others:
            raise StateFileError('%s: %s is a state of another experiment (it holds a saved %s, not a %s)' % (
                who, path, others[0], cls.persistentType))
        return cls.fromScene(readOnly=readOnly, source=os.path.abspath(path), into=into, **overrides)
