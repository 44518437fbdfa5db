"""The sample (section 4): a dense packing of grains with diameters uniform in [dMin, dMax] in the
cylinder, stored per seed and packing parameters so that every later run of the same realization
starts from the same grains. The grains (YADE's SpherePack.makeCloud) fall frictionless into the
cylinder, a plate presses them until they rest, friction is restored, the plate's force lowered and
the grains stiffened to the true modulus; the plate is then lifted. docs/oedometer.md, "The sample",
gives the porosities this reaches and why."""
import json
import math
import os
import time

import numpy as np
from yade import O, Vector3, pack, utils

from ... import runtime
from ...geometry import meanCubedDiameterVolume, sphereVolume
from ...params import requireWritableDir
from .. import grains, preparation
from . import scene
from .parameters import OWNER, packingKey


@runtime.persistent('StoredPacking')
class StoredPacking:
    """Builds the packing of a seed, or loads it from the store; either way the loading starts from
    the stored file, so the same seed gives the same run. Replace it by any object with
    ``prepare(experiment)`` that leaves the grains, the cylinder and the engines in the scene and returns
    the :class:`scene.Rig` (a registered object: ``@ballast.runtime.persistent(name)``)."""

    CLOUD_SOLID = 0.3       # [-] solid fraction of the falling cloud, low enough for grains to fall freely
    PRESS_STILL = (0.03, 1e-5)   # ([s], [m]): the press ends when the plate moved less than this over that time
    SEAT_STILL = (0.01, 2e-6)    # the same once friction is restored and the force lowered
    PRESS_TIME = (0.05, 1.0)     # [s] shortest and longest press

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
        pdir = self.folder(p)
        keyDict, fname = packingKey(p)
        path = os.path.join(pdir, fname)
        if p['reusePacking'] and os.path.exists(path):
            self.reused = True
            exp.phases.say('packing: reusing %s' % path)
        else:
            self.build(exp)
            os.makedirs(pdir, exist_ok=True)
            x, r = grains.arrays()[:2]
            data = {'key': keyDict, 'created': time.strftime('%Y-%m-%dT%H:%M:%S'), 'runId': exp.runId,
                    'steps': dict(exp.phases.steps), 'wallSeconds': dict(exp.phases.wall),
                    'grains': [[repr(float(v)) for v in (xi[0], xi[1], xi[2], ri)] for xi, ri in zip(x, r)]}
            tmp = path + '.%d.tmp' % os.getpid()
            with open(tmp, 'w') as fh:
                json.dump(data, fh)
            os.replace(tmp, path)  # atomic: concurrent runs of the same seed never see half a file
            exp.phases.say('packing: %d grains saved to %s' % (len(r), path))
        self.file = path
        with open(path) as fh:
            stored = json.load(fh)['grains']
        exp.newScene()
        ballast, steel = scene.materials(p, p['young'])
        rig = scene.Rig(scene.Cylinder(p, steel), ballast, steel)
        O.engines = scene.engines(p['damping'], p['law'], scene.rolling(p))
        for g in stored:
            x, y, z, r = (float(v) for v in g)
            O.bodies.append(utils.sphere((x, y, z), r, material=ballast, mask=scene.GRAIN_MASK))
        O.dt = p['dtSafety'] * utils.PWaveTimeStep()
        # contacts re-form with the stored overlaps; only the shear history is lost: let it settle
        exp.phases.run('settle', lambda: grains.unbalanced() < 0.01, tEnd=O.time + 0.01, checkEvery=100)
        return rig

    # ------------------------------------------------------------------ building
    def cloud(self, p, seed, vSolid, Rin):
        """Grains of total volume vSolid [m^3] in a loose cloud (solid fraction CLOUD_SOLID) above the bottom,
        placed by YADE's SpherePack.makeCloud (radii uniform in [dMin/2, dMax/2], no overlaps) in the box
        around the cylinder; those with their centre farther than Rin - dMax/2 - gap from the axis are
        dropped, then the lowest kept until vSolid is reached. Returns (centres, radii, cloud top)."""
        rMin, rMax = p['dMin'] / 2, p['dMax'] / 2
        gap = 0.05 * p['dMin']
        Rc = Rin - rMax - gap
        z0 = rMax + gap
        hBox = 1.25 * vSolid / (self.CLOUD_SOLID * math.pi * Rc ** 2)  # the square box loses 1 - pi/4 of its grains
        num = int(math.ceil(1.25 * vSolid / meanCubedDiameterVolume(p['dMin'], p['dMax']) * 4 / math.pi))
        for attempt in range(6):  # a narrow box holds big grains at a lower solid fraction: make it taller
            sp = pack.SpherePack()
            made = sp.makeCloud((-Rc, -Rc, z0), (Rc, Rc, z0 + hBox), rMean=(rMin + rMax) / 2,
                                rRelFuzz=(rMax - rMin) / (rMax + rMin), num=num, seed=seed)
            if made == num:
                break
            hBox *= 1.3
        else:
            raise RuntimeError('cloud: makeCloud placed %d of %d grains' % (made, num))
        kept = sorted(((c[2], c[0], c[1], r) for c, r in sp if math.hypot(c[0], c[1]) < Rc))
        z, x, y, r = (np.array(v) for v in zip(*kept))
        n = int(np.searchsorted(np.cumsum(sphereVolume(r)), vSolid)) + 1
        if n > len(r):
            raise RuntimeError('cloud: %.3g m^3 of grains asked, %.3g placed' % (vSolid, np.sum(sphereVolume(r))))
        return np.column_stack([x[:n], y[:n], z[:n]]), r[:n], float(np.max(z[:n] + r[:n]))

    def build(self, exp):
        p = exp.p
        exp.newScene()
        ballast, steel = scene.materials(p, p['prepYoung'])
        ballast.frictionAngle = p['depFriction']
        self.rig = scene.Rig(None, ballast, steel)
        Rin = p['diameter'] / 2
        pos, rad, top = self.cloud(p, p['seed'], p['fill'] * math.pi * Rin ** 2 * p['height'], Rin)
        # while the cloud falls the wall reaches above it, or grains bounce out over the rim
        self.rig.cylinder = scene.Cylinder(p, steel, max(p['height'], top + p['dMax']))
        O.engines = scene.engines(p['prepDamping'], p['law'], scene.rolling(p)) + [
            runtime.callback(self, 'shake', iterPeriod=10, dead=True, label='oedoShaker')]
        for c, r in zip(pos, rad):
            O.bodies.append(utils.sphere(tuple(c), float(r), material=self.rig.ballast, mask=scene.GRAIN_MASK))
        O.dt = preparation.PREP_DT_SAFETY * utils.PWaveTimeStep()
        exp.phases.say('deposit: %d grains (%.1f %% of the cylinder) falling from up to %.3f m, friction %g rad '
                       '(E = %.3g Pa while preparing, dt = %.2e s)' % (len(rad), 100 * p['fill'], top,
                                                                      p['depFriction'], p['prepYoung'], O.dt))
        tDep = p['depTime'] or math.sqrt(2 * top / 9.81)
        exp.phases.run('deposit', tEnd=O.time + tDep, simSpan=tDep, simStart=O.time, extra=grains.restInfo)
        out = [b.id for b in grains.spheres() if math.hypot(b.state.pos[0], b.state.pos[1]) > self.rig.cylinder.Rv
               or b.state.pos[2] < 0]
        for i in out:
            O.bodies.erase(i)
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
        x, r, _ = grains.arrays()
        b = utils.wall(float(np.max(x[:, 2] + r)), axis=2, sense=-1, material=self.rig.steel, mask=scene.STEEL_MASK)
        b.state.blockedDOFs = 'xyXYZ'
        b.state.mass = p['steelDensity'] * math.pi * (p['diameter'] / 2) ** 2 * p['plateThickness']
        b.state.inertia = Vector3(1, 1, 1)  # a wall has none; its rotations are blocked, but Newton divides by it
        b.dynamic = True
        self._plate = O.bodies.append(b)
        O.forces.setPermF(self._plate, Vector3(0, 0, -p['pressForce']))
        tShort, tLong = self.PRESS_TIME
        t0 = O.time
        exp.phases.run('press', preparation.still(self._plate, *self.PRESS_STILL, after=t0 + tShort, unbalanced=0.01),
                       tEnd=t0 + tLong,
                       extra=lambda: 'plate at %.4f m  %s' % (O.bodies[self._plate].state.pos[2], grains.restInfo()))
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
        preparation.Stiffener().run(exp, [(self.rig.ballast, p['young']), (self.rig.steel, p['steelYoungRatio'] * p['young'])],
                                    p['young'] / p['prepYoung'])
        if p['young'] > p['prepYoung']:
            exp.phases.run('stiffen', lambda: grains.unbalanced() < 0.02, tEnd=O.time + 0.02, extra=grains.restInfo)
