"""The oedometric test of sections 4-5 as an experiment: parameters (checked when it is built), then
prepare() (the packing), load() (the load cycle of eq. 8 with both engines) and summary().

    from ballast.oedometer import Oedometer
    run = Oedometer(seed=2, f=4, pattern=14)
    run.prepare()
    run.load()
    run.summary()

The pieces are objects that can be replaced without editing the package: ``packing`` (default
:class:`StoredPacking`), ``load`` (:class:`PlateLoad`, :class:`ServoLoad` or :class:`DisplacementLoad` by
``loadMode``), ``outputs`` (:class:`Outputs`).

State: the experiment's PyRunners call it through :mod:`ballast.oedometer.callbacks`. ``save(path)``
writes the experiment's state to ``O.tags`` and calls ``O.save``; the run saves itself at the start
and at the end of loading (and every ``saveEvery``). ``Oedometer.reopen(path)`` loads such a state in
any process and gives the experiment back, ready to ``load()`` on; a plain ``O.load(path)`` followed by
``O.run()`` rebuilds it at its first callback.
"""
import importlib
import json
import math
import os
import time
import uuid

import numpy as np
from yade import O, utils
from yade.wrapper import PyRunner, Sphere

from .. import engines as ballastEngines
from .. import grading
from ..engines import BallastAbrasionEngine, BallastCrushEngine
from ..geometry import sphereVolume
from ..names import fmtTime, runDirName
from ..params import CRUSH, requireWritableDir, validate
from . import callbacks, scene
from .callbacks import command
from .loading import MODES
from .outputs import Outputs
from .packing import StoredPacking
from .parameters import OWNER, PARAMS, check
from .progress import Phases

STATE_TAG = 'ballast.oedometer'           # the experiment's state (JSON), written by save()
TOKEN_TAG = 'ballast.oedometer.token'     # which experiment built this scene
SAVER = 'oedoSaver'
# parameters a reopened run may change: where and how it reports, not the physics
REOPEN_PARAMS = ('results', 'runId', 'progress', 'vtk', 'saveEvery', 'timing', 'cycles')


class Oedometer:
    """One realization of the paper's oedometric test. Keyword arguments: any parameter of
    :data:`ballast.oedometer.parameters.PARAMS` (a bad value raises ParamError here), and the pieces
    ``packing``, ``load``, ``outputs``."""

    def __init__(self, packing=None, load=None, outputs=None, **params):
        self.p = check(params)
        self.packing = packing if packing is not None else StoredPacking()
        self.loading = load if load is not None else MODES[self.p['loadMode']]()
        self.outputs = outputs if outputs is not None else Outputs()
        self.phases = Phases(self.p['progress'])
        self.T = 1.0 / self.p['f']
        self.token = uuid.uuid4().hex
        self.runId = self.out = None
        self.cylinder = self.ballast = self.steel = None
        self.initial = None          # massInitial, nGrains, volumeGrains at the start of loading
        self.maxProtrusion, self.nEscaped = 0.0, 0
        self.saved = []              # state files written so far
        self.wallBefore, self.cpuBefore = 0.0, 0.0  # of the runs this one continues
        self.started, self.cpuStarted = time.time(), time.process_time()
        self.lastIter = 0

    def __repr__(self):
        return '<Oedometer %s: %s>' % (self.runId, ', '.join('%s=%r' % (k, self.p[k]) for k in ('seed', 'f', 'Tc', 'ft0',
                                                                                                'pattern')))

    # ------------------------------------------------------------------ scene ownership
    def newScene(self):
        """O.reset() for a piece that builds a scene: the callbacks then still find this experiment."""
        O.reset()
        self.adopt()

    def adopt(self):
        """Make the current scene this experiment's (after O.loadTmp of an earlier state of it, say)."""
        O.tags[TOKEN_TAG] = self.token
        self.lastIter = O.iter
        callbacks.setLive(self)

    def ownsScene(self):
        """True while the scene is the one this experiment is running (not another, not an older state of it)."""
        if TOKEN_TAG not in O.tags.keys() or O.tags[TOKEN_TAG] != self.token or O.iter < self.lastIter:
            return False
        self.lastIter = O.iter
        return True

    # ------------------------------------------------------------------ the experiment
    def makeOutDir(self):
        """<results>/<run id>/, created atomically; an existing one is never reused (a suffix -2, -3, ...)."""
        p = self.p
        rid = runDirName(p['runId'] or O.tags['d.id'])
        os.makedirs(p['results'], exist_ok=True)
        for k in range(1, 10000):
            name = rid if k == 1 else '%s-%d' % (rid, k)
            path = os.path.join(p['results'], name)
            try:
                os.mkdir(path)
            except FileExistsError:
                continue
            self.runId, self.out = name, path
            return
        raise RuntimeError('no free run directory for %s in %s' % (rid, p['results']))

    def checkOutputs(self):
        """Before any work: the results folder and the packing store can be created and written to."""
        requireWritableDir(OWNER, 'results', self.p['results'])
        if hasattr(self.packing, 'checkOutputs'):
            self.packing.checkOutputs(self)

    def prepare(self):
        """The packing (built, or loaded from the store), settled in the cylinder."""
        if self.out is None:
            self.checkOutputs()
            self.makeOutDir()
            self.phases.say('run %s -> %s' % (self.runId, self.out))
        self.adopt()
        self.packing.prepare(self)
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
            if self.cylinder is None:
                self.prepare()
            self.startLoading()
        self.adopt()
        t0 = self.loading.t0
        done = math.floor((O.time - t0 + 0.5 * O.dt) / self.T)
        total = done + cycles if cycles is not None else (p['cycles'] if done < p['cycles'] else done + 1)
        tStart, tEnd = O.time, t0 + total * self.T
        self.phases.run('load', self.loading.done, tEnd=tEnd, simSpan=tEnd - tStart, simStart=tStart,
                        afterChunk=self.checkContainment,
                        extra=lambda: 'cycle %d/%d  F=%.0f kN  delta=%.1f mm  crushed %d  abraded %d' % (
                            min(math.floor((O.time - t0) / self.T) + 1, total), total,
                            self.loading.force() / 1e3, self.loading.delta() * 1e3, self.counter('crush', 'nCrushed'),
                            self.counter('abrasion', 'nAbraded')))
        self.outputs.record()  # the last row, at the end of the cycle
        self.outputs.cycleEnd()
        end = os.path.join(self.out, 'state-end.yade.gz')
        self.save(end)
        try:
            s = self.summary()
            self.outputs.finish(self, s)
        except Exception as e:  # hours of loading are in the state: say how to get the outputs back
            self.phases.say('the outputs could not be written (%s: %s); the loaded state is saved: e = '
                            'Oedometer.reopen(%r); e.outputs.finish(e, e.summary()) writes them' % (
                                type(e).__name__, e, end))
            raise
        if p['timing']:
            self._writeTiming()
        self.phases.say('done in %s: peak F %.0f kN at delta %.2f mm, delta max %.2f mm, %d crushed, %d abraded, %d '
                        'steps; results in %s' % (fmtTime(s['wallSeconds']), s['peakForce'] / 1e3, s['deltaAtPeak'] * 1e3,
                                                  s['deltaMax'] * 1e3, s['nCrushed'], s['nAbraded'], s['steps'], self.out))
        return s

    def run(self):
        """prepare() and load(): the whole realization."""
        self.prepare()
        return self.load()

    def startLoading(self):
        """The start of load(): seat the plate, add the engines and the recorders, save the state."""
        p = self.p
        self.loading.start(self, self.steel)
        self.addEngines()
        x, r, m = self.grainArrays()
        self.initial = {'massInitial': float(np.sum(m)), 'nGrainsInitial': len(r),
                        'volumeGrains': float(np.sum(sphereVolume(r))), 'radii': r.tolist(), 'masses': m.tolist()}
        self.outputs.start(self)
        if p['saveEvery'] > 0:  # first in the chain: a state saved before the step begins resumes exactly
            O.engines = [PyRunner(command=command('experiment', 'checkpoint'), virtPeriod=p['saveEvery'],
                                  virtLast=O.time, label=SAVER)] + list(O.engines)
        if p['timing']:
            O.timingEnabled = True
        self.phases.say('load: plate at %.4f m on %d grains (%.1f kg, porosity %.3f), F = Fmax/2 [sin(2 pi f t - pi/2) + 1],'
                        ' Fmax = %.4g N, f = %g Hz, dt = %.2e s' % (self.loading.z0, len(r), self.initial['massInitial'],
                                                                   self.porosity0(), p['Fmax'], p['f'], O.dt))
        self.save(os.path.join(self.out, 'state-start.yade.gz'))

    def addEngines(self):
        """BallastCrushEngine and BallastAbrasionEngine after NewtonIntegrator, as the parameters say."""
        p = self.p
        extra = []
        if p['crush']:
            # the engine scales O.dt with the drop of PWaveTimeStep() after a replacement (eq. 5),
            # which keeps the dtSafety margin
            period = {'virtPeriod': p['Tc']} if p['Tc'] > 0 else {'iterPeriod': 1}
            # every engine parameter the experiment declares (parameters.PARAMS reuses CRUSH's declarations)
            own = {k: p[k] for k in CRUSH if k in p}
            crush = BallastCrushEngine(mask=0, label='crush', **period, **own)
            # checks at loading times k T_c (not at scene times, which include the preparation): where they fall
            # in the load cycle is then set by T_c and f alone (docs/oedometer.md, "Crushing period")
            crush.virtLast = self.loading.t0
            extra.append(crush)
        if p['abrasion']:
            extra.append(BallastAbrasionEngine(strength=p['strength'], gamma=p['gamma'], rMin=p['rMin'], mask=0,
                                               iterPeriod=p['abrasionPeriod'], label='abrasion'))
        O.engines = O.engines + extra

    def checkpoint(self):
        """The saver's call (saveEvery): a state at the start of this step."""
        self.save(os.path.join(self.out, 'state-iter%09d.yade.gz' % O.iter))

    # ------------------------------------------------------------------ engines and grains
    def engine(self, label):
        """The ballast engine with this label ('crush', 'abrasion') in O.engines, or None."""
        for e in O.engines:
            if e.label == label:
                if type(e) is PyRunner:  # loaded, not yet restored
                    ballastEngines.restore()
                    return self.engine(label)
                return e
        return None

    def degradingEngines(self):
        return [e for e in (self.engine('crush'), self.engine('abrasion')) if e is not None]

    def counter(self, label, name):
        e = self.engine(label)
        return getattr(e, name) if e is not None else 0

    def events(self):
        """The events of both engines, in time order."""
        ev = [e for eng in self.degradingEngines() for e in eng.events]
        ev.sort(key=lambda e: (e['t'], e['iter'], e['id']))
        return ev

    @staticmethod
    def sphereBodies():
        return [b for b in O.bodies if b is not None and isinstance(b.shape, Sphere)]

    def grainArrays(self):
        """(centres [m], radii [m], masses [kg]) of the grains."""
        bs = self.sphereBodies()
        if not bs:
            return np.zeros((0, 3)), np.zeros(0), np.zeros(0)
        x = np.array([[b.state.pos[0], b.state.pos[1], b.state.pos[2]] for b in bs])
        return x, np.array([b.shape.radius for b in bs]), np.array([b.state.mass for b in bs])

    def porosity0(self):
        """Porosity under the plate at the start of loading [-]."""
        return 1 - self.initial['volumeGrains'] / (math.pi * self.cylinder.Rin ** 2 * self.loading.z0)

    @staticmethod
    def unbalanced():
        u = utils.unbalancedForce()
        return u if math.isfinite(u) else 1.0

    def vRms(self):
        """Root mean square grain speed [m/s], sqrt(2 Ek / mass): the grains rest when it is small."""
        m = self.grainArrays()[2]
        return math.sqrt(2 * utils.kineticEnergy() / max(np.sum(m), 1e-300))

    def restInfo(self):
        return 'unbalanced %.3g  v_rms %.2g m/s' % (self.unbalanced(), self.vRms())

    def checkContainment(self):
        """Largest protrusion of a grain out of the cylinder (side, bottom, plate) and the number of
        grains whose centre left it."""
        x, r, _ = self.grainArrays()
        if len(r) == 0:
            return
        cyl = self.cylinder
        c = O.bodies[cyl.ids[0]].state.pos - cyl.pos0[0]
        rho = np.hypot(x[:, 0] - c[0], x[:, 1] - c[1])
        zTop = self.loading.top()
        prot = np.maximum.reduce([rho + r - cyl.Rv, c[2] - (x[:, 2] - r), x[:, 2] + r - zTop])
        self.maxProtrusion = max(self.maxProtrusion, float(prot.max()))
        self.nEscaped = max(self.nEscaped, int(np.sum((rho > cyl.Rv) | (x[:, 2] < c[2]) | (x[:, 2] > zTop))))

    # ------------------------------------------------------------------ results
    def summary(self):
        """What summary.json holds: peak force and displacements, crushes, the mass ledger, timings,
        the packing and every parameter."""
        p = self.p
        a = np.array(self.outputs.rows)
        k = int(np.argmax(a[:, 1]))
        r, m = self.grainArrays()[1:]
        engs = self.degradingEngines()
        loaded = a[:, 0] >= 0.05 * self.T
        target = self.loading.target(a[:, 0])
        steps = self.phases.steps
        half = min(0.5 * self.T, a[-1, 0])  # eq. 8 peaks at T/2
        F5 = np.where(np.isfinite(a[:, 5]), a[:, 5], a[:, 1]) >= 0.05 * p['Fmax']
        before, after = self.grading()
        s = {
            'runId': self.runId,
            'peakForce': float(a[k, 1]),
            'deltaAtPeak': float(a[k, 2]),
            'deltaAtAppliedPeak': float(np.interp(half, a[:, 0], a[:, 2])),
            'forceAtAppliedPeak': float(np.interp(half, a[:, 0], a[:, 1])),
            'seatingDelta': float(a[np.argmax(F5), 2]) if F5.any() else None,
            'deltaMax': float(np.max(a[:, 2])),
            'deltaFinal': float(a[-1, 2]),
            'nCrushed': self.counter('crush', 'nCrushed'),
            'nAbraded': self.counter('abrasion', 'nAbraded'),
            'nFatigueCrushed': self.counter('crush', 'nFatigueCrushed'),
            'volumeLost': float(sum(e.volumeLost for e in engs)),
            'massInitial': self.initial['massInitial'],
            'massFinal': float(np.sum(m)),
            'massLost': float(sum(e.massLost for e in engs)),
            'wallSeconds': self.wallBefore + time.time() - self.started,
            'cpuSeconds': self.cpuBefore + time.process_time() - self.cpuStarted,  # = wall on an idle machine, 1 thread
            'steps': sum(steps.values()),
            'stepsByPhase': dict(steps),
            'wallSecondsByPhase': {k: round(v, 3) for k, v in self.phases.wall.items()},
            'nGrainsInitial': self.initial['nGrainsInitial'],
            'nSpheresFinal': len(r),
            'maxGeneration': int(np.max(self.outputs.grains.generation, initial=0)),
            'Bg': grading.marsal(before, after),
            'Br': grading.hardin(before, after),
            'BBI': grading.bbi(before, after),
            'lostAsFines': p['lostAsFines'],
            'plateHeight0': self.loading.z0,
            'porosity0': self.porosity0(),
            'cycles': float(a[-1, 0] / self.T),
            'forceErrorRms': float(np.sqrt(np.mean((a[loaded, 1] - target[loaded]) ** 2))) if loaded.any() else None,
            'dtFinal': O.dt,
            'checkSeconds': {e.label: e.checkSeconds for e in engs},
            'nChecks': {e.label: e.nChecks for e in engs},
            'maxProtrusion': self.maxProtrusion,
            'nEscaped': self.nEscaped,
            'packingFile': self.packing.state().get('file'),
            'packingReused': self.packing.state().get('reused'),
            'prepEscaped': self.packing.state().get('escaped'),
            'stateFiles': [os.path.basename(f) for f in self.saved],
            'threads': int(os.environ.get('OMP_NUM_THREADS', 1)),
            'yade': getattr(getattr(__import__('yade'), 'config', None), 'version', ''),
            'params': dict(p),
        }
        return s

    def grading(self):
        """Percentage passing each sieve of grading.SIEVES_MM by mass at the start of loading and now; the
        mass the engines lost counts as fines passing every sieve if lostAsFines."""
        r, m = self.grainArrays()[1:]
        fines = sum(e.massLost for e in self.degradingEngines()) if self.p['lostAsFines'] else 0.0
        return (grading.passing(2 * np.array(self.initial['radii']), self.initial['masses']),
                grading.passing(2 * r, m, fines=fines))

    def _writeTiming(self):
        import contextlib
        import io
        from yade import timing
        buf = io.StringIO()
        with contextlib.redirect_stdout(buf):
            timing.stats()
        with open(os.path.join(self.out, 'timing.txt'), 'w') as fh:
            fh.write(buf.getvalue())

    # ------------------------------------------------------------------ saving and reopening
    def state(self):
        """Everything the experiment needs to go on after O.load(): JSON-able."""
        pieces = {}
        for name in ('packing', 'loading', 'outputs'):
            obj = getattr(self, name)
            pieces[name] = {'class': '%s:%s' % (type(obj).__module__, type(obj).__qualname__), 'state': obj.state()}
        return {'params': self.p, 'runId': self.runId, 'token': self.token, 'pieces': pieces,
                'cylinder': self.cylinder.state(), 'initial': self.initial, 'phases': self.phases.state(),
                'maxProtrusion': self.maxProtrusion, 'nEscaped': self.nEscaped, 'saved': self.saved,
                'wallSeconds': self.wallBefore + time.time() - self.started,
                'cpuSeconds': self.cpuBefore + time.process_time() - self.cpuStarted}

    def save(self, path):
        """The experiment's and the engines' state into O.tags, then O.save(path)."""
        self.saved.append(path)
        O.tags[STATE_TAG] = json.dumps(self.state())
        for e in self.degradingEngines():
            e._save()
        O.save(path)

    @classmethod
    def fromScene(cls, packing=None, load=None, outputs=None, **overrides):
        """The experiment saved in the current scene's O.tags, rebuilt; it writes into a new run
        directory (<results>/<run id>-2, ... unless results or runId are given)."""
        if STATE_TAG not in O.tags.keys():
            raise RuntimeError('%s: this scene holds no saved oedometer (O.tags[%r] is missing); it was not saved by '
                               'Oedometer.save()' % (OWNER, STATE_TAG))
        s = json.loads(O.tags[STATE_TAG])
        bad = sorted(k for k in overrides if k not in REOPEN_PARAMS)
        if bad:
            raise TypeError('%s.reopen: %s cannot be changed in a saved run (only %s)' % (
                OWNER, ', '.join(bad), ', '.join(REOPEN_PARAMS)))
        params = dict(s['params'], **overrides)
        if 'runId' not in overrides:
            params['runId'] = s['runId']
        given = {'packing': packing, 'loading': load, 'outputs': outputs}
        pieces = {}
        for name, spec in s['pieces'].items():
            obj = given[name]
            if obj is None:
                module, qualname = spec['class'].split(':')
                obj = getattr(importlib.import_module(module), qualname)()
            obj.setState(spec['state'])
            pieces[name] = obj
        exp = cls(packing=pieces['packing'], load=pieces['loading'], outputs=pieces['outputs'], **params)
        exp.cylinder = scene.Cylinder.fromState(s['cylinder'])
        exp.initial, exp.saved = s['initial'], list(s['saved'])
        exp.maxProtrusion, exp.nEscaped = s['maxProtrusion'], s['nEscaped']
        exp.phases.setState(s['phases'])
        exp.wallBefore, exp.cpuBefore = s['wallSeconds'], s['cpuSeconds']
        ballastEngines.restore()
        exp.makeOutDir()
        exp.adopt()
        exp.loading.bind(exp)
        exp.outputs.bind(exp)
        exp.phases.say('reopened %s at t = %.6f s (loading time %.6f s) -> %s' % (
            s['runId'], O.time, O.time - exp.loading.t0, exp.out))
        return exp

    @classmethod
    def reopen(cls, path, **overrides):
        """O.load(path) of a state saved by a run, and its experiment back (see fromScene)."""
        if not os.path.isfile(path):
            raise FileNotFoundError('%s.reopen: no such state file: %s' % (OWNER, path))
        O.load(path)
        return cls.fromScene(**overrides)


__all__ = ['Oedometer', 'PARAMS']
