"""The box and its ballast bed (docs/box.md, "Set-up"): a steel box of five walls (floor, two ends, two
sides; YADE's infinite walls), the bed placed in `layers` layers: each a loose cloud of grains (YADE's
makeCloud, diameters uniform in [dMin, dMax]) falling frictionless onto the layer below, then pressed
through a plate at layerPressure until it rests; then friction restored and the grains stiffened to
the true modulus (:mod:`ballast.experiments.preparation`), with the soft modulus prepYoung before."""
import math
import os

import numpy as np
from yade import O, Vector3, pack

from ... import runtime
from ...geometry import meanCubedDiameterVolume, sphereVolume
from .. import grains, preparation, sample
from ..containers import boxWalls
from ..scene import engines, materials, rolling
from .parameters import bedKey

PLATE_THICKNESS = 0.02       # [m] the press plate's mass: steel of this thickness over the box


@runtime.persistent('BoxRig')
class Rig:
    """The box's walls (ids: floor, x-, x+, y-, y+), the materials (ballast, steel of the box, the sleeper's)
    and, once seated, the sleeper's id."""

    def __init__(self, walls, ballast, steel, sleeperMat=None, sleeper=None):
        self.walls, self.ballast, self.steel, self.sleeperMat, self.sleeper = walls, ballast, steel, sleeperMat, sleeper

    def state(self):
        return {'walls': list(self.walls), 'ballast': self.ballast.id, 'steel': self.steel.id,
                'sleeperMat': None if self.sleeperMat is None else self.sleeperMat.id, 'sleeper': self.sleeper}

    @classmethod
    def fromState(cls, s, ref=None):
        mat = None if s['sleeperMat'] is None else O.materials[s['sleeperMat']]
        return cls(s['walls'], O.materials[s['ballast']], O.materials[s['steel']], mat, s['sleeper'])


def walls(p, steel):
    """The floor at z = 0 and the four side walls of the box centred on the z axis."""
    return boxWalls(p['boxLength'], p['boxWidth'], steel)


def folder(p):
    return p['bedDir'] or os.path.join(p['results'], 'beds')


def prepare(exp):
    """The bed of the run's seed and bed parameters: loaded from the store (bedDir) if it is there and
    reuseBed, else built and stored; either way the run starts from the stored grains, so a seed gives
    the same run. Returns (Rig, bed height [m], porosity [-], grains that escaped, the stored file)."""
    p = exp.p
    keys, name = bedKey(p)

    def build():
        top, porosity, escaped = buildBed(exp)
        return {'top': top, 'porosity': porosity, 'escaped': escaped}
    path, doc, _ = sample.stored(exp, folder(p), keys, name, p['reuseBed'], build, 'bed')
    exp.newScene()
    ballast, steel = materials(p, p['young'])
    rig = Rig(walls(p, steel), ballast, steel)
    sample.reload(exp, doc, ballast, p['damping'])
    return rig, doc['top'], doc['porosity'], doc['escaped'], path


def buildBed(exp):
    """The box, the bed in layers, friction and stiffness restored; returns (the bed's height [m] under the last
    press, its porosity [-], the grains that left the box)."""
    p = exp.p
    exp.newScene()
    ballast, steel = materials(p, p['prepYoung'])
    ballast.frictionAngle = p['depFriction']
    rig = Rig(walls(p, steel), ballast, steel)
    O.engines = engines(p['prepDamping'], p['law'], rolling(p))
    area = p['boxLength'] * p['boxWidth']
    top = sample.layers(exp, sample.BoxShape(p['boxLength'], p['boxWidth']), area, p['bedDepth'], ballast,
                        lambda force: press(exp, rig, force))
    escaped = [b.id for b in grains.spheres() if not inside(p, b.state.pos)]
    grains.erase(escaped)
    preparation.restoreFriction(ballast, p['friction'], p['steelFriction'])
    preparation.Stiffener().run(exp, [(ballast, p['young']), (steel, p['steelYoungRatio'] * p['young'])],
                                p['young'] / p['prepYoung'])
    exp.phases.run('settle', lambda: grains.unbalanced() < 0.02, tEnd=O.time + 0.05, extra=grains.restInfo)
    r = grains.arrays()[1]
    porosity = 1 - float(np.sum(sphereVolume(r))) / (area * top)
    return top, porosity, len(escaped)


def inside(p, x):
    return abs(x[0]) < p['boxLength'] / 2 and abs(x[1]) < p['boxWidth'] / 2 and x[2] > 0


def press(exp, rig, force):
    """A steel plate over the whole box pressed with `force` [N] onto the layer until it rests; removed
    after. Returns the height of its underside [m] at rest."""
    p = exp.p
    return sample.pressLayer(exp, rig.steel, p['steelDensity'] * p['boxLength'] * p['boxWidth'] * PLATE_THICKNESS, force)


def crib(exp, zBase):
    """Crib ballast beside the sleeper (cribDepth above its underside at zBase [m]): a loose cloud of grains over
    each side of the box (solidFraction of the crib's volume, from the run's seed) falls onto the bed with
    friction, as ballast tipped into the cribs, while the sleeper is held where it sits; the grains that came to
    rest on the sleeper are swept off; the others are then part of the bed. Returns how many stay."""
    p = exp.p
    sleeper = O.bodies[exp.rig.sleeper]
    held = sleeper.state.blockedDOFs
    sleeper.state.blockedDOFs = 'xyzXYZ'
    sleeper.state.vel = Vector3(0, 0, 0)
    f = sample.ClumpSample.ofScene(p).reach() if p['grain'] == 'clump' else 1.0   # a cloud of circumscribed spheres
    rMax, gap = f * p['dMax'] / 2, 0.05 * p['dMin']
    w, L, W = p['sleeperWidth'], p['boxLength'], p['boxWidth']
    side = L / 2 - w / 2                       # each crib's length along x
    top = zBase + p['cribDepth'] + p['dMax']   # the cloud starts above the crib's final top
    n = 0
    for sign in (-1, 1):
        x0, x1 = sorted((sign * (w / 2 + rMax + gap), sign * (L / 2 - rMax - gap)))
        vSolid = p['solidFraction'] * side * W * p['cribDepth']
        h = 1.5 * vSolid * f ** 3 / (sample.CLOUD_SOLID * (x1 - x0) * (W - 2 * (rMax + gap)))
        sp = pack.SpherePack()
        sp.makeCloud((x0, -W / 2 + rMax + gap, top), (x1, W / 2 - rMax - gap, top + h), rMean=f * (p['dMin'] + p['dMax']) / 4,
                     rRelFuzz=(p['dMax'] - p['dMin']) / (p['dMax'] + p['dMin']),
                     num=int(math.ceil(1.5 * vSolid / meanCubedDiameterVolume(p['dMin'], p['dMax']))),
                     seed=p['seed'] * 100 + 50 + (sign > 0))
        kept = sorted((c[2], c[0], c[1], r) for c, r in sp)
        centres, radii, vol = [], [], 0.0
        for z, x, y, rc in kept:
            r = rc / f
            if vol >= vSolid:
                break
            centres.append((x, y, z))
            radii.append(r)
            vol += float(sphereVolume(r))
        sample.place(centres, radii, exp.rig.ballast, p, p['seed'] * 100 + 50 + (sign > 0))
        n += len(radii)
    tFall = math.sqrt(2 * (top + h - zBase) / 9.81)
    exp.phases.say('crib: %d grains tipped beside the sleeper, %.3f m deep' % (n, p['cribDepth']))
    exp.phases.run('crib', tEnd=O.time + tFall, simSpan=tFall, simStart=O.time, extra=grains.restInfo)
    # the grains that came to rest on the sleeper are swept off, as a crib is levelled
    zTop = sleeper.state.pos[2] + sleeper.shape.extents[2]
    x, r, _ = grains.arrays()
    swept = grains.kind().ids()[(np.abs(x[:, 0]) <= w / 2 + r) & (x[:, 2] > zTop)].tolist()
    grains.erase(swept)
    exp.phases.run('crib', lambda: grains.unbalanced() < 0.05, tEnd=O.time + 0.05, extra=grains.restInfo)
    sleeper.state.blockedDOFs = held
    return n - len(swept)
