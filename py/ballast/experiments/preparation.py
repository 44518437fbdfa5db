"""Steps of a sample's preparation that every experiment with a packed bed takes (the oedometer's
StoredPacking, the box test's bed): friction restored after a frictionless deposition, and the grains
stiffened from the soft preparation modulus to the true one without a kick."""
import math

from yade import O

from .. import runtime
from . import chain, grains
from . import scene

STIFFEN_TIME = 0.01     # [s] simulated time over which the existing contacts are stiffened to the true modulus
PREP_DT_SAFETY = 0.5    # [-] O.dt / PWaveTimeStep() while preparing: the sample does not depend on dtSafety
STIFFENER = 'prepStiffener'


def restoreFriction(ballast, friction, steelFriction):
    """The grains' friction angle [rad] back to `friction`, in their material and in the existing contacts;
    contacts with anything else take the smaller of friction and steelFriction, as YADE's FrictPhys does."""
    ballast.frictionAngle = friction
    grain = math.tan(friction)
    steel = math.tan(min(friction, steelFriction))
    kind = grains.kind()   # a grain by its kind: a wall, a platen or a membrane's node is not one
    for i in O.interactions:
        if i.isReal:
            both = kind.isGrain(O.bodies[i.id1]) and kind.isGrain(O.bodies[i.id2])
            i.phys.tangensOfFrictionAngle = grain if both else steel


def still(bodyId, span, tol, after, unbalanced=None):
    """A phase's end test (Phases.run's done): the body `bodyId` moved less than tol [m] along z over the last
    span [s], O.time past `after` [s], and with `unbalanced` YADE's unbalanced force below it too."""
    hist = []

    def done():
        hist.append((O.time, O.bodies[bodyId].state.pos[2]))
        old = [z for t, z in hist if t <= O.time - span]
        return (O.time >= after and bool(old) and abs(hist[-1][1] - old[-1]) < tol
                and (unbalanced is None or grains.unbalanced() < unbalanced))
    return done


@runtime.persistent('Stiffener')
class Stiffener:
    """Back to the true modulus. New contacts take it from the materials at once; the existing ones are
    stiffened gradually (their stiffnesses are proportional to E under both laws) over STIFFEN_TIME with
    strong damping, so that the overlaps of the soft packing relax quasi-statically instead of kicking
    the grains with a suddenly stiffer spring. Lives only while it runs (state: none)."""

    def __init__(self):
        self._ramp = None

    def state(self):
        return {}

    @classmethod
    def fromState(cls, s, ref=None):
        return cls()

    def run(self, exp, moduli, ratio):
        """moduli: [(material, its true Young's modulus [Pa])], set at once; ratio: true over preparation modulus
        of the contacts. Uses exp.p's law and prepDamping, exp.phases for the runs."""
        p = exp.p
        for mat, young in moduli:
            mat.young = young
        O.dt = PREP_DT_SAFETY * grains.kind().pWaveTimeStep()   # YADE's PWaveTimeStep() but for polyhedra
        if ratio <= 1:
            return
        newton = chain.newton()
        newton.damping = max(p['prepDamping'], 0.8)
        # the stiffnesses that scale with E: the law's, and with rolling resistance the rolling and twisting ones
        attrs = scene.LAWS[p['law']][2] + (('kr', 'ktw') if scene.rolling(p) else ())
        soft = {(i.id1, i.id2): [(a, getattr(i.phys, a)) for a in attrs if hasattr(i.phys, a)]
                for i in O.interactions if i.isReal}
        exp.phases.say('stiffen: E %.3g -> %.3g Pa over %.3g s, dt = %.2e s' % (p['prepYoung'], p['young'],
                                                                               STIFFEN_TIME, O.dt))
        self._ramp = (O.time, ratio, soft)
        O.engines = O.engines + [runtime.callback(self, 'step', iterPeriod=100, initRun=True, label=STIFFENER)]
        exp.phases.run('stiffen', tEnd=O.time + STIFFEN_TIME)
        O.engines = [e for e in O.engines if e.label != STIFFENER]
        self._ramp = (O.time - 2 * STIFFEN_TIME, ratio, soft)
        self.step()  # the last step to the full modulus
        newton.damping = p['prepDamping']
        runtime.unregister(self)

    def step(self):
        t0, ratio, soft = self._ramp
        fac = ratio ** min((O.time - t0) / STIFFEN_TIME, 1.0)
        for i in O.interactions:
            k = soft.get((i.id1, i.id2))
            if k is not None and i.isReal:
                for a, v in k:
                    setattr(i.phys, a, v * fac)
