"""YADE engines of the crushable-ballast model (Dubina & Eliáš, sections 2 and 3).

Both engines are Python subclasses of YADE's ``PyRunner``, a C++ ``PeriodicEngine``: they sit in
``O.engines`` (after ``NewtonIntegrator``) and ``iterPeriod``, ``virtPeriod`` (the paper's crushing
period T_c), ``realPeriod``, ``nDo``, ``initRun``, ``dead`` and ``label`` behave as for any YADE
engine. At each check the engine harvests the scene (see :mod:`ballast.harvest`), decides for all
grains at once in C++ (``ballast.crushCheck`` / ``ballast.abrasionCheck``) and applies the result.

Persistence: ``O.save()`` keeps only PyRunner's own fields. Each engine therefore keeps its
parameters and outputs as JSON in ``O.tags['ballast.<key>']`` (written when they or the events
change), its events in ``O.tags['ballast.<key>.events']`` and the outputs that change at every
check in ``O.tags['ballast.<key>.checks']`` (a short tuple, written at every check); its
``command`` names that key.
After ``O.load()`` the engine is a plain PyRunner until it fires: then, or at once when you call
:func:`restore`, it is replaced by a full engine with the saved parameters, counters and events,
and its label points to it again.
"""
import ast
import base64
import builtins
import json
import time
import uuid

import numpy as np
from yade import O, utils
from yade import Vector3
from yade.wrapper import PyRunner

from . import _ballast, contacts, energy, harvest
from .geometry import sphereVolume
from .params import ABRASION, CRUSH, PERIODIC, ParamError, docTable, validate, validateAll

# PyRunner's (PeriodicEngine's) own settings are checked as parameters (params.PERIODIC); its counters
# are set only when an engine is restored
_PERIODS = ('iterPeriod', 'virtPeriod', 'realPeriod')
_PERIODIC_STATE = ('iterLast', 'virtLast', 'realLast', 'nDone')
_TAG = 'ballast.'
_COMMAND = "import ballast.engines as _be; _be._fire(%r)"

_ENERGY_AFTER_STEPS = 10  # energyAfter: the first check at least this many steps after a replacement ("a few steps")
_BROKEN = 'bound broken'  # start of prefilterNote once a full read broke the prefilter's bound
_live = {}      # key -> engine instance created in this process
_classes = {}   # class name -> class, for restoring


def _requireAPeriod(owner, periods):
    """A PeriodicEngine whose periods are all 0 never runs: refuse it."""
    if not any(v > 0 for v in periods.values()):
        raise ParamError('iterPeriod', '%s: %s is not allowed: the engine would never check; give iterPeriod >= 1, '
                         'virtPeriod > 0 [s] or realPeriod > 0 [s]' % (owner, ', '.join(
                             '%s = %r' % kv for kv in periods.items())))


def _resizeGrain(tab, bid, factor):
    """Radius x factor for every radius change the engines make: mass (factor^3), inertia (factor^5) and the
    grain's refR (utils.growParticle; bodyStressTensors reads refR), then its contacts as YADE would create
    them at the new radius (ballast.contacts), and the grain table. Returns (old radius, mass before, after)."""
    b = O.bodies[bid]
    r, mass = b.shape.radius, b.state.mass
    utils.growParticle(bid, factor, True)
    contacts.resize(bid, r, factor * r)
    tab.resized(bid, factor * r)
    return r, mass, b.state.mass


class _BallastEngine(PyRunner):
    _params = {}
    _outputs = {}   # name -> (initial value, doc); updated at run time

    def __init__(self, **kw):
        name = type(self).__name__
        key = kw.pop('_key', None) or uuid.uuid4().hex[:12]
        if 'command' in kw:
            raise TypeError('%s: command is set by the engine itself and cannot be given' % name)
        periodic = {k: validate(name, PERIODIC, k, kw.pop(k)) for k in list(kw) if k in PERIODIC}
        unknown = sorted(k for k in kw if k not in self._params)
        if unknown:
            raise TypeError('%s: unknown parameter(s) %s; parameters: %s; periodic settings: %s'
                            % (name, ', '.join(unknown), ', '.join(self._params), ', '.join(PERIODIC)))
        if not any(k in periodic for k in _PERIODS):
            periodic['iterPeriod'] = 1  # no period given: a check every step (the paper's T_c = 0)
        _requireAPeriod(name, {k: periodic.get(k, 0) for k in _PERIODS})
        values = validateAll(name, self._params, kw)
        PyRunner.__init__(self, command=_COMMAND % key, **periodic)
        self.__dict__.update(values)
        self.__dict__['_key'] = key
        for k, (v, _) in self._outputs.items():
            self.__dict__['_events' if k == 'events' else k] = list(v) if isinstance(v, list) else v
        self.__dict__['_counter'] = 0
        _live[key] = self
        self._save()

    @property
    def events(self):
        """The events so far (a copy: outputs are changed by the engine only)."""
        return [{k: list(v) if isinstance(v, list) else v for k, v in e.items()} for e in self.__dict__['_events']]

    def __setattr__(self, name, value):
        owner = type(self).__name__
        if name in self._params:
            self.__dict__[name] = validate(owner, self._params, name, value)
            self._save()
        elif name == 'command' and '_key' in self.__dict__:
            raise AttributeError('%s: command is set by the engine itself' % owner)
        elif name in self._outputs:
            raise AttributeError('%s: %s is an output, updated at run time' % (owner, name))
        elif name in PERIODIC:
            value = validate(owner, PERIODIC, name, value)
            if name in _PERIODS:
                _requireAPeriod(owner, dict({k: getattr(self, k) for k in _PERIODS}, **{name: value}))
            PyRunner.__setattr__(self, name, value)
        elif name in _PERIODIC_STATE:
            PyRunner.__setattr__(self, name, value)
        else:
            raise AttributeError('%s: no attribute %r to set; parameters: %s; periodic settings: %s'
                                 % (owner, name, ', '.join(self._params), ', '.join(PERIODIC)))

    # ---------------------------------------------------------------- state
    def state(self):
        """Parameters and outputs as a JSON-able dict (what O.save keeps in O.tags)."""
        s = {'class': type(self).__name__, 'key': self._key, 'counter': self._counter}
        s['params'] = {k: self.__dict__[k] for k in self._params}
        s['outputs'] = {k: self.__dict__['_events' if k == 'events' else k] for k in self._outputs}
        return s

    def _save(self, events=True):
        """State to O.tags: parameters and scalar outputs, and the events when they changed."""
        s = self.state()
        ev = s['outputs'].pop('events')
        if events:
            O.tags[_TAG + self._key + '.events'] = json.dumps(ev)
        O.tags[_TAG + self._key] = json.dumps(s)
        self._saveChecks()

    def _saveChecks(self):
        """The outputs that change at every check (a short repr, not the whole state in JSON)."""
        O.tags[_TAG + self._key + '.checks'] = repr(tuple(self.__dict__[k] for k in self._perCheck))

    def eventsArray(self):
        """events as a NumPy structured array (t, iter, id, x, y, z, radius, value, strength, nNew)."""
        dt = [('t', float), ('iter', np.int64), ('id', np.int64), ('x', float), ('y', float), ('z', float),
              ('radius', float), ('value', float), ('strength', float), ('nNew', np.int64)]
        return np.array([(e['t'], e['iter'], e['id'], *e['pos'], e['radius'], e['value'], e['strength'],
                          len(e['newIds'])) for e in self.__dict__['_events']], dtype=dt)

    def __str__(self):
        p = ', '.join('%s=%r' % (k, self.__dict__[k]) for k in self._params)
        return '<%s %s label=%r %s>' % (type(self).__name__, p, self.label, self._summary())

    __repr__ = __str__

    # ---------------------------------------------------------------- running
    def _fire(self):
        t0 = time.perf_counter()
        tab = harvest.grains()
        sel = tab.select(self.mask)
        changed = self._check(tab, tab.ids[sel], tab.radii[sel])
        d = self.__dict__
        d['nChecks'] += 1
        t1 = time.perf_counter()
        d['checkSeconds'] += t1 - t0
        if changed:
            self._save()
        else:
            self._saveChecks()

    def _event(self, kind, bid, pos, r, value, strength, newIds):
        self.__dict__['_events'].append({'kind': kind, 't': O.time, 'iter': O.iter, 'id': bid, 'pos': [pos[0], pos[1], pos[2]],
                            'radius': r, 'value': value, 'strength': strength, 'newIds': newIds})

    def _adjustDt(self, pw0):
        """Eq. 5: the critical step scales with the smallest radius; keep O.dt's safety margin."""
        if pw0 is None:
            return
        pw1 = utils.PWaveTimeStep()
        if 0 < pw1 < pw0:
            O.dt = O.dt * pw1 / pw0

    def _dtBefore(self):
        return utils.PWaveTimeStep() if self.adjustDt and not O.dynDt else None


class BallastCrushEngine(_BallastEngine):
    _params = CRUSH
    _outputs = {
        'nCrushed': (0, 'grains crushed so far'),
        'volumeLost': (0.0, 'grain volume lost by crushing [m^3]'),
        'massLost': (0.0, 'grain mass lost by crushing [kg]'),
        'events': ([], 'one dict per crushed grain: kind, t [s], iter, id, pos [m], radius [m], value (sigma_e [Pa]), '
                       'strength (f_t [Pa]; f_t (1 - D) with fatigue), newIds; energyBefore, energyAfter (the first '
                       'check at least %d steps after) and with keep=volume energyGrown: [kinetic, elastic] [J] of '
                       'the grain or its fragments, its neighbours before the crush and those of the fragments '
                       '(ballast.energy)' % _ENERGY_AFTER_STEPS),
        'nChecks': (0, 'checks run so far'),
        'checkSeconds': (0.0, 'wall time spent in checks, before the state is written to O.tags [s]'),
        'maxStressRatio': (0.0, 'largest sigma_e / f_t over the grains at the last check [-]'),
        'maxCrushableRatio': (0.0, 'largest sigma_e / f_t over the grains that can crush (r >= rMin) at the last '
                                   'check, 0 if none [-] (fragments below rMin may be far above their f_t)'),
        'nFatigueCrushed': (0, 'grains crushed below their undamaged strength (sigma_e <= f_t), by fatigue damage'),
        'maxDamage': (0.0, 'largest fatigue damage D over the grains at the last check [-]'),
    }

    _perCheck = ('nChecks', 'checkSeconds', 'maxStressRatio', 'maxCrushableRatio', 'maxDamage')  # outputs that change at every check
    FRESH = (0.0, 0.0, 1.0, 0.0)  # fatigue state of a new grain: damage, extreme, rising, peaks

    def fatigueState(self, ids=None):
        """Fatigue state by body id, an (n,4) array: damage D [-], running extreme of s [-], rising (1/0),
        damaging peaks; rows of ids (default: every id up to the largest seen)."""
        F = self.__dict__.get('_fatigue')
        if F is None:
            F = np.empty((0, 4))
        if ids is None:
            return F.copy()
        ids = np.asarray(ids, dtype=np.int64)
        out = np.tile(self.FRESH, (len(ids), 1))
        known = ids < len(F)
        out[known] = F[ids[known]]
        return out

    def _fatigueRows(self, ids):
        """The state array, grown to hold every id (new rows fresh)."""
        d = self.__dict__
        F = d.get('_fatigue')
        need = int(np.max(ids)) + 1 if len(ids) else 0
        if F is None or len(F) < need:
            G = np.tile(self.FRESH, (max(need, 2 * (0 if F is None else len(F))), 1))
            if F is not None:
                G[:len(F)] = F
            d['_fatigue'] = F = G
        return F

    def _saveChecks(self):
        _BallastEngine._saveChecks(self)
        d = self.__dict__
        if d.get('_growing') or d.get('_pending') or (_TAG + self._key + '.internal') in O.tags.keys():
            O.tags[_TAG + self._key + '.internal'] = json.dumps({'growing': d.get('_growing', []),
                                                                'pending': d.get('_pending', [])})
        F = self.__dict__.get('_fatigue')
        if F is not None:  # bitwise: base64 of the float64 array
            O.tags[_TAG + self._key + '.fatigue'] = base64.b64encode(np.ascontiguousarray(F).tobytes()).decode('ascii')

    def _summary(self):
        return 'nCrushed=%d volumeLost=%.4g m^3 massLost=%.4g kg' % (self.nCrushed, self.volumeLost, self.massLost)

    def strengthFactors(self, ids):
        """Each grain's Weibull strength factor w (docs/strength.md): a function of (seed, body id, modulus),
        so the same after O.save/O.load and drawn afresh for fragments (new ids); None without scatter."""
        if self.weibullModulus == 0:
            return None
        return _ballast.weibullFactors(self.seed, np.asarray(ids, dtype=np.int64), self.weibullModulus)

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
            F = self._fatigueRows(ids)
            F[ids], crush = _ballast.fatigueCheck(ratio, radii, F[ids], self.fatigueExponent, self.fatigueEndurance,
                                                  self.fatigueHysteresis, self.rMin)
            strength = ft * (1 - F[ids, 0])
            d['maxDamage'] = float(np.max(F[ids, 0]))
        changed = self._recordEnergies()
        hit = np.flatnonzero(crush)
        if 0 < self.maxPerCheck < len(hit):  # sequential crushing: the most overloaded first
            hit = hit[np.argsort(-(se[hit] / strength[hit]), kind='stable')[:self.maxPerCheck]]
        if len(hit):
            pw0 = self._dtBefore()
            for k in hit:
                if se[k] <= ft[k]:
                    d['nFatigueCrushed'] += 1
                newIds = self._replace(tab, int(ids[k]), float(radii[k]), float(se[k]), float(strength[k]))
                if self.fatigue:  # fragments start undamaged (docs/fatigue.md)
                    self._fatigueRows(np.asarray(newIds))[newIds] = self.FRESH
            tab.commit()
            self._adjustDt(pw0)
            changed = True
        return self._grow(tab) or changed

    # ---------------------------------------------------------------- after a replacement (issue 13)
    def _recordEnergies(self):
        """Energy of the fragments, the parent's neighbours and the fragments' own neighbours a few steps after
        a replacement (energyAfter) and after its growth ended (energyGrown). The parent's neighbours are
        kept because the fragments, inside the parent, often touch none of them at first: the energy of
        the same bodies before and after is what the replacement destroys or injects."""
        d = self.__dict__
        pending = d.get('_pending')
        if not pending:
            return False
        due = [p for p in pending if O.iter >= p['due']]
        for p in due:
            d['_events'][p['event']][p['key']] = energy.snapshot(p['ids'], p['neighbours'])
        d['_pending'] = [p for p in pending if O.iter < p['due']]
        return bool(due)

    def _grow(self, tab):
        """keep='volume': every growing replacement's fragments towards the parent's volume, by the share of
        growTime elapsed. The cluster of fragments is scaled about its centre of mass by a factor per check
        (radii and distances alike), so fragments never overlap each other; the neighbours are pushed
        out gradually. The contacts follow (ballast.contacts)."""
        d = self.__dict__
        growing = d.get('_growing')
        if not growing:
            return False
        still = []
        for g in growing:
            frac = 1.0 if self.growTime <= 0 else min(1.0, (O.time - g['t0']) / self.growTime)
            want = g['ratio'] ** frac                  # fragments' volume over their volume when placed
            f = (want / g['grown']) ** (1.0 / 3.0)
            alive = [O.bodies[i] for i in g['ids'] if O.bodies[i] is not None]  # crushed ones: their fragments grow
            if alive:
                mass = sum(b.state.mass for b in alive)
                centre = sum((b.state.pos * b.state.mass for b in alive), Vector3(0, 0, 0)) / mass
            for b in alive:
                b.state.pos = centre + (b.state.pos - centre) * f
                r, mass, newMass = _resizeGrain(tab, b.id, f)  # the density stays: mass x f^3
                d['volumeLost'] -= sphereVolume(r) * (f ** 3 - 1)
                d['massLost'] -= newMass - mass
            g['grown'] = want
            if frac < 1:
                still.append(g)
            else:
                d.setdefault('_pending', []).append({'event': g['event'], 'key': 'energyGrown', 'due': O.iter,
                                                     'ids': g['ids'], 'neighbours': g.get('neighbours', [])})
        d['_growing'] = still
        tab.commit()
        return True

    def _replace(self, tab, bid, r, se, ft):
        """Section 2: the grain is erased and replaced by fragments inside it (Fig. 1)."""
        b = O.bodies[bid]
        st, mat, color, mask = b.state, b.material, b.shape.color, b.groupMask
        pos, vel, angVel, mass = Vector3(st.pos), Vector3(st.vel), Vector3(st.angVel), st.mass
        neighbours = energy.partners([bid])
        before = energy.snapshot([bid])  # kinetic and elastic energy of the grain and its neighbours
        frags = _ballast.placeFragments(self.pattern, (pos[0], pos[1], pos[2]), r, self.seed, self._counter)
        self.__dict__['_counter'] += 1
        O.bodies.erase(bid)
        bodies = [utils.sphere(Vector3(x, y, z), rf, material=mat, color=color, mask=mask) for x, y, z, rf in frags]
        if self.keep == 'mass':  # denser fragments: the parent's mass; its momentum then too (centroid at its centre)
            scale = mass / sum(nb.state.mass for nb in bodies)
            for nb in bodies:
                nb.state.mass *= scale
                nb.state.inertia = nb.state.inertia * scale
        newIds, newMass = [], 0.0
        for nb in bodies:
            # rigid-body velocity of the parent at the fragment's centre: momentum kept with the mass kept
            nb.state.vel = vel + angVel.cross(nb.state.pos - pos)
            nb.state.angVel = angVel
            newMass += nb.state.mass
            newIds.append(O.bodies.append(nb))
        tab.replaced(bid, newIds, frags[:, 3], mask)
        d = self.__dict__
        d['nCrushed'] += 1
        d['volumeLost'] += sphereVolume(r) - float(np.sum(sphereVolume(frags[:, 3])))
        d['massLost'] += mass - newMass
        self._event('crush', bid, pos, r, se, ft, newIds)
        k = len(d['_events']) - 1
        d['_events'][k]['energyBefore'] = before
        d.setdefault('_pending', []).append({'event': k, 'key': 'energyAfter', 'ids': newIds, 'neighbours': neighbours,
                                             'due': O.iter + _ENERGY_AFTER_STEPS})
        if self.keep == 'volume':
            d.setdefault('_growing', []).append({'ids': newIds, 'neighbours': neighbours, 't0': O.time, 'event': k,
                                                 'grown': 1.0,
                                                 'ratio': r ** 3 / float(np.sum(frags[:, 3] ** 3))})
        return newIds


class BallastAbrasionEngine(_BallastEngine):
    _params = ABRASION
    _outputs = {
        'nAbraded': (0, 'abrasion events so far'),
        'volumeLost': (0.0, 'grain volume lost by abrasion [m^3]'),
        'massLost': (0.0, 'grain mass lost by abrasion [kg]'),
        'events': ([], 'one dict per abrasion: kind, t [s], iter, id, pos [m], radius before [m], value (p0 [Pa]), '
                       'strength [Pa], newIds (empty)'),
        'nChecks': (0, 'checks run so far'),
        'checkSeconds': (0.0, 'wall time spent in checks, before the state is written to O.tags [s]'),
        'maxPressureRatio': (0.0, 'largest p0 / strength over the contacts read at the last check [-] (with the '
                                  'prefilter, the contacts not read are proven below 1)'),
        'prefilterActive': (False, 'whether the last check used the prefilter'),
        'prefilterNote': ('', 'why the prefilter is off, if it is'),
        'nCandidates': (0, 'grains whose bound exceeded the strength at the last check (their contacts were read)'),
        'contactsRead': (0, 'contacts read from YADE so far, over all checks'),
        'nVerified': (0, 'full checks that confirmed the bound'),
    }

    _perCheck = ('nChecks', 'checkSeconds', 'maxPressureRatio', 'prefilterActive', 'prefilterNote', 'nCandidates',
                 'contactsRead', 'nVerified')

    def _summary(self):
        return 'nAbraded=%d volumeLost=%.4g m^3 massLost=%.4g kg' % (self.nAbraded, self.volumeLost, self.massLost)

    def _contacts(self, tab, ids, radii):
        """Contacts to evaluate: all, or with the prefilter only those of grains that may abrade, by
        bounds on eq. 7. Hertz contacts: sphere-sphere contacts from YADE's largest overlap ratio (C++),
        wall and facet contacts from each grain's fabric stress. Linear contacts: eq. 7 does not depend
        on the load (harvest.linearBound), one bound for all. Returns (id1, id2, Fn, uN) and, when all
        contacts were read to verify the bounds, the bound of each grain (else None)."""
        d = self.__dict__
        d['nCandidates'], d['prefilterActive'] = len(ids), False
        if not self.prefilter:
            d['prefilterNote'] = ''
            return harvest.contacts(), None
        verify = d['nVerified'] == 0 or self.nChecks % self.verifyPeriod == 0
        if verify or d.get('_law') is None:
            # the contact law and the moduli are looked up again at every verification only
            d['_law'], why = harvest.contactLaw()
            d['_lawNote'] = why or ''
            d['_moduli'] = {'hertz': harvest.moduli, 'linear': harvest.linearBound}[d['_law']](tab) if d['_law'] else None
        if d['_law'] is None:
            d['prefilterNote'] = d['_lawNote']
            return harvest.contacts(), None
        if d['prefilterNote'].startswith(_BROKEN):  # the note is saved with the engine: it stays off after O.load
            return harvest.contacts(), None
        d['prefilterNote'] = ''
        if d['_law'] == 'linear':
            bound = np.full(len(ids), d['_moduli'])
        else:
            Ess, Esw = d['_moduli']
            gss = _ballast.sphereContactBound(utils.maxOverlapRatio(), Ess) if Ess > 0 else 0.0
            bound = (_ballast.abrasionBound(harvest.stresses(ids), radii, 0.0, Esw) if Esw > 0 else np.zeros(len(ids)))
            bound = np.maximum(bound, gss)
        cand = np.flatnonzero((bound > self.strength) & (radii >= self.rMin))
        d['prefilterActive'], d['nCandidates'] = True, len(cand)
        if verify:
            return harvest.contacts(), bound
        if len(cand) > self.maxCandidates * len(ids):
            return harvest.contacts(), None
        return harvest.contactsOf(ids[cand]), None

    def _verify(self, ids, p0, Fn, bound):
        """After a full read: eq. 7 of every grain against its bound; a violation switches the
        prefilter off for the rest of the run."""
        d = self.__dict__
        bad = np.flatnonzero(p0 > bound * (1 + 1e-9))
        if len(bad):
            k = bad[np.argmax(p0[bad] / np.maximum(bound[bad], 1e-300))]
            d['prefilterActive'] = False
            d['prefilterNote'] = ('%s at iter %d: grain %d has p0 = %.4g Pa above its bound %.4g Pa; the prefilter '
                                  'is off from now on' % (_BROKEN, O.iter, ids[k], p0[k], bound[k]))
            print('BallastAbrasionEngine: ' + d['prefilterNote'])
        elif np.any(Fn > 0):
            d['nVerified'] += 1

    def _check(self, tab, ids, radii):
        if len(ids) == 0:
            return False
        (id1, id2, Fn, uN), bound = self._contacts(tab, ids, radii)
        self.__dict__['contactsRead'] += len(id1)
        index = np.full(len(tab.radiusById), -1, dtype=np.int64)
        index[ids] = np.arange(len(ids))
        p0, abrade = _ballast.abrasionCheck(radii, index[id1], index[id2], Fn, tab.radiusById[id1],
                                            tab.radiusById[id2], uN, self.strength, self.rMin)
        self.__dict__['maxPressureRatio'] = float(np.max(p0) / self.strength)
        if bound is not None:
            self._verify(ids, p0, Fn, bound)
        hit = np.flatnonzero(abrade)
        if len(hit) == 0:
            return False
        pw0 = self._dtBefore()
        g = self.gamma
        for k in hit:
            bid = int(ids[k])
            pos = Vector3(O.bodies[bid].state.pos)
            r, mass, newMass = _resizeGrain(tab, bid, g)
            d = self.__dict__
            d['nAbraded'] += 1
            d['volumeLost'] += sphereVolume(r) * (1 - g ** 3)
            d['massLost'] += mass - newMass
            self._event('abrasion', bid, pos, r, float(p0[k]), self.strength, [])
        tab.commit()
        self._adjustDt(pw0)
        return True


for _c in (BallastCrushEngine, BallastAbrasionEngine):
    _classes[_c.__name__] = _c
    _c.__doc__ = ('%s: see the module doc.\n\nParameters (validated when built and when set):\n%s\n\n'
                  'Outputs (updated at run time):\n%s' % (
                      _c.__name__, docTable(_c._params),
                      '\n'.join('    %s: %s' % (k, d) for k, (v, d) in _c._outputs.items())))
BallastCrushEngine.__doc__ = 'Bulk crushing, section 2 (eqs. 1-4, Fig. 1).\n\n' + BallastCrushEngine.__doc__
BallastAbrasionEngine.__doc__ = 'Abrasion, section 3 (eqs. 6-7).\n\n' + BallastAbrasionEngine.__doc__


# ---------------------------------------------------------------- dispatch and persistence
def _inEngines(eng):
    return any(e is eng for e in O.engines)


def _fire(key):
    """Called by the engine's command. Restores a loaded engine first if needed."""
    eng = _live.get(key)
    if eng is None or not _inEngines(eng):
        eng = _restoreKey(key)
    eng._fire()


def _restoreKey(key):
    tag = _TAG + key
    if tag not in O.tags.keys():
        raise RuntimeError("ballast: the engine with key %r has no saved state (O.tags[%r] is missing), so it "
                           "cannot be restored; rebuild it with BallastCrushEngine(...) or BallastAbrasionEngine(...) "
                           "and put it in O.engines" % (key, tag))
    s = json.loads(O.tags[tag])
    keys = O.tags.keys()
    s['outputs']['events'] = json.loads(O.tags[tag + '.events']) if (tag + '.events') in keys else []
    if (tag + '.checks') in keys:  # the per-check outputs, newer than the state
        s['outputs'].update(zip(_classes[s['class']]._perCheck, ast.literal_eval(O.tags[tag + '.checks'])))
    engines = list(O.engines)
    pos = [i for i, e in enumerate(engines) if isinstance(e, PyRunner) and e.command == _COMMAND % key]
    if not pos:
        raise RuntimeError('ballast: no engine in O.engines runs the command of %r' % key)
    old = engines[pos[0]]
    periodic = {k: getattr(old, k) for k in PERIODIC}
    new = _classes[s['class']](_key=key, **dict(s['params'], **periodic))
    for k in _PERIODIC_STATE:
        setattr(new, k, getattr(old, k))
    s['outputs']['_events'] = s['outputs'].pop('events')
    new.__dict__.update(s['outputs'])
    internal = json.loads(O.tags[tag + '.internal']) if (tag + '.internal') in keys else {}
    new.__dict__['_growing'] = internal.get('growing', [])
    new.__dict__['_pending'] = [p if isinstance(p, dict) else  # states saved before the neighbours were kept
                                {'event': p[0], 'key': p[1], 'ids': s['outputs']['_events'][p[0]]['newIds'],
                                 'neighbours': [], 'due': 0} for p in internal.get('pending', [])]
    new.__dict__['_counter'] = s['counter']
    if (tag + '.fatigue') in keys:
        new.__dict__['_fatigue'] = np.frombuffer(base64.b64decode(O.tags[tag + '.fatigue']), dtype=float).reshape(-1, 4).copy()
    new._save()  # the constructor wrote an empty state over the loaded one
    engines[pos[0]] = new
    O.engines = engines
    if new.label:
        setattr(builtins, new.label, new)
    return new


def restore():
    """Re-attach every ballast engine of a loaded scene now (they also re-attach at their next check).
    Returns the restored engines."""
    out = []
    for e in list(O.engines):
        if type(e) is PyRunner and e.command.startswith(_COMMAND.split('%')[0]):
            key = e.command[len(_COMMAND.split('%')[0]):].strip("()'\"")
            out.append(_restoreKey(key))
    return out
