"""The abrasion prefilter (docs/engines.md): read from YADE only the contacts of grains whose bound on
the Hertz pressure p0 of eq. 7 exceeds the strength; same decisions as reading every contact.
Hertz-Mindlin contacts: a fabric-stress bound per grain (``ballast.abrasionBound``) and one from the
largest overlap ratio (``ballast.sphereContactBound``); linear contacts (FrictPhys): eq. 7 is
3 kn / (2 pi R), a constant (``harvest.linearBound``). Every verifyPeriod-th check reads all contacts
and checks the bound; a broken bound switches the prefilter off for the rest of the run. The bounds take
a grain's contacts at its own radius: they hold for a kind whose grain is one sphere
(``GrainKind.oneSphere``); for another kind the prefilter stays off."""
import numpy as np
from yade import O, utils

from .. import _ballast, harvest

BROKEN = 'bound broken'  # start of the engine's prefilterNote once a full read broke the bound


class Prefilter:
    def __init__(self):
        self.law = self.lawNote = self.moduli = None   # looked up again at every verification only

    def contacts(self, eng, tab, ids, radii):
        """(id1, id2, Fn, uN) to evaluate, and the bound of each grain when all contacts were read to verify
        it (else None). Writes the engine's outputs nCandidates, prefilterActive, prefilterNote."""
        d = eng.__dict__
        d['nCandidates'], d['prefilterActive'] = len(ids), False
        if not eng.prefilter:
            d['prefilterNote'] = ''
            return harvest.contacts(), None
        verify = d['nVerified'] == 0 or eng.nChecks % eng.verifyPeriod == 0
        if not tab.kind.oneSphere:
            d['prefilterNote'] = 'grain kind %r: the bounds hold for grains of one sphere only' % tab.kind.name
            return harvest.contacts(), None
        if verify or self.law is None:
            self.law, why = harvest.contactLaw()
            self.lawNote = why or ''
            self.moduli = {'hertz': harvest.moduli, 'linear': harvest.linearBound}[self.law](tab) if self.law else None
        if self.law is None:
            d['prefilterNote'] = self.lawNote
            return harvest.contacts(), None
        if d['prefilterNote'].startswith(BROKEN):  # the note is saved with the engine: it stays off after O.load
            return harvest.contacts(), None
        d['prefilterNote'] = ''
        if self.law == 'linear':
            bound = np.full(len(ids), self.moduli)
        else:
            Ess, Esw = self.moduli
            gss = _ballast.sphereContactBound(utils.maxOverlapRatio(), Ess) if Ess > 0 else 0.0
            bound = (_ballast.abrasionBound(harvest.stresses(ids), radii, 0.0, Esw) if Esw > 0 else np.zeros(len(ids)))
            bound = np.maximum(bound, gss)
        cand = np.flatnonzero((bound > eng.strength) & (radii >= eng.rMin))
        d['prefilterActive'], d['nCandidates'] = True, len(cand)
        if verify:
            return harvest.contacts(), bound
        if len(cand) > eng.maxCandidates * len(ids):
            return harvest.contacts(), None
        return harvest.contactsOf(ids[cand]), None

    @staticmethod
    def verify(eng, ids, p0, Fn, bound):
        """After a full read: eq. 7 of every grain against its bound; a violation switches the prefilter off."""
        d = eng.__dict__
        bad = np.flatnonzero(p0 > bound * (1 + 1e-9))
        if len(bad):
            k = bad[np.argmax(p0[bad] / np.maximum(bound[bad], 1e-300))]
            d['prefilterActive'] = False
            d['prefilterNote'] = ('%s at iter %d: grain %d has p0 = %.4g Pa above its bound %.4g Pa; the prefilter '
                                  'is off from now on' % (BROKEN, O.iter, ids[k], p0[k], bound[k]))
            print('BallastAbrasionEngine: ' + d['prefilterNote'])
        elif np.any(Fn > 0):
            d['nVerified'] += 1
