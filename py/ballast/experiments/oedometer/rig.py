"""What the oedometer's packing builds and its loading and outputs use (section 4, Fig. 3)."""
from yade import O

from ... import runtime
from ..containers import Cylinder


@runtime.persistent('OedometerRig')
class Rig:
    """What the packing builds and the loading and the outputs use: the cylinder and the ballast and steel
    materials (FrictMat in O.materials)."""

    def __init__(self, cylinder, ballast, steel):
        self.cylinder, self.ballast, self.steel = cylinder, ballast, steel

    def state(self):
        return {'cylinder': self.cylinder.state(), 'ballast': self.ballast.id, 'steel': self.steel.id}

    @classmethod
    def fromState(cls, s, ref=None):
        return cls(Cylinder.fromState(s['cylinder']), O.materials[s['ballast']], O.materials[s['steel']])
