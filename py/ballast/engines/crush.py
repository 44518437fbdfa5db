"""Bulk crushing, section 2 of the paper (eqs. 1-4, Fig. 1): a grain whose criterion stress (the von
Mises stress of its fabric stress, eqs. 2-3, by default) exceeds its strength f_t = ft0 / r^m (eq. 4)
is replaced by the fragments of a pattern of Fig. 1, inside it. The decision for all grains is the C++
core's (pkg/BallastCrushEngine.cpp); fatigue (docs/fatigue.md) and what follows a replacement
(energy snapshots, growth with keep='volume') are components of their own."""
import numpy as np
from yade import O, Vector3

from .. import _ballast, energy, harvest, runtime
from ..engineparams import CRUSH
from .base import BallastEngine, docstring
from .fatigue import FatigueState
from .replacements import ENERGY_AFTER_STEPS, Replacements


@runtime.persistent('BallastCrushEngine')
class BallastCrushEngine(BallastEngine):
    _params = CRUSH
    _outputs = {
        'nCrushed': (0, 'grains crushed so far'),
        'volumeLost': (0.0, 'grain volume lost by crushing [m^3]'),
        'massLost': (0.0, 'grain mass lost by crushing [kg]'),
        'events': ([], 'one dict per crushed grain: kind, t [s], iter, id, pos [m], radius [m], value (sigma_e [Pa]), '
                       'strength (f_t [Pa]; f_t (1 - D) with fatigue), newIds; energyBefore, energyAfter (the first '
                       'check at least %d steps after) and with keep=volume energyGrown: [kinetic, elastic] [J] of '
                       'the grain or its fragments, its neighbours before the crush and those of the fragments '
                       '(ballast.energy)' % ENERGY_AFTER_STEPS),
        'nChecks': (0, 'checks run so far'),
        'checkSeconds': (0.0, 'wall time spent in checks [s]'),
        'maxStressRatio': (0.0, 'largest sigma_e / f_t over the grains at the last check [-]'),
        'maxCrushableRatio': (0.0, 'largest sigma_e / f_t over the grains that can crush (r >= rMin) at the last '
                                   'check, 0 if none [-] (fragments below rMin may be far above their f_t)'),
        'nFatigueCrushed': (0, 'grains crushed below their undamaged strength (sigma_e <= f_t), by fatigue damage'),
        'maxDamage': (0.0, 'largest fatigue damage D over the grains at the last check [-]'),
    }

    def __init__(self, **kw):
        BallastEngine.__init__(self, **kw)
        self.__dict__['_fatigue'] = FatigueState()
        self.__dict__['_replacements'] = Replacements()

    def _componentState(self):
        d = self.__dict__
        return {'replacements': d['_replacements'].state(), 'fatigue': d['_fatigue'].state(),
                'fatiguePeaks': d['_fatigue'].peaksState()}

    def _setComponentState(self, s):
        self.__dict__['_replacements'].setState(s['replacements'])
        self.__dict__['_fatigue'].setState(s['fatigue'], s.get('fatiguePeaks'))

    def fatigueState(self, ids=None):
        """Fatigue state by body id, an (n,4) array: damage D [-], running extreme of s [-], rising (1/0),
        damaging peaks; rows of ids (default: every id up to the largest seen)."""
        return self.__dict__['_fatigue'].of(ids)

    def takeFatiguePeaks(self, ids):
        """The largest sigma_e / f_t [-] of each grain of ids since the last call (0 if none), for cycle jumping
        (docs/cycles.md)."""
        return self.__dict__['_fatigue'].takePeaks(ids)

    def advanceFatigue(self, ids, damage, peaks):
        """Cycle jumping (docs/cycles.md): the grains ids take damage [-] (an array) and peaks more damaging peaks."""
        self.__dict__['_fatigue'].advance(ids, damage, peaks)
        self.__dict__['maxDamage'] = float(np.max(self.fatigueState(ids)[:, 0])) if len(ids) else self.maxDamage

    def _summary(self):
        return 'nCrushed=%d volumeLost=%.4g m^3 massLost=%.4g kg' % (self.nCrushed, self.volumeLost, self.massLost)

    def strengthFactors(self, ids):
        """Each grain's Weibull strength factor w (docs/strength.md): a function of (seed, body id, modulus),
        so the same after O.save/O.load and drawn afresh for fragments (new ids); None without scatter."""
        if self.weibullModulus == 0:
            return None
        ids = np.asarray(ids, dtype=np.int64)
        # the same grains as the last check's, as at most checks: the same factors (drawing them was a quarter of a
        # check's own time on the triaxial specimen, bench/bench_checks.py)
        key = (self.seed, self.weibullModulus, ids.tobytes())
        last = self.__dict__.get('_weibull')
        if last is None or last[0] != key:
            w = _ballast.weibullFactors(self.seed, ids, self.weibullModulus)
            w.flags.writeable = False   # shared by the checks that follow
            last = (key, w)
            self.__dict__['_weibull'] = last
        return last[1]

    def evaluate(self, ids, radii):
        """(the criterion's stress [Pa], the strength f_t [Pa], crush) of the grains `ids` now, without fatigue."""
        fMax = harvest.largestContactForces(ids) if self.criterion == 'maxContactForce' else None
        return _ballast.crushCheck(harvest.stresses(ids), radii, self.ft0, self.m, self.rMin, self.criterion, fMax,
                                   self.strengthFactors(ids))

    def _check(self, tab, ids, radii):
        if len(ids) == 0:
            return False
        se, ft, crush = self.evaluate(ids, radii)
        d = self.__dict__
        ratio = se / ft
        d['maxStressRatio'] = float(np.max(ratio))
        crushable = radii >= self.rMin  # eq. 1's other condition
        d['maxCrushableRatio'] = float(np.max(ratio[crushable])) if crushable.any() else 0.0
        strength = ft
        if self.fatigue:  # docs/fatigue.md: a sample of s for every grain, crush when s > 1 - D
            crush, damage = d['_fatigue'].check(ratio, radii, ids, self.fatigueExponent, self.fatigueEndurance,
                                                self.fatigueHysteresis, self.rMin)
            strength = ft * (1 - damage)
            d['maxDamage'] = float(np.max(damage))
        changed = d['_replacements'].recordEnergies(d['_events'])
        hit = np.flatnonzero(crush)
        if 0 < self.maxPerCheck < len(hit):  # sequential crushing: the most overloaded first
            hit = hit[np.argsort(-(se[hit] / strength[hit]), kind='stable')[:self.maxPerCheck]]
        if len(hit):
            pw0 = self._dtBefore()
            fragments = []
            tensors = harvest.stresses(ids[hit])  # this step's, read once before any change (a clump splits by it)
            for j, k in enumerate(hit):
                if se[k] <= ft[k]:
                    d['nFatigueCrushed'] += 1
                newIds = self._replace(tab, int(ids[k]), float(radii[k]), float(se[k]), float(strength[k]), tensors[j])
                if self.fatigue:  # fragments start undamaged (docs/fatigue.md)
                    d['_fatigue'].fresh(newIds)
                fragments += newIds
            tab.commit()
            self._adjustDt(pw0, fragments)
            changed = True
        return d['_replacements'].grow(tab, self.growTime, d) or changed

    def _fragments(self, pos, r):
        """Fig. 1's fragments inside the grain at pos of r_eq r [m], the next orientation of the engine's sequence."""
        frags = _ballast.placeFragments(self.pattern, (pos[0], pos[1], pos[2]), r, self.seed, self._counter)
        self.__dict__['_counter'] += 1
        return frags

    def _replace(self, tab, bid, r, se, ft, stress):
        """Section 2: the grain (r_eq r [m], stress tensor stress [Pa]) crushes as its kind says: a sphere is erased
        and replaced by fragments inside it (Fig. 1), a clump splits into pieces of its members (docs/grains.md)."""
        pos = Vector3(O.bodies[bid].state.pos)
        neighbours = energy.partners([bid])
        before = energy.snapshot([bid])  # kinetic and elastic energy of the grain and its neighbours
        rep = tab.kind.crush(bid, stress, lambda: self._fragments(pos, r), self.keep == 'mass')
        tab.replaced(bid, rep.ids, rep.radii, rep.mask)
        d = self.__dict__
        d['nCrushed'] += 1
        d['volumeLost'] += rep.volumeBefore - rep.volumeAfter
        d['massLost'] += rep.massBefore - rep.massAfter
        self._event('crush', bid, pos, r, se, ft, rep.ids)
        k = len(d['_events']) - 1
        d['_events'][k]['energyBefore'] = before
        if rep.split is not None:  # a clump's pieces: volumeLost above is minus the overlap they share
            d['_events'][k]['split'] = rep.split
        # pieces of a clump keep its volume (ratio 1): nothing to regrow; fragments always have less
        d['_replacements'].added(k, rep.ids, neighbours, self.keep == 'volume' and rep.volumeRatio != 1, rep.volumeRatio)
        return rep.ids


docstring(BallastCrushEngine, 'Bulk crushing, section 2 (eqs. 1-4, Fig. 1).')
