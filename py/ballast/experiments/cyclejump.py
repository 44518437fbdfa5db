"""Cycle jumping for any cyclic experiment (docs/cycles.md): at the end of each simulated load cycle the
experiment reports the cycle; over the last `window` simulated cycles without a crush or an abrasion the
jumper measures each grain's fatigue damage rate, and where the C++ core (pkg/CycleJump.hpp) allows a jump
of DN cycles every grain's damage is advanced by DN rates at once. Crushes are never extrapolated: the jump
ends before the cycle the first grain would fail in. The grains do not move during a jump: the bed has seen
n simulated cycles when the count says N, so the settlement of the jumped cycles is b ln(N / n), with b of
the law s = a + b ln n fitted to the simulated cycles without the steps of those with a crush or an abrasion
(ballast.settlementlaws.settlementJumped), reported apart: in cycles.csv at each simulated cycle, in jumps.csv
at each jump's end (settlementJumpedTotal, the same definition; settlementJumped is what the jump adds to the
total of the jump before, so a jump's share can be negative where the law's b fell).

The experiment owns the cycle count and the states: it calls :meth:`CycleJumper.cycleEnded` at each simulated
cycle's end, and when that returns a plan, :meth:`CycleJumper.apply` at the start of the next step (where a
saved state resumes exactly), saving the states before and after."""
import numpy as np
import pandas as pd

from .. import _ballast, runtime
from ..settlementlaws import settlementLaw
from ..runfiles import writeAtomic

LOG_COLUMNS = ('jump', 'cycle', 'cycles', 'to', 'limit', 'grain', 'maxRate', 'maxDamage', 'settlementLawA',
               'settlementLawB', 'settlementLawR2', 'settlementJumped', 'settlementJumpedTotal', 'stateBefore',
               'stateAfter', 'grainPeak', 'grainDrift')


# attribute -> its parameter (ballast.experiments.parameters.CYCLE_JUMP), in the constructor's order
SETTINGS = {'window': 'jumpWindow', 'steady': 'jumpSteady', 'maxDamage': 'jumpMaxDamage', 'margin': 'jumpMargin',
            'growth': 'jumpGrowth', 'after': 'jumpAfter', 'driftNoise': 'jumpDriftNoise',
            'driftDamage': 'jumpDriftDamage'}
INTEGER = ('window', 'margin', 'after')  # counts of cycles


def _pack(a):
    return None if a is None else {'shape': list(a.shape), 'data': runtime.packArray(a)}


def _unpack(s):
    return None if s is None else runtime.unpackArray(s['data']).reshape(s['shape'])


@runtime.persistent('CycleJumper')
class CycleJumper:
    """The damage rates of the last simulated cycles, the jumps made and the settlement they extrapolated.
    window [cycles], steady [-], maxDamage [-], margin [cycles], growth [-], after [cycles], driftNoise [-],
    driftDamage [-]: the parameters jumpWindow, jumpSteady, jumpMaxDamage, jumpMargin, jumpGrowth, jumpAfter,
    jumpDriftNoise, jumpDriftDamage
    (ballast.experiments.parameters.CYCLE_JUMP, checked by the experiment)."""

    def __init__(self, window=10, steady=0.2, maxDamage=0.05, margin=1, growth=1.0, after=0, driftNoise=2.0,
                 driftDamage=0.0):
        self._set(dict(zip(SETTINGS.values(), (window, steady, maxDamage, margin, growth, after, driftNoise,
                                               driftDamage))))
        self.target = None        # the cycle the run ends at (no jump goes past it)
        self.ids = []             # the grains of the window (body ids)
        self.last = None          # (2, n): their damage D and damaging peaks at the last cycle's end (after a jump)
        self.increments = []      # per simulated cycle of the window: (3, n) increments of D and peaks, the largest s
        self.direct = []          # [cycle (with the jumped ones), simulated settlement [m], a grain crushed or abraded
                                  # in it] of every simulated cycle (no third entry in states of before it: False)
        self.jumps = []           # one dict per jump (LOG_COLUMNS)
        self.jumped = 0           # cycles not simulated [cycles]
        self.pending = None       # the plan of the jump to make at the next step
        self.on = True            # False: the cycles are read, no jump is planned (a run reopened without jump)

    @classmethod
    def of(cls, p):
        """The jumper of the parameters p, None without jump."""
        if not p['jump']:
            return None
        j = cls()
        j._set(p)
        return j

    def _set(self, p):
        """The settings from the parameters p (by parameter name, SETTINGS)."""
        for attr, name in SETTINGS.items():
            setattr(self, attr, int(p[name]) if attr in INTEGER else p[name])

    def seed(self, cycles, settlements, changed):
        """Jumping started in a run reopened after simulated cycles (a slice, continueFrom, a resume with jump):
        those cycles, numbered in the count, with their simulated settlement [m] and whether a grain crushed or
        abraded in each, become the series the settlement law is fitted to, as if the jumper had seen them; n, the
        cycles simulated, then counts them (cycles.csv's definition)."""
        if self.direct:
            raise RuntimeError('CycleJumper.seed: the jumper has seen %d cycles already' % len(self.direct))
        self.direct = [[int(c), float(s), bool(x)] for c, s, x in zip(cycles, settlements, changed)]

    def tune(self, p):
        """The parameters p (checked) of a run reopened with other jump settings; jump off: no more jumps, the
        cycles jumped stay counted."""
        self._set(p)
        self.on = bool(p['jump'])
        self.increments = self.increments[-self.window:]

    def cycleEnded(self, engine, ids, cycle, settlement, changed):
        """A simulated cycle `cycle` (numbered with the jumped ones) ended with the simulated permanent settlement
        [m]; changed: a grain crushed or abraded in it. engine: the BallastCrushEngine with fatigue; ids: the
        grains. Returns the plan of a jump (also kept as pending) or None."""
        self.direct.append([int(cycle), float(settlement), bool(changed)])
        ids = [int(i) for i in ids]
        F = engine.fatigueState(ids)
        now = np.vstack([F[:, 0], F[:, 3]])
        peaks = engine.takeFatiguePeaks(ids)
        if changed or ids != self.ids or self.last is None:   # a new network: measure afresh
            self.ids, self.last, self.increments = ids, now, []
            return None
        self.increments = (self.increments + [np.vstack([now - self.last, peaks[None, :]])])[-self.window:]
        self.last = now
        # the last cycle of a run is simulated: its end state is a real one
        remaining = (self.target - cycle - 1) if self.target is not None and self.on else 0
        if len(self.increments) < self.window or remaining < 1 or cycle < self.after:
            return None
        inc = np.array(self.increments)                       # (window, 3, n)
        damage = now[0] - np.concatenate([np.cumsum(inc[::-1, 0], axis=0)[::-1], np.zeros((1, len(ids)))])
        damage = np.maximum.accumulate(np.maximum(damage, 0.0), axis=0)   # rounding of the sums: never falling
        cycles, limit, grain, maxRate, rate, peak, drift = _ballast.cycleJumpPlan(
            damage, inc[:, 2], cycle, remaining, self.window, self.steady, self.maxDamage, self.margin, self.growth,
            engine.fatigueEndurance, self.driftNoise, engine.fatigueExponent, self.driftDamage)
        if cycles < 1:
            return None
        self.pending = {'cycle': int(cycle), 'cycles': int(cycles), 'limit': limit,
                        # no grain bounds a jump by the cycles remaining or the growth: grain empty in jumps.csv
                        'grain': int(ids[grain]) if grain >= 0 else None, 'maxRate': float(maxRate),
                        'rate': rate, 'peakRate': np.mean(inc[:, 1], axis=0), 'grainPeak': float(peak),
                        'grainDrift': float(drift)}
        return self.pending

    def apply(self, engine, before='', after=''):
        """The pending jump: every grain of the window takes DN rates of damage and of damaging peaks, the cycles
        are counted as jumped, the settlement law of the simulated cycles gives their settlement. before, after:
        the states saved around it (names for the log). Returns the log entry."""
        plan, self.pending = self.pending, None
        n, ids = plan['cycles'], self.ids
        dD, dP = n * plan['rate'], np.round(n * plan['peakRate'])
        engine.advanceFatigue(ids, dD, dP)
        self.last = self.last + np.vstack([dD, dP])
        N0 = plan['cycle']
        law = settlementLaw([d[1] for d in self.direct], [len(d) > 2 and d[2] for d in self.direct])
        self.jumped += n
        # cycles.csv's definition (settlementlaws.settlementJumped) at the jump's end: b ln(N / n), N the count, n the
        # cycles simulated, b of the law known now; the jump's own share is what it adds to the previous jump's total
        total = law['b'] * np.log((N0 + n) / len(self.direct)) if law else 0.0
        ds = total - self._jumpedTotal()
        entry = {'jump': len(self.jumps) + 1, 'cycle': N0, 'cycles': n, 'to': N0 + n, 'limit': plan['limit'],
                 'grain': plan['grain'], 'maxRate': plan['maxRate'],
                 'maxDamage': float(np.max(engine.fatigueState(ids)[:, 0])) if ids else 0.0,
                 'settlementLawA': law['a'] if law else None, 'settlementLawB': law['b'] if law else None,
                 'settlementLawR2': law['r2'] if law else None, 'settlementJumped': float(ds),
                 'settlementJumpedTotal': float(total),
                 'stateBefore': before, 'stateAfter': after, 'grainPeak': plan.get('grainPeak'),
                 'grainDrift': plan.get('grainDrift')}
        self.jumps.append(entry)
        return entry

    def _jumpedTotal(self):
        """The extrapolated settlement [m] at the last jump's end (0 before any): its settlementJumpedTotal, or in
        states of before that column the sum of the jumps' settlementJumped."""
        if not self.jumps:
            return 0.0
        last = self.jumps[-1]
        return last['settlementJumpedTotal'] if 'settlementJumpedTotal' in last else sum(
            e['settlementJumped'] for e in self.jumps)

    def writeLog(self, path):
        """jumps.csv: a row per jump (LOG_COLUMNS)."""
        writeAtomic(path, pd.DataFrame(self.jumps, columns=LOG_COLUMNS).to_csv(index=False, float_format='%.9g'))

    # ------------------------------------------------------------------ saving
    def state(self):
        s = {k: getattr(self, k) for k in tuple(SETTINGS) + ('target', 'ids', 'direct', 'jumps', 'jumped', 'on')}
        s['last'] = _pack(self.last)
        s['increments'] = [_pack(a) for a in self.increments]
        s['pending'] = None if self.pending is None else dict(
            self.pending, rate=_pack(self.pending['rate']), peakRate=_pack(self.pending['peakRate']))
        return s

    @classmethod
    def fromState(cls, s, ref=None):
        # states saved before jumpDriftNoise or jumpDriftDamage existed: the rules of then (0)
        before = {'driftNoise': 0.0, 'driftDamage': 0.0}
        j = cls(**{k: s[k] if k in s else before[k] for k in SETTINGS})
        for k in ('target', 'ids', 'direct', 'jumps', 'jumped'):   # states of before also hold an unused 'extrapolated'
            setattr(j, k, s[k])
        j.on = s.get('on', True)
        j.last = _unpack(s['last'])
        j.increments = [_unpack(a) for a in s['increments']]
        if s['pending'] is not None:
            j.pending = dict(s['pending'], rate=_unpack(s['pending']['rate']),
                             peakRate=_unpack(s['pending']['peakRate']))
        return j
