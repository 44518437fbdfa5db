"""The sample (section 4): grains with diameters uniform in [dMin, dMax] deposited under gravity into
the cylinder, vibrated, stiffened to the true modulus, and stored per seed and packing parameters so
that every later run of the same realization starts from the same grains."""
import json
import math
import os
import time

import numpy as np
from yade import O, Vector3, utils
from yade.wrapper import PyRunner

from ..geometry import meanCubedDiameterVolume, sphereVolume
from . import scene
from .callbacks import command
from .parameters import packingKey


class StoredPacking:
    """Builds the packing of a seed, or loads it from the store; either way the loading starts from
    the stored file, so the same seed gives the same run. Replace it by any object with
    ``prepare(experiment)`` that leaves the grains, the cylinder and the engines in the scene."""

    STIFFEN_TIME = 0.01     # [s] simulated time over which the soft preparation modulus is raised to young
    PREP_DT_SAFETY = 0.5    # [-] O.dt / PWaveTimeStep() while preparing: the packing does not depend on dtSafety
    CLOUD_SOLID = 0.3       # [-] solid fraction of the falling cloud, low enough for grains to fall freely
    OVERFILL_SOLID = 0.64   # [-] enough grains to overfill the cylinder at this solid fraction; the excess is cut

    def __init__(self):
        self.file, self.reused, self.escaped = None, False, None
        self._shake = self._stiffen = None

    def state(self):
        return {'file': self.file, 'reused': self.reused, 'escaped': self.escaped}

    def setState(self, s):
        self.file, self.reused, self.escaped = s['file'], s['reused'], s['escaped']

    # ------------------------------------------------------------------ the piece's entry point
    def prepare(self, exp):
        p = exp.p
        pdir = p['packingDir'] or os.path.join(p['results'], 'packings')
        keyDict, fname = packingKey(p)
        path = os.path.join(pdir, fname)
        if p['reusePacking'] and os.path.exists(path):
            self.reused = True
            exp.phases.say('packing: reusing %s' % path)
        else:
            self.build(exp)
            os.makedirs(pdir, exist_ok=True)
            x, r = exp.grainArrays()[:2]
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
            grains = json.load(fh)['grains']
        exp.newScene()
        exp.ballast, exp.steel = scene.materials(p, p['young'])
        exp.cylinder = scene.Cylinder(p, exp.steel)
        O.engines = scene.engines(p['damping'], p['law'])
        for g in grains:
            x, y, z, r = (float(v) for v in g)
            O.bodies.append(utils.sphere((x, y, z), r, material=exp.ballast, mask=scene.GRAIN_MASK))
        O.dt = p['dtSafety'] * utils.PWaveTimeStep()
        # contacts re-form with the stored overlaps; only the shear history is lost: let it settle
        exp.phases.run('settle', lambda: exp.unbalanced() < 0.01, tEnd=O.time + 0.01, checkEvery=100)

    # ------------------------------------------------------------------ building
    def cloud(self, p, rng, n, Rin):
        """n grains, diameters uniform in [dMin, dMax], at random non-overlapping places in the
        cylinder at solid fraction CLOUD_SOLID. Returns (centres, radii, cloud height)."""
        d = rng.uniform(p['dMin'], p['dMax'], n)
        r = np.sort(d / 2)[::-1]  # big first: random sequential addition fails less
        gap = 0.05 * p['dMin']
        hCloud = np.sum(sphereVolume(r)) / (self.CLOUD_SOLID * math.pi * Rin ** 2)
        pos = np.zeros((n, 3))
        for i, ri in enumerate(r):
            for trial in range(100000):
                if trial and trial % 300 == 0:
                    hCloud *= 1.1
                rho = (Rin - ri - gap) * math.sqrt(rng.uniform())
                phi = rng.uniform(0, 2 * math.pi)
                c = np.array([rho * math.cos(phi), rho * math.sin(phi), rng.uniform(ri + gap, max(hCloud - ri, ri + gap))])
                if i == 0 or np.all(np.sum((pos[:i] - c) ** 2, axis=1) > (r[:i] + ri + gap) ** 2):
                    pos[i] = c
                    break
            else:
                raise RuntimeError('could not place grain %d of %d in the cloud' % (i, n))
        return pos, r, hCloud

    def build(self, exp):
        p = exp.p
        exp.newScene()
        exp.ballast, exp.steel = scene.materials(p, p['prepYoung'])
        rng = np.random.default_rng(p['seed'])
        Rin = p['diameter'] / 2
        n = int(math.ceil(self.OVERFILL_SOLID * math.pi * Rin ** 2 * p['height'] / meanCubedDiameterVolume(p['dMin'], p['dMax'])))
        pos, rad, hCloud = self.cloud(p, rng, n, Rin)
        # while the cloud falls the wall reaches above it, or grains bounce out over the rim
        exp.cylinder = scene.Cylinder(p, exp.steel, max(p['height'], hCloud + p['dMax']))
        O.engines = scene.engines(p['prepDamping'], p['law']) + [
            PyRunner(command=command('packing', 'shake'), iterPeriod=10, dead=True, label='oedoShaker')]
        for c, r in zip(pos, rad):
            O.bodies.append(utils.sphere(tuple(c), float(r), material=exp.ballast, mask=scene.GRAIN_MASK))
        O.dt = self.PREP_DT_SAFETY * utils.PWaveTimeStep()
        exp.phases.say('deposit: %d grains falling from up to %.3f m (E = %.3g Pa while preparing, dt = %.2e s)' % (
            n, hCloud, p['prepYoung'], O.dt))
        tFall = math.sqrt(2 * hCloud / 9.81)
        # at rest: forces balanced (grains on the frictionless steel may still slide, so not v = 0)
        exp.phases.run('deposit', lambda: O.time > 1.2 * tFall and exp.unbalanced() < 0.1, tEnd=p['depTime'],
                       simSpan=p['depTime'], simStart=0.0, extra=exp.restInfo)
        # fill to the cylinder height: grains sticking out above it are removed
        grains = exp.sphereBodies()
        cut = [b.id for b in grains if b.state.pos[2] + b.shape.radius > p['height']]
        out = [b.id for b in grains if math.hypot(b.state.pos[0], b.state.pos[1]) > exp.cylinder.Rv or b.state.pos[2] < 0]
        for i in set(cut + out):
            O.bodies.erase(i)
        self.escaped = len(set(out) - set(cut))
        exp.phases.say('deposit: done at t=%.3f s, %d grains above %.3f m removed (%d escaped), %d left' % (
            O.time, len(cut), p['height'], self.escaped, len(exp.sphereBodies())))
        self.vibrate(exp)
        self.stiffen(exp)

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
        self._shake = (t0, p['vibAcc'], omega, list(exp.cylinder.ids))
        shaker = next(e for e in O.engines if e.label == 'oedoShaker')
        shaker.iterPeriod, shaker.dead = max(1, int(1 / (p['vibFreq'] * O.dt * 200))), False  # 200 updates a period
        exp.phases.say('vibrate: %d periods of %.3g m/s^2 at %.3g Hz (amplitude %.2f mm)' % (
            periods, p['vibAcc'], p['vibFreq'], 1e3 * p['vibAcc'] / omega ** 2))
        exp.phases.run('vibrate', tEnd=tEnd, simSpan=tEnd - t0, simStart=t0)
        shaker.dead = True
        for i, x0 in zip(exp.cylinder.ids, exp.cylinder.pos0):
            O.bodies[i].state.vel = Vector3(0, 0, 0)
            O.bodies[i].state.pos = x0
        exp.phases.run('vibrate', lambda: exp.unbalanced() < 0.1, tEnd=O.time + 0.2, extra=exp.restInfo)

    def shake(self):
        t0, a, w, ids = self._shake
        v = a / w * math.sin(w * (O.time - t0))
        for i in ids:
            O.bodies[i].state.vel = Vector3(v, 0, 0)

    def stiffen(self, exp):
        """Back to the true modulus. New contacts take it from the materials at once; the existing
        ones are stiffened gradually (their stiffnesses are proportional to E under both laws) over STIFFEN_TIME
        with strong damping, so that the overlaps of the soft packing relax quasi-statically
        instead of kicking the grains with a suddenly stiffer spring."""
        p = exp.p
        ratio = p['young'] / p['prepYoung']
        exp.ballast.young = p['young']
        exp.steel.young = p['steelYoungRatio'] * p['young']
        O.dt = self.PREP_DT_SAFETY * utils.PWaveTimeStep()
        if ratio <= 1:
            return
        newton = scene.newton()
        newton.damping = max(p['prepDamping'], 0.8)
        kn, ks = scene.LAWS[p['law']][2]
        soft = {(i.id1, i.id2): (getattr(i.phys, kn), getattr(i.phys, ks)) for i in O.interactions if i.isReal}
        exp.phases.say('stiffen: E %.3g -> %.3g Pa over %.3g s, dt = %.2e s' % (p['prepYoung'], p['young'],
                                                                               self.STIFFEN_TIME, O.dt))
        self._stiffen = (O.time, ratio, soft, kn, ks)
        O.engines = O.engines + [PyRunner(command=command('packing', 'stiffenStep'), iterPeriod=100, initRun=True,
                                          label='oedoStiffener')]
        exp.phases.run('stiffen', tEnd=O.time + self.STIFFEN_TIME)
        O.engines = [e for e in O.engines if e.label != 'oedoStiffener']
        self._stiffen = (O.time - 2 * self.STIFFEN_TIME, ratio, soft, kn, ks)
        self.stiffenStep()  # the last step to the full modulus
        newton.damping = p['prepDamping']
        exp.phases.run('stiffen', lambda: exp.unbalanced() < 0.02, tEnd=O.time + 0.02, extra=exp.restInfo)

    def stiffenStep(self):
        t0, ratio, soft, kn, ks = self._stiffen
        fac = ratio ** min((O.time - t0) / self.STIFFEN_TIME, 1.0)
        for i in O.interactions:
            k = soft.get((i.id1, i.id2))
            if k is not None and i.isReal:
                setattr(i.phys, kn, k[0] * fac)
                setattr(i.phys, ks, k[1] * fac)
