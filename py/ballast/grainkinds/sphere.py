"""The sphere kind, the paper's: a grain is one YADE ``Sphere`` body, free (not a clump member).

A body is a grain when its shape is exactly ``Sphere``: YADE's subclasses of it (``GridNode``, the node
of a membrane or grid) are other things and never grains. Its equivalent radius is its radius; its
stress is YADE's ``utils.bodyStressTensors`` (Love-Weber over its contacts and its own volume); it is
resized by ``utils.growParticle`` (radius, mass x f^3, inertia x f^5, its side's refR), its contacts
then by :func:`ballast.contacts.resize`. The expressions are those the engines used before this layer,
in the same order, so every decision and output keeps its bits.
"""
import numpy as np
from yade import O, Vector3, utils
from yade.wrapper import Sphere

from .. import _ballast, contacts
from ..geometry import sphereVolume
from . import GrainKind, Replaced, Resized, register


class SphereKind(GrainKind):
    name = 'sphere'
    oneSphere = True

    def isGrain(self, body):
        # exactly Sphere: a GridNode is a Sphere to Python's isinstance, but a membrane's node, not a grain
        return type(body.shape) is Sphere and not body.isClumpMember

    def radii(self, ids):
        """Radii [m] (r_eq of a sphere)."""
        return np.array([O.bodies[int(i)].shape.radius for i in ids], dtype=float)

    def volumes(self, ids):
        """4/3 pi r^3 [m^3], the array form of geometry.sphereVolume."""
        return sphereVolume(self.radii(ids))

    def volume(self, bid):
        """4/3 pi r^3 [m^3] of grain bid, the scalar form (a float's power, as the ledgers always took it)."""
        return sphereVolume(O.bodies[int(bid)].shape.radius)

    def signature(self):
        """Total volume of the scene's spheres [m^3] (YADE, C++): changes with any sphere added, erased or resized."""
        return utils.getSpheresVolume()

    def stressTensors(self):
        """YADE's per-body Love-Weber stress [Pa], by body id, converted in C++."""
        return _ballast.matricesToArray(utils.bodyStressTensors())

    def grainOf(self, bodyIds):
        """A sphere grain's contacts are its own: the ids themselves."""
        return bodyIds

    def replace(self, bid, fragments, keepMass):
        """See GrainKind.replace: erase, then utils.sphere fragments appended in the order given."""
        b = O.bodies[bid]
        st, mat, color, mask = b.state, b.material, b.shape.color, b.groupMask
        pos, vel, angVel, mass, r = Vector3(st.pos), Vector3(st.vel), Vector3(st.angVel), st.mass, b.shape.radius
        O.bodies.erase(bid)
        bodies = [utils.sphere(Vector3(x, y, z), rf, material=mat, color=color, mask=mask) for x, y, z, rf in fragments]
        if keepMass:  # denser fragments: the parent's mass; its momentum then too (centroid at its centre)
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
        rf = fragments[:, 3]
        return Replaced(newIds, rf, mask, sphereVolume(r), float(np.sum(sphereVolume(rf))), mass, newMass,
                        r ** 3 / float(np.sum(rf ** 3)))

    def resize(self, bid, factor):
        """See GrainKind.resize: utils.growParticle (bodyStressTensors reads the refR it sets), then contacts."""
        b = O.bodies[bid]
        r, mass = b.shape.radius, b.state.mass
        utils.growParticle(bid, factor, True)
        contacts.resize(bid, r, factor * r)
        return Resized(r, factor * r, sphereVolume(r), mass, b.state.mass)


register(SphereKind())
