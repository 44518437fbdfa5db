"""The single-particle crushing test as an experiment on the base (docs/calibration.md): grains drawn
from the stated sizes, each squeezed between its own pair of steel platens (the bottom one fixed, the
top one closing at `speed`), until it first crushes under the crushing engine of the oedometer (any
criterion, strength option and pattern). Per grain: the force on its top platen and the platens'
displacement at the crush, F/d^2, the criterion's stress and the strength at the crush, and the
F-displacement curve; then the Weibull statistics (:mod:`.strengths`).

    from ballast.experiments.single_particle import SingleParticle
    test = SingleParticle(n=50, weibullModulus=3)
    test.run()                # prepare() and load(); writes strengths.csv, curves.csv, summary.json, figures

The grains stand in a row, a pitch of 1.5 dMax apart: their platens never meet and a grain never
touches another. With grain 'clump' each grain is a clump of volume-equivalent diameter d (a template of
:mod:`..clumpsample`) lying on its flat side, its short axis vertical and turned about it at random from the seed
(as a grain is laid between platens: turned at random, a clump touching each platen at one member rolls out
between frictionless platens), its platens at its lowest and highest points and wide enough for it, the pitch
1.5 times the largest clump's circumscribed diameter; d stays the grain's size in every output (F/d^2, the
strain). Once a grain has crushed its fragments and platens are removed, so the first crush is the only one.
Gravity is off (a grain's weight is 1e-5 of its crushing force).
"""
import math

import numpy as np
from yade import O, Vector3, utils
from yade.wrapper import (Bo1_Box_Aabb, Bo1_Sphere_Aabb, ForceResetter, Ig2_Box_Sphere_ScGeom,
                          Ig2_Sphere_Sphere_ScGeom, InsertionSortCollider, InteractionLoop, NewtonIntegrator)

from ... import grainkinds, runtime
from ...engines import BallastCrushEngine
from ..base import Experiment
from ..clumpsample import ClumpSample
from ..scene import AVOID, GRAIN_MASK, LAWS, STEEL_MASK, materials  # platens pair with grains only (AVOID)
from . import outputs
from .parameters import SingleParticleParameters

PITCH = 1.5            # [-] grains' centres this many dMax apart
PLATEN_HALF = 0.6      # [-] half-width of a square platen over the grain's diameter
PLATEN_THICKNESS = 0.01  # [m]
CURVE_EVERY = 10       # [steps] between rows of a grain's F-displacement curve


def lying(v, turn):
    """Vertices v ((n, 3) [m], a convex polyhedron about the origin) turned so that its largest face lies on z = 0 and
    the grain above it, then turned by turn [rad] about z through its centroid's vertical."""
    from scipy.spatial import ConvexHull
    hull = ConvexHull(v)
    a, b, c = (v[hull.simplices[:, i]] for i in range(3))
    area = np.linalg.norm(np.cross(b - a, c - a), axis=1)
    n = hull.equations[int(np.argmax(area)), :3]   # its outward normal: to -z
    R = rotationOnto(n, np.array([0.0, 0.0, -1.0]))
    w = v @ R.T
    cz, sz = math.cos(turn), math.sin(turn)
    w = w @ np.array([[cz, -sz, 0], [sz, cz, 0], [0, 0, 1]]).T
    return w - (0, 0, float(np.min(w[:, 2])))


def rotationOnto(a, b):
    """The rotation matrix taking the unit vector a onto the unit vector b (Rodrigues)."""
    k = np.cross(a, b)
    s, c = np.linalg.norm(k), float(np.dot(a, b))
    if s < 1e-12:
        return np.eye(3) if c > 0 else np.diag([1.0, -1.0, -1.0])
    k = k / s
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + s * K + (1 - c) * K @ K


def platen(x, z, reach, steel, up):
    """A fixed steel facet in the plane z [m] at (x, 0): an equilateral triangle whose inscribed circle, of radius
    1.5 reach [m], holds the grain's footprint; up: its face towards +z (the bottom platen)."""
    R = 3 * reach   # circumradius: twice the inscribed circle's radius
    pts = [Vector3(x + R * math.cos(t), R * math.sin(t), z) for t in (math.pi / 2, math.pi * 7 / 6, math.pi * 11 / 6)]
    return utils.facet(pts if up else pts[::-1], material=steel, fixed=True, mask=STEEL_MASK)


@runtime.persistent('SingleParticleTester')
class Tester:
    """The grains under test and what each gave. Two callbacks every step: measure() before the crushing
    engine reads the force on each loaded grain's platens (a replacement changes the force container
    after it), step() after it notes the crushes (those forces, the displacement, the event's stress and
    strength), removes the crushed grain's fragments and platens, stops a grain at maxStrain and samples
    the curves."""

    def __init__(self, speed=0.0, maxStrain=0.0):
        self.speed, self.maxStrain = speed, maxStrain
        self.grain, self.d, self.top, self.bottom = [], [], [], []   # body ids and diameters, per grain
        self.h = []           # per grain its height between the platens [m] when placed (a sphere's: d)
        self.result = []      # per grain None (loading) or {crushed, F, Fbottom, displacement, value, strength, t}
        self.curves = []      # (grain, t, displacement, F)
        self.t0, self.seen = None, 0
        self.forces = {}      # grain -> (F on its top platen, F on its bottom one) [N] this step

    def state(self):
        return {k: getattr(self, k) for k in ('speed', 'maxStrain', 'grain', 'd', 'h', 'top', 'bottom', 'result',
                                              'curves', 't0', 'seen')}  # forces: measured again at the next step

    @classmethod
    def fromState(cls, s, ref=None):
        t = cls()
        for k, v in s.items():
            setattr(t, k, [tuple(c) for c in v] if k == 'curves' else v)
        return t

    def displacement(self):
        return self.speed * (O.time - self.t0)

    def finished(self):
        return all(r is not None for r in self.result)

    def _remove(self, k, ids):
        for i in list(ids) + [self.top[k], self.bottom[k]]:
            if O.bodies[i] is not None:
                O.bodies.erase(i, O.bodies[i].isClump)   # a clump or a clumped piece with its members

    def measure(self):
        self.forces = {k: (O.forces.f(self.top[k])[2], -O.forces.f(self.bottom[k])[2])
                       for k, r in enumerate(self.result) if r is None}

    def step(self):
        crush = next(e for e in O.engines if isinstance(e, BallastCrushEngine))
        u = self.displacement()
        if crush.nCrushed > self.seen:
            index = {g: k for k, g in enumerate(self.grain)}
            for e in crush.events[self.seen:]:
                k = index.get(e['id'])
                if k is None or self.result[k] is not None:
                    continue
                F, Fb = self.forces[k]
                self.result[k] = {'crushed': True, 'F': F, 'Fbottom': Fb, 'displacement': u, 'value': e['value'],
                                  'strength': e['strength'], 't': O.time - self.t0}
                self._remove(k, e['newIds'])
            self.seen = crush.nCrushed
        sample = O.iter % CURVE_EVERY == 0
        for k, r in enumerate(self.result):
            if r is not None:
                continue
            if u >= self.maxStrain * self.d[k]:  # not crushed: its platens stop, the grain leaves the test
                F, Fb = self.forces[k]
                self.result[k] = {'crushed': False, 'F': F, 'Fbottom': Fb, 'displacement': u, 'value': math.nan, 'strength': math.nan, 't': O.time - self.t0}
                self._remove(k, [self.grain[k]])
            elif sample:
                self.curves.append((k, O.time - self.t0, u, self.forces[k][0]))


@runtime.persistent('SingleParticle')
class SingleParticle(Experiment):
    """The single-particle crushing test; keyword arguments: any parameter of
    :data:`ballast.experiments.single_particle.parameters.PARAMS`, or parameters=check(...)."""

    NAME = 'single_particle'
    Parameters = SingleParticleParameters
    REOPEN_PARAMS = ('results', 'runId', 'progress')

    def __init__(self, parameters=None, **params):
        self.tester = None
        Experiment.__init__(self, parameters, **params)

    def pieces(self):
        return Experiment.pieces(self) + [self.tester]

    def diameters(self):
        """The grains' diameters [m]: as given, or n uniform in [dMin, dMax] drawn from the seed."""
        p = self.p
        if p['diameters']:
            return np.array(p['diameters'], dtype=float)
        return np.random.default_rng(p['seed']).uniform(p['dMin'], p['dMax'], p['n'])

    def prepare(self):
        """The grains in a row, each touching its two platens, the engines, the time step (eq. 5)."""
        p = self.p
        self.openRunDirectory()
        self.newScene()
        ballast, steel = materials(p, p['young'])
        ip2, law2, _ = LAWS[p['law']]
        O.engines = [ForceResetter(),
                     InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Box_Aabb()], avoidSelfInteractionMask=AVOID),
                     InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Box_Sphere_ScGeom()], [ip2()], [law2()]),
                     NewtonIntegrator(damping=p['damping'], gravity=(0, 0, 0))]
        d = self.diameters()
        self.tester = tester = Tester(p['speed'], p['maxStrain'])
        if p['grain'] == 'polyhedron':
            return self.preparePolyhedra(d)
        if p['grain'] == 'clump':
            place, pitch = self.clumps(d, ballast)
        else:
            pitch = PITCH * max(d.max(), p['dMax'])

            def place(k, x, dk):   # a sphere on its bottom platen: (its id, its height, its platens' half-width)
                return O.bodies.append(utils.sphere((x, 0, dk / 2), dk / 2, material=ballast, mask=GRAIN_MASK)), dk, \
                    PLATEN_HALF * dk
        for k, dk in enumerate(d):
            x, t = k * pitch, PLATEN_THICKNESS / 2
            gid, h, a = place(k, x, dk)
            tester.grain.append(gid)
            tester.h.append(float(h))
            tester.bottom.append(O.bodies.append(utils.box((x, 0, -t), (a, a, t), fixed=True, material=steel,
                                                           mask=STEEL_MASK)))
            tester.top.append(O.bodies.append(utils.box((x, 0, h + t), (a, a, t), fixed=True, material=steel,
                                                        mask=STEEL_MASK)))
        tester.d, tester.result = [float(x) for x in d], [None] * len(d)
        O.engines = O.engines + [
            runtime.callback(tester, 'measure', iterPeriod=1, label='singleParticleForces'),
            BallastCrushEngine(ft0=p['ft0'], m=p['m'], pattern=p['pattern'], criterion=p['criterion'],
                               weibullModulus=p['weibullModulus'], seed=p['seed'], rMin=p['rMin'], adjustDt=False,
                               scaledPWaveStep=p.scaledPWaveStep(), label='crush', **p.crushPeriod()),
            runtime.callback(tester, 'step', iterPeriod=1, label='singleParticleTester')]
        O.dt = p['dtSafety'] * utils.PWaveTimeStep()
        self.adopt()
        self.startTimeStep(None)   # the platens are kinematic: only the grains move under Newton
        self.say('prepared %d grains of %.1f-%.1f mm, platens closing at %g m/s, dt = %.3g s' % (
            len(d), 1e3 * d.min(), 1e3 * d.max(), p['speed'], O.dt))
        return self

    def preparePolyhedra(self, d):
        """With grain 'polyhedron' (docs/grains.md, "Polyhedra"): grain k a random polyhedron of r_eq d/2
        (grainkinds.polyhedron.randomVertices, seed [seed, k]) lying on its largest face, turned at random about z,
        between two steel facets (triangles whose inscribed circle holds the grain) at its lowest and highest points;
        YADE's volumetric law, and YADE's PolyhedraSplitter crushing it (engines.PolyhedronCrushEngine)."""
        from ...engines import PolyhedronCrushEngine
        from ...grainkinds.polyhedron import addPolyhedron, randomVertices
        from ..scene import polyhedronEngines, polyhedronMaterials
        p, tester = self.p, self.tester
        ballast, steel = polyhedronMaterials(p, p['young'])
        O.engines = polyhedronEngines(p['damping'], gravity=(0, 0, 0))
        rng = np.random.default_rng(p['seed'])
        shapes = [lying(randomVertices(dk / 2, [p['seed'], k]), rng.uniform(0, 2 * math.pi)) for k, dk in enumerate(d)]
        # a platen's bounding box (0.87 of its circumradius, 3 reach, on either side) clear of the next grain's: a facet
        # paired with a polyhedron it does not touch crashed YADE's Ig2_Facet_Polyhedra in this build (measured)
        pitch = 4 * max(float(np.max(np.linalg.norm(v[:, :2], axis=1))) for v in shapes)
        for k, v in enumerate(shapes):
            x = k * pitch
            h = float(np.max(v[:, 2]))
            reach = float(np.max(np.linalg.norm(v[:, :2], axis=1)))
            tester.grain.append(addPolyhedron(v + (x, 0, 0), ballast, mask=GRAIN_MASK))
            tester.h.append(h)
            tester.bottom.append(O.bodies.append(platen(x, 0.0, reach, steel, up=True)))
            tester.top.append(O.bodies.append(platen(x, h, reach, steel, up=False)))
        tester.d, tester.result = [float(x) for x in d], [None] * len(d)
        crush = PolyhedronCrushEngine(ft0=p['ft0'], rMin=p['rMin'], seed=p['seed'], adjustDt=False, label='crush',
                                      **p.crushPeriod())
        crush.floor()
        O.engines = O.engines + [runtime.callback(tester, 'measure', iterPeriod=1, label='singleParticleForces')] + \
            crush.engines() + [runtime.callback(tester, 'step', iterPeriod=1, label='singleParticleTester')]
        O.dt = p['dtSafety'] * grainkinds.current().pWaveTimeStep()
        self.adopt()
        self.startTimeStep(None)
        self.say('prepared %d polyhedra of %.1f-%.1f mm (volume-equivalent), platens closing at %g m/s, dt = %.3g s' % (
            len(d), 1e3 * d.min(), 1e3 * d.max(), p['speed'], O.dt))
        return self

    def clumps(self, d, ballast):
        """With grain 'clump': (place(k, x, d) -> (the clump's id, its height [m], its platens' half-width [m]), the
        pitch [m]). Grain k: a template drawn from the seed, on its flat side turned at random about z, r_eq d/2, its
        lowest point on z = 0."""
        p = self.p
        shapes = ClumpSample.ofScene(p)
        ks, qs = shapes.draw(len(d), p['seed'], flat=True)
        frames = []   # per grain the members' (lowest, highest) [m] about the template's origin, and its reach
        for k, q, dk in zip(ks, qs, d):
            C, R, _ = shapes.templates[k]
            z = np.array([(q * Vector3(*c))[2] for c in C.tolist()]) * dk / 2
            reach = float(np.max(np.linalg.norm(C, axis=1) + R)) * dk / 2   # circumscribed radius about the origin
            frames.append((float(np.min(z - R * dk / 2)), float(np.max(z + R * dk / 2)), reach))
        pitch = PITCH * 2 * max(f[2] for f in frames)

        def place(k, x, dk):
            lo, hi, reach = frames[k]
            return shapes.add(ks[k], qs[k], (x, 0, -lo), dk / 2, ballast), hi - lo, max(PLATEN_HALF * dk, reach)
        return place, pitch

    def load(self):
        """Close every pair of platens until its grain crushes (or closes by maxStrain); write the outputs."""
        p, tester = self.p, self.tester
        if tester is None:
            self.prepare()
            tester = self.tester
        if tester.t0 is None:
            tester.t0 = O.time
            for i in tester.top:
                O.bodies[i].state.vel = (0, 0, -p['speed'])
        tEnd = tester.t0 + p['maxStrain'] * max(tester.d) / p['speed'] + 2 * O.dt
        self.runUntil(tester.finished, tEnd=tEnd, phase='crush', checkEvery=50, simSpan=tEnd - O.time,
                      simStart=O.time, extra=lambda: '%d of %d grains done' % (
                          sum(r is not None for r in tester.result), len(tester.result)))
        s = self.finishRun(self.writeOutputs)
        spread = ('F/d^2 %.3g-%.3g MPa' % (s['forceOverD2Min'] / 1e6, s['forceOverD2Max'] / 1e6) if s['nCrushed']
                  else 'none crushed by maxStrain')
        self.say('done: %d of %d grains crushed, %s; results in %s' % (s['nCrushed'], s['n'], spread, self.out))
        if s['nUnloaded']:
            self.say('warning: ' + s['warnings'][-1])
        return s

    def writeOutputs(self):
        """strengths.csv, curves.csv, the figures and summary.json (outputs.write); returns the summary."""
        t = self.table()
        s = outputs.summary(self, t)
        outputs.write(self, s, t)
        return s

    def summary(self):
        """What summary.json holds (outputs.summary: the statistics of the strengths)."""
        return outputs.summary(self)

    def table(self):
        """strengths.csv as a pandas DataFrame (outputs.table)."""
        return outputs.table(self)

    # ------------------------------------------------------------------ saving
    def state(self):
        return dict(self.baseState(), tester=runtime.ref(self.tester))

    @classmethod
    def fromState(cls, s, ref):
        exp = cls.__new__(cls)
        exp.setBaseState(s, ref)
        exp.tester = ref(s['tester'])
        return exp
