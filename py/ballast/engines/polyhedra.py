"""Crushing of polyhedron grains by YADE's own ``PolyhedraSplitter`` (Eliáš 2014; issue 47, item 4), with the package's
bookkeeping around it: the same outputs as :class:`BallastCrushEngine` (nCrushed, the ledger, events), so every
experiment reads a polyhedron scene as it reads the others.

The splitter's rule (YADE 2023.02a, pkg/dem/Polyhedra_splitter.cpp): a polyhedron of volume V whose tensor
sigma = (1/V) sum_c f (x) (x_c - x) has a von Mises stress (eq. 2, of its symmetric part) above
``strength / (r_eq / 1000)`` is cut by two planes through its centroid, normal to (n_max + n_min) and
(n_max - n_min) (n the principal directions of the largest and smallest principal values), into four pieces
(three new bodies; the original keeps its id and becomes one piece). With the material's ``strength`` = ft0 / 1000
(YADE reads r_eq in metres here although its comment says millimetres), that is the paper's eq. 4 with m = 1:
f_t = ft0 / r_eq. Its pieces are YADE's: each a convex polyhedron with mass density x its volume; a thin gap is left
between them (SPLITTER_GAP in YADE), whose volume is booked as lost.

How the two work together, in O.engines after NewtonIntegrator:

1. this engine (a PyRunner at the crushing period) computes every grain's stress as the splitter does (one pass
   over the contacts, :func:`ballast.grainkinds.polyhedron.stressSums`) and the paper's ratio sigma_e / f_t with the
   C++ core (``_ballast.crushCheck``, criterion vonMises, m = 1); where a grain above rMin is over its strength it
   wakes the splitter for this step;
2. the splitter (label ``polyhedraSplitter``, dead unless woken) splits, deciding by its own rule;
3. :meth:`PolyhedronCrushEngine.booked` (every step, nothing to do unless woken) finds what it split (the grains
   whose volume fell; the new bodies, three per split, in YADE's order), books events and the ledger, gives pieces
   below rMin a twin of the material that YADE will not split, scales O.dt as eq. 5 says and puts the splitter to
   sleep again.

rMin is the package's: YADE's splitter has no floor, so a grain below it gets the unsplittable twin. Weibull scatter,
other criteria, m != 1, fatigue, maxPerCheck and keep are not YADE's rule and are refused.
"""
import time

import numpy as np
from yade import O
from yade.wrapper import PolyhedraMat, PolyhedraSplitter

from .. import _ballast, grainkinds, harvest, runtime
from ..geometry import equivalentRadius
from ..grainkinds import polyhedron
from ..params import ParamError
from .base import docstring
from .crush import BallastCrushEngine

SPLITTER = 'polyhedraSplitter'   # the label of YADE's splitter in O.engines
# what YADE's rule is: a value of another crushing option would be lost, so the engine refuses it (the experiments
# refuse it earlier, naming the parameter)
FIXED = {'m': 1.0, 'criterion': 'vonMises', 'weibullModulus': 0.0, 'fatigue': False, 'maxPerCheck': 0, 'keep': 'none'}


def yadeStrength(ft0):
    """PolyhedraMat.strength [Pa km] for the size law ft0 / r_eq [Pa m]: YADE's strength / (r_eq / 1000), r_eq in m."""
    return ft0 / 1000.0


def unsplittable(material):
    """The twin of a PolyhedraMat that YADE's splitter leaves alone (IsSplitable off), appended to O.materials once and
    found again by its label."""
    label = material.label + '-whole'
    for m in O.materials:
        if m.label == label:
            return m
    twin = PolyhedraMat()   # attributes set one by one: the keyword constructor left young at 1e9 (measured)
    for k in ('young', 'poisson', 'frictionAngle', 'density', 'strength'):
        setattr(twin, k, getattr(material, k))
    twin.IsSplitable, twin.label = False, label
    O.materials.append(twin)
    return twin


def splitter(**period):
    """YADE's PolyhedraSplitter for this engine: every step when woken, dead otherwise."""
    return PolyhedraSplitter(iterPeriod=1, dead=True, label=SPLITTER, **period)


@runtime.persistent('PolyhedronCrushEngine')
class PolyhedronCrushEngine(BallastCrushEngine):
    """Bulk crushing of polyhedron grains by YADE's PolyhedraSplitter (see the module doc). Put it, then
    :func:`splitter`, then ``runtime.callback(engine, 'booked', iterPeriod=1)`` in O.engines (:meth:`engines`)."""

    def __init__(self, **kw):
        BallastCrushEngine.__init__(self, **kw)
        for k, v in FIXED.items():
            if getattr(self, k) != v:
                raise ParamError(k, 'PolyhedronCrushEngine: %s = %r is not YADE\'s PolyhedraSplitter rule (von Mises '
                                    'stress against ft0 / r_eq); only %r' % (k, getattr(self, k), v))
        # when woken: (body count, {grain: (value, strength, pos, r_eq, volume, mass)}, eq. 5's step before the split)
        self.__dict__['_pending'] = None

    def engines(self):
        """[this engine, YADE's splitter, the bookkeeping callback]: what goes into O.engines after Newton."""
        return [self, splitter(), runtime.callback(self, 'booked', iterPeriod=1, label='polyhedronBooking')]

    def _splitter(self):
        found = [e for e in O.engines if isinstance(e, PolyhedraSplitter) and e.label == SPLITTER]
        if not found:
            raise RuntimeError('PolyhedronCrushEngine: no PolyhedraSplitter labelled %r in O.engines; add '
                               'engine.engines() after NewtonIntegrator' % SPLITTER)
        return found[0]

    def fire(self):
        """One check: the splitter's stress of every grain in contact, the ratio to ft0 / r_eq; wake the splitter if a
        grain above rMin is over."""
        t0 = time.perf_counter()
        kind = grainkinds.current()
        d = self.__dict__
        n = len(O.bodies)
        S = polyhedron.stressSums(n)
        touched = np.flatnonzero(np.abs(S).reshape(n, 9).sum(axis=1) > 0)
        ids = np.array([i for i in touched.tolist() if kind.isGrain(O.bodies[i])], dtype=np.int64)
        if len(ids):
            V = kind.volumes(ids)
            r = equivalentRadius(V)
            se, ft, crush = _ballast.crushCheck(S[ids] / V[:, None, None], r, self.ft0, 1.0, self.rMin, 'vonMises')
            ratio = se / ft
            d['maxStressRatio'] = float(np.max(ratio))
            ok = r >= self.rMin
            d['maxCrushableRatio'] = float(np.max(ratio[ok])) if ok.any() else 0.0
            hit = np.flatnonzero(crush)
            if len(hit):
                due = {}
                for k in hit.tolist():
                    b = O.bodies[int(ids[k])]
                    due[int(ids[k])] = (float(se[k]), float(ft[k]), tuple(b.state.pos), float(r[k]), float(V[k]),
                                        b.state.mass)
                # eq. 5's step of the grains as they are, before the splitter cuts them (booked() scales O.dt by it)
                d['_pending'] = (n, due, self._dtBefore())
                self._splitter().dead = False
        d['nChecks'] += 1
        d['checkSeconds'] += time.perf_counter() - t0

    def booked(self):
        """After the splitter (every step; nothing unless it was woken): book its splits."""
        d = self.__dict__
        if d['_pending'] is None:
            return
        n0, due, pw0 = d['_pending']
        d['_pending'] = None
        self._splitter().dead = True
        new = list(range(n0, len(O.bodies)))
        if not new:
            return
        kind = grainkinds.current()
        parents = [i for i in sorted(due) if O.bodies[i] is not None
                   and kind.volumes([i])[0] < due[i][4] * (1 - 1e-12)]
        if len(new) != 3 * len(parents):   # YADE split a grain at the edge of its rule that this check did not see
            raise RuntimeError('PolyhedronCrushEngine: the splitter made %d bodies for %d grains over their strength '
                               '(three each expected)' % (len(new), len(parents)))
        store = polyhedron.splits(create=True)
        for j, pid in enumerate(parents):
            se, ft, pos, r, V, M = due[pid]
            pieces = [pid] + new[3 * j:3 * j + 3]   # YADE keeps one piece in the grain's body, appends three
            Vp = kind.volumes(pieces)
            for i, ri in zip(pieces, equivalentRadius(Vp).tolist()):
                if ri < self.rMin:
                    O.bodies[i].material = unsplittable(O.bodies[i].material)
            d['nCrushed'] += 1
            d['volumeLost'] += V - float(np.sum(Vp))   # the gap YADE leaves between the pieces
            d['massLost'] += M - sum(O.bodies[i].state.mass for i in pieces)
            self._event('crush', pid, pos, r, se, ft, pieces)
            store.splits += 1
        harvest.refresh()
        if pw0 is not None:
            pw1 = kind.pWaveTimeStep()
            if 0 < pw1 < pw0:
                O.dt = O.dt * pw1 / pw0

    def _dtBefore(self):
        return grainkinds.current().pWaveTimeStep() if self.adjustDt and self.scaledPWaveStep == 0 else None

    def floor(self):
        """Grains already below rMin get the unsplittable twin of their material (call once, before the first
        check)."""
        kind = grainkinds.current()
        ids = kind.ids()
        for i, r in zip(ids.tolist(), kind.radii(ids).tolist()):
            if r < self.rMin:
                O.bodies[i].material = unsplittable(O.bodies[i].material)

    def _componentState(self):
        return {}

    def _setComponentState(self, s):
        pass


docstring(PolyhedronCrushEngine, "Bulk crushing of polyhedra by YADE's PolyhedraSplitter (issue 47, item 4).")
