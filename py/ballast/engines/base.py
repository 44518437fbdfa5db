"""The base of the package's YADE engines: a Python subclass of YADE's ``PyRunner`` (a C++
``PeriodicEngine``) living in the scene through :mod:`ballast.runtime`.

``iterPeriod``, ``virtPeriod`` (the paper's crushing period T_c), ``realPeriod``, ``nDo``, ``initRun``,
``dead`` and ``label`` behave as for any YADE engine. At each check the engine harvests the scene
(:mod:`ballast.harvest`), decides for all grains at once in C++ and applies the result. Parameters
are declared once in :mod:`ballast.params` and checked when the engine is built and whenever one is
set; outputs are changed by the engine only. Its state (parameters, outputs, the components' own)
is saved by the runtime with the scene; after ``O.load()`` the runtime rebuilds it.
"""
import time

import numpy as np
from yade import O, utils
from yade.wrapper import PyRunner

from .. import harvest, runtime
from ..densityscaling import scaleDensities
from ..engineparams import PERIODIC
from ..params import ParamError, validate, validateAll

PERIODS = ('iterPeriod', 'virtPeriod', 'realPeriod')
PERIODIC_STATE = ('iterLast', 'virtLast', 'realLast', 'nDone')
TIMING = ('execTime', 'execCount')   # YADE's Engine timing, which yade.timing.reset() sets to 0


class Records(np.ndarray):
    """A NumPy structured array that prints as a table with its column names (a bare structured array prints its
    rows as tuples, the names nowhere); indexing, slicing and a['column'] are NumPy's."""

    def __repr__(self):
        import pandas as pd
        if self.dtype.names is None:   # a column taken out of it: a plain array
            return repr(self.view(np.ndarray))
        return pd.DataFrame(np.atleast_1d(self.view(np.ndarray))).to_string(max_rows=40)   # every column

    __str__ = __repr__


def requireAPeriod(owner, periods):
    """A PeriodicEngine whose periods are all 0 never runs: refuse it."""
    if not any(v > 0 for v in periods.values()):
        raise ParamError('iterPeriod', '%s: %s is not allowed: the engine would never check; give iterPeriod >= 1, '
                         'virtPeriod > 0 [s] or realPeriod > 0 [s]' % (owner, ', '.join(
                             '%s = %r' % kv for kv in periods.items())))


def resizeGrain(tab, bid, factor):
    """Grain bid scaled by factor [-] for every size change the engines make: by its kind (a sphere: radius,
    mass x factor^3, inertia x factor^5, refR, then its contacts as YADE would create them at the new radius),
    then the grain table. Returns the kind's Resized (r_eq [m] before and after, volume before [m^3], mass
    before and after [kg])."""
    rs = tab.kind.resize(bid, factor)
    tab.resized(bid, rs.radiusAfter)
    return rs


def abradeUnit(tab, unitId, grainId, factor):
    """Abrasion unit unitId of grain grainId abraded by factor [-] (section 3) by the kind (GrainKind.abrade: a
    sphere grain as resizeGrain; a clump's member worn, docs/grains.md), then the grain table: the grain's r_eq and
    the unit's own radius. Returns the kind's Resized."""
    rs = tab.kind.abrade(unitId, factor)
    if unitId == grainId:
        tab.resized(grainId, rs.radiusAfter)
    else:
        tab.resized(grainId, rs.radiusAfter, unitId, O.bodies[unitId].shape.radius)
    return rs


class BallastEngine(runtime.Runner):
    """Parameters `_params` ({name: Param}), outputs `_outputs` ({name: (initial value, doc)}); subclasses
    give `_check(tab, ids, radii)` -> whether the scene changed, and `_summary()`."""

    _params = {}
    _outputs = {}

    def __init__(self, **kw):
        name = type(self).__name__
        if 'command' in kw:
            raise TypeError('%s: command is set by the engine itself and cannot be given' % name)
        periodic = {k: validate(name, PERIODIC, k, kw.pop(k)) for k in list(kw) if k in PERIODIC}
        unknown = sorted(k for k in kw if k not in self._params)
        if unknown:
            raise TypeError('%s: unknown parameter(s) %s; parameters: %s; periodic settings: %s'
                            % (name, ', '.join(unknown), ', '.join(self._params), ', '.join(PERIODIC)))
        if not any(k in periodic for k in PERIODS):
            periodic['iterPeriod'] = 1  # no period given: a check every step (the paper's T_c = 0)
        requireAPeriod(name, {k: periodic.get(k, 0) for k in PERIODS})
        values = validateAll(name, self._params, kw)
        PyRunner.__init__(self, **periodic)
        self.__dict__.update(values)
        for k, (v, _) in self._outputs.items():
            self.__dict__['_events' if k == 'events' else k] = list(v) if isinstance(v, list) else v
        self.__dict__['_counter'] = 0
        PyRunner.__setattr__(self, 'command', runtime.command(self, 'fire'))

    @property
    def events(self):
        """The events so far (a copy: outputs are changed by the engine only)."""
        return [{k: list(v) if isinstance(v, list) else v for k, v in e.items()} for e in self.__dict__['_events']]

    def __setattr__(self, name, value):
        owner = type(self).__name__
        if name in self._params:
            self.__dict__[name] = validate(owner, self._params, name, value)
        elif name == 'command':
            raise AttributeError('%s: command is set by the engine itself' % owner)
        elif name in self._outputs:
            raise AttributeError('%s: %s is an output, updated at run time' % (owner, name))
        elif name in PERIODIC:
            value = validate(owner, PERIODIC, name, value)
            if name in PERIODS:
                requireAPeriod(owner, dict({k: getattr(self, k) for k in PERIODS}, **{name: value}))
            PyRunner.__setattr__(self, name, value)
        elif name in PERIODIC_STATE or name in TIMING:
            PyRunner.__setattr__(self, name, value)
        else:
            raise AttributeError('%s: no attribute %r to set; parameters: %s; periodic settings: %s'
                                 % (owner, name, ', '.join(self._params), ', '.join(PERIODIC)))

    # ---------------------------------------------------------------- state (ballast.runtime)
    def state(self):
        """Parameters, outputs and the components' state, JSON-able (what O.save keeps)."""
        d = self.__dict__
        s = {'class': type(self).__name__, 'counter': d['_counter'],
             'params': {k: d[k] for k in self._params},
             'outputs': {k: d['_events' if k == 'events' else k] for k in self._outputs}}
        s.update(self._componentState())
        return s

    def _componentState(self):
        return {}

    def _setComponentState(self, s):
        pass

    @classmethod
    def fromState(cls, s, ref):
        eng = cls(**s['params'])
        d = eng.__dict__
        out = dict(s['outputs'])
        d['_events'] = out.pop('events')
        d.update(out)
        d['_counter'] = s['counter']
        eng._setComponentState(s)
        return eng

    def eventsArray(self):
        """events as a NumPy structured array (t, iter, id, x, y, z, radius, value, strength, nNew), which prints as
        a table with its column names (:class:`Records`)."""
        dt = [('t', float), ('iter', np.int64), ('id', np.int64), ('x', float), ('y', float), ('z', float),
              ('radius', float), ('value', float), ('strength', float), ('nNew', np.int64)]
        return np.array([(e['t'], e['iter'], e['id'], *e['pos'], e['radius'], e['value'], e['strength'],
                          len(e['newIds'])) for e in self.__dict__['_events']], dtype=dt).view(Records)

    def __str__(self):
        p = ', '.join('%s=%r' % (k, self.__dict__[k]) for k in self._params)
        return '<%s %s label=%r %s>' % (type(self).__name__, p, self.label, self._summary())

    __repr__ = __str__

    # ---------------------------------------------------------------- running
    def fire(self):
        """One check (the runtime's call at every period)."""
        t0 = time.perf_counter()
        tab = harvest.grains()
        sel = tab.select(self.mask)
        self._check(tab, tab.ids[sel], tab.radii[sel])
        d = self.__dict__
        d['nChecks'] += 1
        d['checkSeconds'] += time.perf_counter() - t0

    def _event(self, kind, bid, pos, r, value, strength, newIds):
        self.__dict__['_events'].append({'kind': kind, 't': O.time, 'iter': O.iter, 'id': bid,
                                         'pos': [pos[0], pos[1], pos[2]], 'radius': r, 'value': value,
                                         'strength': strength, 'newIds': newIds})

    def _adjustDt(self, pw0, changed):
        """After grains changed (ids `changed`): with density scaling their densityScaling (their own P-wave
        step reaches scaledPWaveStep, O.dt stays); else eq. 5: the critical step scales with the smallest
        radius, so O.dt keeps its safety margin."""
        scaleDensities(changed, self.scaledPWaveStep)
        if pw0 is None:
            return
        pw1 = utils.PWaveTimeStep()
        if 0 < pw1 < pw0:
            O.dt = O.dt * pw1 / pw0

    def _dtBefore(self):
        # with a time stepper (O.dynDt) too: the scaled step holds until the stepper's next update, which
        # may be several steps after the replacement (GlobalStiffnessTimeStepper.timeStepUpdateInterval)
        return utils.PWaveTimeStep() if self.adjustDt and self.scaledPWaveStep == 0 else None


def docstring(cls, heading):
    """The class doc from its declarations: parameters with unit, range and default, and the outputs."""
    cls.__doc__ = ('%s\n\n%s: see ballast.engines.\n\nParameters (validated when built and when set):\n%s\n\n'
                   'Outputs (updated at run time):\n%s' % (
                       heading, cls.__name__, '\n'.join('    ' + p.docline(n) for n, p in cls._params.items()),
                       '\n'.join('    %s: %s' % (k, d) for k, (v, d) in cls._outputs.items())))
