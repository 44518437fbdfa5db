"""Running the simulation in phases with progress lines: how far (simulated time, % of the phase), how
fast, time left, and what the phase wants to show; steps and wall seconds counted per phase. Every
experiment runs through one :class:`Phases` (its ``runUntil``)."""
import math
import time

from yade import O

from .. import runtime
from ..names import fmtTime


@runtime.persistent('Phases')
class Phases:
    """Runs O in chunks until a phase ends. Where a phase ends never depends on the machine's speed:
    the end test `done()` runs in a PyRunner every checkEvery steps, which ends the run after the step it
    is in, so a seed always gives the same packing and the same run."""

    CHUNK_WALL = 2.0  # [s] wall time of a chunk of O.run(n, True) (each costs ~40 ms of overhead)
    LABEL = 'phaseEnd'

    def __init__(self, progressSeconds, name):
        self.progressSeconds, self.name = progressSeconds, name
        self.started = time.time()
        self.steps, self.wall = {}, {}
        self.done, self.finished = None, False
        self.running = None  # (phase, O.iter, wall time) at the start of the phase being run

    def say(self, msg):
        print('[%s %7.1fs] %s' % (self.name, time.time() - self.started, msg), flush=True)

    def check(self):
        """The PyRunner's call: end the run after this step once the phase is done. Not O.pause(): it lets
        O.run(n, True) return while the step is still running its later engines, and the worker thread
        then goes on stepping when the next O.run starts before it has looked (a step too many under load).
        A stop iteration ends the loop in the worker itself, once the step is whole."""
        if self.done is not None and self.done():
            self.finished = True
            O.stopAtIter = O.iter + 1

    def run(self, phase, done=None, tEnd=None, simSpan=None, simStart=None, extra=None, checkEvery=200,
            afterChunk=None):
        """Run until O.time reaches tEnd [s] or done() is true, a progress line every progressSeconds.
        tEnd may be a function giving the end [s] as it stands (cycle jumping moves it: fewer cycles are
        simulated). simSpan: planned simulated duration [s] of the phase, from simStart (for % and time left)."""
        end = tEnd if callable(tEnd) else (lambda: tEnd)
        w0, i0, t0 = time.time(), O.iter, O.time
        lastPrint = time.time()
        chunk = 500
        self.finished, self.done, self.running = False, done, (phase, i0, w0)
        if done is not None:
            O.engines = O.engines + [runtime.callback(self, 'check', iterPeriod=checkEvery, label=self.LABEL)]
        try:
            while not self.finished:
                stop = end()
                if stop is not None and O.time >= stop - 0.5 * O.dt:
                    break
                tw = time.time()
                n = chunk if stop is None else max(1, min(chunk, int(math.ceil((stop - O.time) / O.dt - 0.5))))
                O.run(n, True)
                if n == chunk:
                    chunk = int(min(max(chunk * self.CHUNK_WALL / max(time.time() - tw, 1e-3), 100), 50000))
                if afterChunk is not None:
                    afterChunk()
                now = time.time()
                if now - lastPrint >= self.progressSeconds:
                    lastPrint = now
                    self.say(self._line(phase, (O.time - t0) / max(now - w0, 1e-9), simSpan, simStart, extra))
        finally:
            if done is not None:
                O.engines = [e for e in O.engines if e.label != self.LABEL]
            self.done = None
            self.steps, self.wall = self.counts()
            self.running = None

    def counts(self):
        """(steps, wall seconds) per phase, the phase being run included up to now: a state saved mid-phase
        carries them, so a resumed run counts on from there."""
        steps, wall = dict(self.steps), dict(self.wall)
        if self.running is not None:
            phase, i0, w0 = self.running
            steps[phase] = steps.get(phase, 0) + O.iter - i0
            wall[phase] = wall.get(phase, 0) + time.time() - w0
        return steps, wall

    def _line(self, phase, rate, simSpan, simStart, extra):
        """rate: simulated over wall seconds since the phase (or its resumption) began, stable from line to line."""
        line = '%-8s t=%.4f s  step %d  dt=%.2e s' % (phase, O.time, O.iter, O.dt)
        if simSpan:
            elapsed = O.time - simStart
            eta = (simSpan - elapsed) / rate if rate > 0 else None
            line += '  %5.1f%% of %s  ETA %s' % (100 * min(elapsed / simSpan, 1), 'loading' if phase == 'load' else 'phase',
                                                 fmtTime(eta))
        if extra:
            line += '  ' + extra()
        return line

    def state(self):
        steps, wall = self.counts()
        return {'steps': steps, 'wall': wall, 'progressSeconds': self.progressSeconds, 'name': self.name}

    @classmethod
    def fromState(cls, s, ref=None):
        ph = cls(s['progressSeconds'], s['name'])
        ph.steps, ph.wall = dict(s['steps']), dict(s['wall'])
        return ph
