"""Abrasion, section 3 of the paper (eqs. 6-7): a grain whose largest Hertz pressure p0 at a contact
(eq. 7) exceeds the strength loses a surface layer, its radius times gamma. The decision for all
contacts is the C++ core's (pkg/BallastAbrasionEngine.cpp); which contacts are read is the
prefilter's (:mod:`.prefilter`)."""
import numpy as np
from yade import O, Vector3

from .. import _ballast, runtime
from ..engineparams import ABRASION
from .base import BallastEngine, docstring, resizeGrain
from .prefilter import Prefilter


@runtime.persistent('BallastAbrasionEngine')
class BallastAbrasionEngine(BallastEngine):
    _params = ABRASION
    _outputs = {
        'nAbraded': (0, 'abrasion events so far'),
        'volumeLost': (0.0, 'grain volume lost by abrasion [m^3]'),
        'massLost': (0.0, 'grain mass lost by abrasion [kg]'),
        'events': ([], 'one dict per abrasion: kind, t [s], iter, id, pos [m], radius before [m], value (p0 [Pa]), '
                       'strength [Pa], newIds (empty)'),
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
        index = np.full(len(tab.radiusById), -1, dtype=np.int64)
        index[ids] = np.arange(len(ids))
        own1, own2 = tab.kind.grainOf(id1), tab.kind.grainOf(id2)  # a contact's body -> its grain
        p0, abrade = _ballast.abrasionCheck(radii, index[own1], index[own2], Fn, tab.radiusById[id1],
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
            bid = int(ids[k])
            pos = Vector3(O.bodies[bid].state.pos)
            rs = resizeGrain(tab, bid, g)
            d['nAbraded'] += 1
            d['volumeLost'] += rs.volumeBefore * (1 - g ** 3)
            d['massLost'] += rs.massBefore - rs.massAfter
            self._event('abrasion', bid, pos, rs.radiusBefore, float(p0[k]), self.strength, [])
        tab.commit()
        self._adjustDt(pw0, ids[hit])
        return True


docstring(BallastAbrasionEngine, 'Abrasion, section 3 (eqs. 6-7).')
