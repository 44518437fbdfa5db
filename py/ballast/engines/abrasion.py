"""Abrasion, section 3 of the paper (eqs. 6-7): a grain whose largest Hertz pressure p0 at a contact
(eq. 7) exceeds the strength loses a surface layer, its radius times gamma. The pressure is read per
abrasion unit, the grain kind's: a sphere grain itself; a clump's member, which alone is worn
(docs/grains.md, "Corner wear of a clump"). The decision for all
contacts is the C++ core's (pkg/BallastAbrasionEngine.cpp); which contacts are read is the
prefilter's (:mod:`.prefilter`)."""
import numpy as np
from yade import O, Vector3

from .. import _ballast, runtime
from ..engineparams import ABRASION
from .base import BallastEngine, abradeUnit, docstring
from .prefilter import Prefilter


@runtime.persistent('BallastAbrasionEngine')
class BallastAbrasionEngine(BallastEngine):
    _params = ABRASION
    _outputs = {
        'nAbraded': (0, 'abrasion events so far'),
        'volumeLost': (0.0, 'grain volume lost by abrasion [m^3]'),
        'massLost': (0.0, 'grain mass lost by abrasion [kg]'),
        'events': ([], 'one dict per abrasion: kind, t [s], iter, id (the grain), pos [m] (the worn sphere\'s centre), '
                       'radius before (r_eq) [m], value (p0 [Pa]), strength [Pa], newIds (empty); a worn clump '
                       'member adds member (its id)'),
        'nChecks': (0, 'checks run so far'),
        'checkSeconds': (0.0, 'wall time spent in checks [s]'),
        'maxPressureRatio': (0.0, 'largest p0 / strength over the contacts read at the last check [-] (with the '
                                  'prefilter, the contacts not read are proven below 1)'),
        'prefilterActive': (False, 'whether the last check used the prefilter'),
        'prefilterNote': ('', 'why the prefilter is off, if it is'),
        'nCandidates': (0, 'grains whose bound exceeded the strength at the last check (their contacts were read)'),
        'contactsRead': (0, 'contacts read from YADE so far, over all checks'),
        'nVerified': (0, 'full checks that confirmed the bound'),
    }

    def __init__(self, **kw):
        BallastEngine.__init__(self, **kw)
        self.__dict__['_prefilter'] = Prefilter()

    def _summary(self):
        return 'nAbraded=%d volumeLost=%.4g m^3 massLost=%.4g kg' % (self.nAbraded, self.volumeLost, self.massLost)

    def _check(self, tab, ids, radii):
        if len(ids) == 0:
            return False
        prefilter = self.__dict__['_prefilter']
        (id1, id2, Fn, uN), bound = prefilter.contacts(self, tab, ids, radii)
        self.__dict__['contactsRead'] += len(id1)
        # eq. 7 per abrasion unit, the sphere that wears: a sphere grain itself, a clump's member (the kind's)
        units, unitRadii, unitGrain = tab.kind.abrasionUnits(ids, radii, tab.radiusById)
        index = np.full(len(tab.radiusById), -1, dtype=np.int64)
        index[units] = np.arange(len(units))
        own1, own2 = tab.kind.unitOf(id1), tab.kind.unitOf(id2)  # a contact's body -> its unit
        p0, abrade = _ballast.abrasionCheck(unitRadii, index[own1], index[own2], Fn, tab.radiusById[id1],
                                            tab.radiusById[id2], uN, self.strength, self.rMin)
        self.__dict__['maxPressureRatio'] = float(np.max(p0) / self.strength)
        if bound is not None:
            prefilter.verify(self, ids, p0, Fn, bound)
        hit = np.flatnonzero(abrade)
        if len(hit) == 0:
            return False
        pw0 = self._dtBefore()
        g = self.gamma
        d = self.__dict__
        for k in hit:
            uid, bid = int(units[k]), int(unitGrain[k])
            pos = Vector3(O.bodies[uid].state.pos)
            rs = abradeUnit(tab, uid, bid, g)
            d['nAbraded'] += 1
            # a grain scaled whole loses V (1 - gamma^3); a worn clump member, V - V' (the kind's)
            d['volumeLost'] += (rs.volumeBefore * (1 - g ** 3) if rs.volumeAfter is None
                                else rs.volumeBefore - rs.volumeAfter)
            d['massLost'] += rs.massBefore - rs.massAfter
            self._event('abrasion', bid, pos, rs.radiusBefore, float(p0[k]), self.strength, [])
            if uid != bid:
                d['_events'][-1]['member'] = uid
        tab.commit()
        self._adjustDt(pw0, np.array(list(dict.fromkeys(unitGrain[hit].tolist())), dtype=np.int64))
        return True


docstring(BallastAbrasionEngine, 'Abrasion, section 3 (eqs. 6-7).')
