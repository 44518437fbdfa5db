"""The one sample builder every experiment with a packed bed uses: a loose cloud of grains in the
container's shape (YADE's SpherePack.makeCloud, diameters uniform in [dMin, dMax]), its deposition, a
press through a steel plate until it rests, and the store: a prepared sample is saved under a name made
from the parameters that decide it (the experiment's key) and every later run of the same key starts
from the stored grains, so a seed gives the same run. What each experiment composes of these steps is
its own (the oedometer: one fill, vibration, a press then a seating load; the box: layers, each
pressed): ``experiments/oedometer/packing.py``, ``experiments/box/bed.py``.

The container's shape enters the cloud only, through :class:`CylinderShape` and :class:`BoxShape`
(where the cloud is made, how many grains to ask of makeCloud); the container's bodies are
:mod:`.containers`. Grains are placed and stored as spheres [x, y, z, r] (the paper's grain), or with grain 'clump'
as clumps of volume-equivalent radius r (:mod:`.clumpsample`: the templates and each clump's template, orientation,
centre and r are stored besides)."""
import json
import math
import os
import time

import numpy as np
from yade import O, Vector3, pack, utils

from ..geometry import meanCubedDiameterVolume, sphereVolume
from ..runfiles import writeAtomic
from . import grains, polyhedronsample, preparation
from .clumpsample import ClumpSample
from .scene import GRAIN_MASK, STEEL_MASK, sceneEngines

CLOUD_SOLID = 0.3            # [-] solid fraction of a falling cloud: grains fall freely
PRESS_STILL = (0.03, 1e-5)   # ([s], [m]): a press ends when its plate moved less than this over that time
PRESS_TIME = (0.05, 1.0)     # [s] shortest and longest press
CLOUD_ATTEMPTS = 6           # makeCloud in a box 1.3 times taller each time it cannot place every grain


class CylinderShape:
    """A cylinder of inner radius Rin [m] around the z axis: the cloud fills the square around it and keeps the
    grains whose centre is within Rin - rMax - gap of the axis (the square loses 1 - pi/4 of them)."""

    def __init__(self, Rin):
        self.Rin = Rin

    def region(self, vSolid, rMax, gap, zBottom, grainVolume):
        """(lower corner, upper x and y, height [m], grains to ask of makeCloud) of the cloud holding vSolid [m^3]
        of grains of mean volume grainVolume [m^3]."""
        Rc = self.Rin - rMax - gap
        h = 1.25 * vSolid / (CLOUD_SOLID * math.pi * Rc ** 2)
        return (-Rc, -Rc, zBottom + rMax + gap), (Rc, Rc), h, int(math.ceil(1.25 * vSolid / grainVolume * 4 / math.pi))

    def keeps(self, c, rMax, gap):
        return math.hypot(c[0], c[1]) < self.Rin - rMax - gap


class BoxShape:
    """A box of inner length [m] (x) and width [m] (y) centred on the z axis: the cloud fills it, held rMax + gap
    off its walls (makeCloud falls short of CLOUD_SOLID between close walls: a taller cloud)."""

    def __init__(self, length, width):
        self.length, self.width = length, width

    def region(self, vSolid, rMax, gap, zBottom, grainVolume):
        a, b = self.length / 2 - rMax - gap, self.width / 2 - rMax - gap
        h = 1.5 * vSolid / (CLOUD_SOLID * 4 * a * b)
        return (-a, -b, zBottom + rMax + gap), (a, b), h, int(math.ceil(1.2 * vSolid / grainVolume))

    def keeps(self, c, rMax, gap):
        return True


def cloud(shape, dMin, dMax, vSolid, seed, zBottom=0.0):
    """Grains of total volume vSolid [m^3] in a loose cloud (solid fraction CLOUD_SOLID) in `shape` above zBottom
    [m], placed without overlap by makeCloud (radii uniform in [dMin/2, dMax/2]), the lowest kept until vSolid is
    reached. Returns (centres (n, 3) [m], radii [m], the cloud's top [m])."""
    rMin, rMax = dMin / 2, dMax / 2
    gap = 0.05 * dMin
    lo, hi, h, num = shape.region(vSolid, rMax, gap, zBottom, meanCubedDiameterVolume(dMin, dMax))
    for attempt in range(CLOUD_ATTEMPTS):  # a narrow container holds big grains at a lower solid fraction
        sp = pack.SpherePack()
        made = sp.makeCloud(lo, (hi[0], hi[1], lo[2] + h), rMean=(rMin + rMax) / 2,
                            rRelFuzz=(rMax - rMin) / (rMax + rMin), num=num, seed=seed)
        if made == num:
            break
        h *= 1.3
    else:
        raise RuntimeError('cloud: makeCloud placed %d of %d grains' % (made, num))
    kept = sorted((c[2], c[0], c[1], r) for c, r in sp if shape.keeps(c, rMax, gap))
    z, x, y, r = (np.array(v) for v in zip(*kept))
    n = int(np.searchsorted(np.cumsum(sphereVolume(r)), vSolid)) + 1
    if n > len(r):
        raise RuntimeError('cloud: %.3g m^3 of grains asked, %.3g placed' % (vSolid, np.sum(sphereVolume(r))))
    return np.column_stack([x[:n], y[:n], z[:n]]), r[:n], float(np.max(z[:n] + r[:n]))


def grainCloud(p, shape, vSolid, seed, zBottom=0.0):
    """cloud() of p's grains; with grain 'clump' or 'polyhedron' a cloud of their circumscribed spheres (the
    templates' reach, or polyhedronsample.REACH, times the sizes, the volume in proportion) whose radii are then the
    grains' r_eq: they are placed without overlap, off the walls."""
    if p['grain'] not in ('clump', 'polyhedron'):
        return cloud(shape, p['dMin'], p['dMax'], vSolid, seed, zBottom)
    f = ClumpSample.ofScene(p).reach() if p['grain'] == 'clump' else polyhedronsample.REACH
    x, r, top = cloud(shape, f * p['dMin'], f * p['dMax'], f ** 3 * vSolid, seed, zBottom)
    return x, r / f, top


def place(centres, radii, material, p=None, seed=0):
    """The grains appended to the scene, in the order given (their ids follow it): spheres, or with p['grain'] 'clump'
    clumps of the scene's templates (built from p on first need) turned at random from seed, or with 'polyhedron'
    the kind's polyhedra drawn from seed (polyhedronsample.place)."""
    if p is not None and p['grain'] == 'clump':
        ClumpSample.ofScene(p).place(centres, radii, material, seed)
        return
    if p is not None and p['grain'] == 'polyhedron':
        polyhedronsample.place(centres, radii, material, seed)
        return
    for c, r in zip(centres, radii):
        O.bodies.append(utils.sphere(tuple(float(v) for v in c), float(r), material=material, mask=GRAIN_MASK))


def deposit(exp, tFall):
    """The grains fall for tFall [s] of simulated time, with progress lines."""
    exp.phases.run('deposit', tEnd=O.time + tFall, simSpan=tFall, simStart=O.time, extra=grains.restInfo)


def press(exp, steel, mass, force, mark=None):
    """A steel plate (a wall, free along z only, of `mass` [kg]) laid on the grains' top and pressed down with
    `force` [N] until it rests (PRESS_STILL, within PRESS_TIME), or until it reaches the height `mark` [m] if given.
    Returns its id: the caller keeps or erases it."""
    plate = utils.wall(grains.top(), axis=2, sense=-1, material=steel, mask=STEEL_MASK)
    plate.state.blockedDOFs = 'xyXYZ'
    plate.state.mass = mass
    plate.state.inertia = Vector3(1, 1, 1)  # a wall has none; its rotations are blocked, but Newton divides by it
    plate.dynamic = True
    pid = O.bodies.append(plate)
    O.forces.setPermF(pid, Vector3(0, 0, -force))
    tShort, tLong = PRESS_TIME
    t0 = O.time
    rests = preparation.still(pid, *PRESS_STILL, after=t0 + tShort, unbalanced=0.01)
    if mark is None:
        exp.phases.run('press', rests, tEnd=t0 + tLong,
                       extra=lambda: 'plate at %.4f m  %s' % (O.bodies[pid].state.pos[2], grains.restInfo()))
    else:   # checked often: the plate should stop near its mark
        exp.phases.run('press', lambda: O.bodies[pid].state.pos[2] <= mark or rests(), tEnd=t0 + tLong, checkEvery=20,
                       extra=lambda: 'plate at %.4f m, its mark %.4f m  %s' % (O.bodies[pid].state.pos[2], mark,
                                                                              grains.restInfo()))
    return pid


def layers(exp, shape, area, depth, ballast, pressLayer, toHeight=None):
    """A bed or specimen of `depth` [m] over `area` [m^2] in exp.p['layers'] layers: each a cloud in `shape` of
    solidFraction of its share of the volume (seed: exp.p['seed'] * 100 + the layer), falling onto the layer below,
    then pressed at layerPressure by pressLayer(force [N]), which returns the layer's top [m], or with toHeight
    compacted to its share of the depth by toHeight(z [m]), which returns (the top [m], the pressure then [Pa]).
    Returns the last top."""
    p, top = exp.p, 0.0
    for k in range(p['layers']):
        pos, rad, cloudTop = grainCloud(p, shape, p['solidFraction'] * area * depth / p['layers'], p['seed'] * 100 + k,
                                        top)
        place(pos, rad, ballast, p, p['seed'] * 100 + k)
        if k == 0:
            O.dt = preparation.PREP_DT_SAFETY * utils.PWaveTimeStep()
        tFall = math.sqrt(2 * (cloudTop - top) / 9.81)
        exp.phases.say('layer %d of %d: %d grains falling from up to %.3f m' % (k + 1, p['layers'], len(rad), cloudTop))
        deposit(exp, tFall)
        if toHeight is None:
            top = pressLayer(p['layerPressure'] * area)
            exp.phases.say('layer %d pressed at %.3g kPa: top at %.4f m' % (k + 1, p['layerPressure'] / 1e3, top))
        else:
            mark = (k + 1) * depth / p['layers']
            top, pressure = toHeight(mark)
            exp.phases.say('layer %d compacted to %.4f m (its mark %.4f m), carrying %.3g kPa there%s' % (
                k + 1, top, mark, pressure / 1e3, ' (it lay below: denser than solidFraction)' if top < mark else
                ' (refusal: the mark not reached at layerPressure)' if top > mark + 1e-9 else ''))
    return top


def pressLayerTo(exp, steel, mass, zTarget, area, pressure):
    """A layer compacted to a height, as a laboratory compacts a specimen's layers to marks on the mould
    (undercompaction, Ladd 1978) with a given effort: the plate of press() pressed down at `pressure` [Pa] (area
    [m^2]) until it rests or reaches zTarget [m], where it is stopped and held until the grains rest; then taken
    away. Returns (the plate's height then [m], the pressure the grains carry on it then [Pa]): above zTarget where
    the effort does not pack the grains so densely (refusal); a layer resting below zTarget (denser than asked) is
    not touched: (its top, 0)."""
    x, r, _ = grains.arrays()
    top = float(np.max(x[:, 2] + r))
    if top <= zTarget:
        return top, 0.0
    pid = press(exp, steel, mass, pressure * area, mark=zTarget)
    b = O.bodies[pid]
    O.forces.setPermF(pid, Vector3(0, 0, 0))   # a permanent force outlives its body in the force container
    if b.state.pos[2] <= zTarget:   # at the mark: held there (a fixed plate) while the grains come to rest
        b.dynamic = False
        b.state.vel = Vector3(0, 0, 0)
        b.state.pos = Vector3(b.state.pos[0], b.state.pos[1], zTarget)
        exp.phases.run('hold', lambda: grains.unbalanced() < 0.02, tEnd=O.time + PRESS_TIME[1], checkEvery=100,
                       extra=grains.restInfo)
        z, p = zTarget, abs(float(O.forces.f(pid)[2])) / area
    else:
        z, p = float(b.state.pos[2]), pressure
    O.bodies.erase(pid)
    return z, p


def pressLayer(exp, steel, mass, force):
    """press(), then the plate taken away (a layer of a bed or a specimen pressed): the height of its underside [m]
    at rest."""
    pid = press(exp, steel, mass, force)
    top = float(O.bodies[pid].state.pos[2])
    O.forces.setPermF(pid, Vector3(0, 0, 0))   # a permanent force outlives its body in the force container
    O.bodies.erase(pid)
    return top


# ---------------------------------------------------------------------------- the store
def store(path, key, exp, **extra):
    """The grains of the scene saved to `path` (JSON, written atomically: concurrent runs of the same key never
    see half a file) with the key that decides them, who made them and `extra` (what the experiment needs back).
    Clump grains: their centres of mass and r_eq, and what rebuilds them (ClumpSample.document)."""
    x, r = grains.arrays()[:2]
    os.makedirs(os.path.dirname(path) or '.', exist_ok=True)
    doc = dict({'key': key, 'created': time.strftime('%Y-%m-%dT%H:%M:%S'), 'runId': exp.runId,
                'steps': dict(exp.phases.steps), 'wallSeconds': dict(exp.phases.wall)}, **extra)
    doc['grains'] = [[repr(float(v)) for v in (xi[0], xi[1], xi[2], ri)] for xi, ri in zip(x, r)]
    clumps = ClumpSample.current() if grains.kind().name == 'clump' else None
    if clumps is not None:
        doc.update(clumps.document())
    if grains.kind().name == 'polyhedron':   # the shapes: their vertices
        doc.update(polyhedronsample.document(grains.kind().ids()))
    writeAtomic(path, json.dumps(doc))
    return len(r)


def stored(exp, folder, key, name, reuse, build, what='sample'):
    """The stored sample `name` in `folder`: built by build() and stored if it is not there or not reused (build
    returns the extra fields to keep), then read. Returns (its path, its document, whether it was reused)."""
    path = os.path.join(folder, name)
    reused = bool(reuse and os.path.exists(path))
    if reused:
        exp.phases.say('%s: reusing %s' % (what, path))
    else:
        n = store(path, key, exp, **(build() or {}))
        exp.phases.say('%s: %d grains saved to %s' % (what, n, path))
    with open(path) as fh:
        return path, json.load(fh), reused


def placeStored(doc, ballast):
    """The grains of a stored document placed in the scene, of material ballast, at rest: spheres, clumps (the key
    holds grain, so the scene's kind is the document's) or polyhedra."""
    if 'clumps' in doc:
        ClumpSample.fromDocument(doc).rebuild(doc, ballast)
    elif 'polyhedra' in doc:
        polyhedronsample.rebuild(doc, ballast)
    else:
        g = np.array([[float(v) for v in row] for row in doc['grains']]).reshape(-1, 4)
        place(g[:, :3], g[:, 3], ballast)


def reload(exp, doc, ballast, damping, settleTime=0.01):
    """The stored grains placed in the scene (whose container and materials the caller has built), the engine
    chain with the loading damping, the step of eq. 5, and a short settling: contacts re-form with the stored
    overlaps, only their shear and rolling history is lost."""
    p = exp.p
    O.engines = sceneEngines(p, damping)
    placeStored(doc, ballast)
    O.dt = p['dtSafety'] * grains.kind().pWaveTimeStep()   # YADE's PWaveTimeStep() but for polyhedra
    exp.phases.run('settle', lambda: grains.unbalanced() < 0.01, tEnd=O.time + settleTime, checkEvery=100)
