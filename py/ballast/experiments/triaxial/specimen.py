"""The triaxial specimen (docs/triaxial.md, "Set-up"): built in a rigid mould of steel facets on a steel base, in
`layers` layers, each a loose cloud of grains falling frictionless onto the layer below and pressed through a plate
at layerPressure until it rests, then friction restored and the grains stiffened to the true modulus; stored (the
sample store of :mod:`ballast.experiments.sample`) so a seed gives the same specimen. For the test the stored grains
are placed in the mould again, the top platen laid on them, and the mould is taken off once the membrane holds
them (:mod:`.membrane`)."""
import math
import os

import numpy as np
from yade import O, Vector3, utils

from ... import runtime
from ...geometry import sphereVolume
from .. import grains, preparation, sample
from ..containers import Cylinder
from ..scene import STEEL_COLOR, STEEL_MASK, engines, materials, rolling
from .parameters import layersKey, specimenKey

PLATE_THICKNESS = 0.02   # [m] the preparation press plate's mass: steel of this thickness over the mould
MOULD_HEIGHT = 3.0       # [-] the mould's height over the specimen's: a layer's cloud starts up to about twice as high


@runtime.persistent('TriaxialRig')
class Rig:
    """The cell's bodies: the base (a wall at z = 0), the top platen (a wall pressing down, free along z), the mould's
    facets while it is on (none after), and the materials."""

    def __init__(self, base=None, top=None, mould=(), ballast=None, steel=None):
        self.base, self.top, self.mould, self.ballast, self.steel = base, top, list(mould), ballast, steel

    def state(self):
        return {'base': self.base, 'top': self.top, 'mould': list(self.mould), 'ballast': self.ballast.id,
                'steel': self.steel.id}

    @classmethod
    def fromState(cls, s, ref=None):
        return cls(s['base'], s['top'], s['mould'], O.materials[s['ballast']], O.materials[s['steel']])

    def removeMould(self):
        for i in self.mould:
            O.bodies.erase(i)
        self.mould = []


def folder(p):
    return p['specimenDir'] or os.path.join(p['results'], 'specimens')


def mould(p, steel):
    """The mould's side facets and the base wall at z = 0: (facet ids, base id)."""
    cyl = Cylinder(p, steel, height=MOULD_HEIGHT * p['height'])   # above the falling clouds: no grain jumps the rim
    return [i for i in cyl.ids if i != cyl.bottom], cyl.bottom


def prepare(exp):
    """The specimen of the run's seed and specimen parameters in its mould under the top platen: loaded from the store
    (specimenDir) if it is there and reuseSpecimen, else built and stored. Returns (Rig, porosity [-] in the mould,
    the stored file)."""
    p = exp.p
    keys, name = specimenKey(p)

    def build():
        return {'porosity': buildSpecimen(exp)}
    path, doc, _ = sample.stored(exp, folder(p), keys, name, p['reuseSpecimen'], build, 'specimen')
    exp.newScene()
    ballast, steel = materials(p, p['young'])
    facets, base = mould(p, steel)
    rig = Rig(base, None, facets, ballast, steel)
    sample.reload(exp, doc, ballast, p['damping'])
    top = utils.wall(grains.top(), axis=2, sense=-1, material=steel, color=STEEL_COLOR, mask=STEEL_MASK)
    top.state.blockedDOFs = 'xyXYZ'
    top.state.mass = p['platenMass']
    top.state.inertia = Vector3(1, 1, 1)   # a wall has none; its rotations are blocked, but Newton divides by it
    top.state.isDamped = False   # what acts on it is the load, as on the box's sleeper
    top.dynamic = True
    rig.top = O.bodies.append(top)
    return rig, doc['porosity'], path


def layers(exp, p, steel, ballast, R, area):
    """The specimen's layers deposited and pressed, the grains that left the mould taken away: the last top [m]."""
    mass = p['steelDensity'] * area * PLATE_THICKNESS
    toHeight = (lambda z: sample.pressLayerTo(exp, steel, mass, z, area, p['layerPressure'])) \
        if p['compaction'] == 'height' else None
    top = sample.layers(exp, sample.CylinderShape(R), area, p['height'], ballast,
                        lambda force: sample.pressLayer(exp, steel, mass, force), toHeight)
    # a grain that jumped the mould's rim while the layers fell lies on the base outside: not part of the specimen
    escaped = [b.id for b in grains.spheres() if math.hypot(b.state.pos[0], b.state.pos[1]) > R or b.state.pos[2] < 0]
    grains.erase(escaped)
    if escaped:
        exp.phases.say('%d grains left the mould while falling: taken away' % len(escaped))
    return top


def buildSpecimen(exp):
    """The mould, the specimen's layers (built, and with depFriction 0 stored under layersKey, or those stored for a
    specimen that differs in young or friction only), friction and stiffness restored; returns its porosity [-] in the
    mould."""
    p = exp.p
    exp.newScene()
    ballast, steel = materials(p, p['prepYoung'])
    ballast.frictionAngle = p['depFriction']
    facets, base = mould(p, steel)
    O.engines = engines(p['prepDamping'], p['law'], rolling(p))
    R = p['diameter'] / 2
    area = math.pi * R ** 2
    if p['depFriction'] == 0:
        # frictionless layers at rest are their positions (lost: the residual velocities), stored in the sample store;
        # with depFriction > 0 their contacts' shear history would be lost too, and the grains slide when it is (a
        # reused specimen's grains moved 6.9 mm against a fresh build's 3.0 mm): such layers are built every time
        keys, name = layersKey(p)
        _, doc, reused = sample.stored(exp, folder(p), keys, name, p['reuseSpecimen'],
                                       lambda: {'top': layers(exp, p, steel, ballast, R, area)}, 'layers')
        if reused:
            sample.placeStored(doc, ballast)
            # one step at the soft modulus makes the contacts: the stiffener ramps those it finds, and a contact first
            # made at the true modulus would push the soft overlaps apart young / prepYoung times harder (a 2 cm kick)
            O.dt = preparation.PREP_DT_SAFETY * grains.kind().pWaveTimeStep()
            O.step()
        top = doc['top']
    else:
        top = layers(exp, p, steel, ballast, R, area)
    preparation.restoreFriction(ballast, p['friction'], p['steelFriction'])
    preparation.Stiffener().run(exp, [(ballast, p['young']), (steel, p['steelYoungRatio'] * p['young'])],
                                p['young'] / p['prepYoung'])
    exp.phases.run('settle', lambda: grains.unbalanced() < 0.02, tEnd=O.time + 0.05, extra=grains.restInfo)
    r = grains.arrays()[1]
    return 1 - float(np.sum(sphereVolume(r))) / (area * top)
