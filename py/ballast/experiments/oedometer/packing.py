"""The sample (section 4): a dense packing of grains with diameters uniform in [dMin, dMax] in the
cylinder, stored per seed and packing parameters so that every later run of the same realization
starts from the same grains. The grains (YADE's SpherePack.makeCloud) fall frictionless into the
cylinder, a plate presses them until they rest, friction is restored, the plate's force lowered and
the grains stiffened to the true modulus; the plate is then lifted. docs/oedometer.md, "The sample",
gives the porosities this reaches and why."""
import math
import os

from yade import O, Vector3

from ... import runtime
from ...params import requireWritableDir
from .. import grains, preparation, sample
from ..containers import Cylinder
from ..scene import polyhedronModulus, sceneEngines, sceneMaterials
from .parameters import OWNER, packingKey
from .rig import Rig


@runtime.persistent('StoredPacking')
class StoredPacking:
    """Builds the packing of a seed, or loads it from the store; either way the loading starts from
    the stored file, so the same seed gives the same run. Replace it by any object with
    ``prepare(experiment)`` that leaves the grains, the cylinder and the engines in the scene and returns
    the :class:`Rig` (a registered object: ``@ballast.runtime.persistent(name)``)."""

    SEAT_STILL = (0.01, 2e-6)    # ([s], [m]): seated when the plate moved less than this over that time
    # ([m/s], [s]): polyhedra deposit on until their rms speed is below this (at most that long): a press started on
    # grains still bouncing from their fall kicked them to 30 m/s (measured)
    POLYHEDRA_REST = (0.1, 0.2)

    def __init__(self):
        self.file, self.reused, self.escaped = None, False, None
        self._shake = self._plate = None
        self.rig = None  # while building: the scene's cylinder and materials

    def state(self):
        return {'file': self.file, 'reused': self.reused, 'escaped': self.escaped}

    @classmethod
    def fromState(cls, s, ref=None):
        obj = cls()
        obj.file, obj.reused, obj.escaped = s['file'], s['reused'], s['escaped']
        return obj

    # ------------------------------------------------------------------ the piece's entry point
    @staticmethod
    def folder(p):
        return p['packingDir'] or os.path.join(p['results'], 'packings')

    def checkOutputs(self, exp):
        """The store is a folder this run can write (checked before any work)."""
        requireWritableDir(OWNER, 'packingDir', self.folder(exp.p))

    def prepare(self, exp):
        p = exp.p
        keyDict, fname = packingKey(p)
        self.file, doc, self.reused = sample.stored(exp, self.folder(p), keyDict, fname, p['reusePacking'],
                                                    lambda: self.build(exp), 'packing')
        exp.newScene()
        ballast, steel = sceneMaterials(p, p['young'])
        rig = Rig(Cylinder(p, steel), ballast, steel)
        sample.reload(exp, doc, ballast, p['damping'])
        return rig

    # ------------------------------------------------------------------ building
    def build(self, exp):
        p = exp.p
        exp.newScene()
        ballast, steel = sceneMaterials(p, p['prepYoung'])
        ballast.frictionAngle = p['depFriction']
        self.rig = Rig(None, ballast, steel)
        Rin = p['diameter'] / 2
        pos, rad, top = sample.grainCloud(p, sample.CylinderShape(Rin), p['fill'] * math.pi * Rin ** 2 * p['height'],
                                          p['seed'])
        # while the cloud falls the wall reaches above it, or grains bounce out over the rim
        self.rig.cylinder = Cylinder(p, steel, max(p['height'], top + p['dMax']))
        O.engines = sceneEngines(p, p['prepDamping']) + [
            runtime.callback(self, 'shake', iterPeriod=10, dead=True, label='oedoShaker')]
        sample.place(pos, rad, self.rig.ballast, p, p['seed'])
        O.dt = preparation.PREP_DT_SAFETY * grains.kind().pWaveTimeStep()   # YADE's PWaveTimeStep() but for polyhedra
        exp.phases.say('deposit: %d grains (%.1f %% of the cylinder) falling from up to %.3f m, friction %g rad '
                       '(E = %.3g Pa while preparing, dt = %.2e s)' % (len(rad), 100 * p['fill'], top,
                                                                      p['depFriction'], p['prepYoung'], O.dt))
        tDep = p['depTime'] or math.sqrt(2 * top / 9.81)
        sample.deposit(exp, tDep)
        if p['grain'] == 'polyhedron':   # polyhedra bounce and roll longer (no viscous term in YADE's volumetric law)
            vRest, tMax = self.POLYHEDRA_REST
            exp.phases.run('deposit', lambda: grains.vRms() < vRest, tEnd=O.time + tMax, extra=grains.restInfo)
        out = [b.id for b in grains.spheres() if math.hypot(b.state.pos[0], b.state.pos[1]) > self.rig.cylinder.Rv
               or b.state.pos[2] < 0]
        grains.erase(out)
        self.escaped = len(out)
        self.vibrate(exp)
        self.press(exp)
        self.stiffen(exp)
        if self._plate is not None:
            O.bodies.erase(self._plate)
            self._plate = None

    def press(self, exp):
        """A plate of the loading plate's mass pressed with pressForce onto the frictionless grains until they
        rest; then friction restored (materials and contacts) and the force lowered to seatForce."""
        p = exp.p
        self._plate = None
        if p['pressForce'] <= 0:
            self.restoreFriction(exp)
            return
        self._plate = sample.press(exp, self.rig.steel, p['steelDensity'] * math.pi * (p['diameter'] / 2) ** 2 *
                                   p['plateThickness'], p['pressForce'])
        self.restoreFriction(exp)
        O.forces.setPermF(self._plate, Vector3(0, 0, -p['seatForce']))
        t0 = O.time
        exp.phases.run('press', preparation.still(self._plate, *self.SEAT_STILL, after=t0 + self.SEAT_STILL[0],
                                                  unbalanced=0.01), tEnd=t0 + 0.2)
        exp.phases.say('press: %g N then %g N, plate at %.4f m' % (p['pressForce'], p['seatForce'],
                                                                    O.bodies[self._plate].state.pos[2]))

    def restoreFriction(self, exp):
        preparation.restoreFriction(self.rig.ballast, exp.p['friction'], exp.p['steelFriction'])

    def vibrate(self, exp):
        """Horizontal acceleration a cos(w tau) of the cylinder: velocity (a/w) sin(w tau), displacement
        (a/w^2)(1 - cos(w tau)), at rest in the original place after whole periods."""
        p = exp.p
        if p['vibTime'] <= 0 or p['vibAcc'] <= 0:
            return
        omega = 2 * math.pi * p['vibFreq']
        periods = math.ceil(p['vibTime'] * p['vibFreq'] - 1e-9)
        t0 = O.time
        tEnd = t0 + periods / p['vibFreq']
        self._shake = (t0, p['vibAcc'], omega, list(self.rig.cylinder.ids))
        shaker = next(e for e in O.engines if e.label == 'oedoShaker')
        shaker.iterPeriod, shaker.dead = max(1, int(1 / (p['vibFreq'] * O.dt * 200))), False  # 200 updates a period
        exp.phases.say('vibrate: %d periods of %.3g m/s^2 at %.3g Hz (amplitude %.2f mm)' % (
            periods, p['vibAcc'], p['vibFreq'], 1e3 * p['vibAcc'] / omega ** 2))
        exp.phases.run('vibrate', tEnd=tEnd, simSpan=tEnd - t0, simStart=t0)
        shaker.dead = True
        for i, x0 in zip(self.rig.cylinder.ids, self.rig.cylinder.pos0):
            O.bodies[i].state.vel = Vector3(0, 0, 0)
            O.bodies[i].state.pos = x0
        exp.phases.run('vibrate', lambda: grains.unbalanced() < 0.1, tEnd=O.time + 0.2, extra=grains.restInfo)

    def shake(self):
        t0, a, w, ids = self._shake
        v = a / w * math.sin(w * (O.time - t0))
        for i in ids:
            O.bodies[i].state.vel = Vector3(v, 0, 0)

    def stiffen(self, exp):
        """Back to the true modulus (preparation.Stiffener), then let the grains settle."""
        p = exp.p
        E, Es = p['young'], p['steelYoungRatio'] * p['young']
        if p['grain'] == 'polyhedron':   # PolyhedraMat's young is the volumetric modulus of the Young's modulus
            E, Es = polyhedronModulus(p, E), polyhedronModulus(p, Es)
        preparation.Stiffener().run(exp, [(self.rig.ballast, E), (self.rig.steel, Es)], p['young'] / p['prepYoung'])
        if p['young'] > p['prepYoung']:
            exp.phases.run('stiffen', lambda: grains.unbalanced() < 0.02, tEnd=O.time + 0.02, extra=grains.restInfo)
