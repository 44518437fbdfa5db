"""What every cyclic experiment reads of its grains' breakage (the box test, the triaxial test): the cycles whose
grading is read, the breakage engines of the scene and the mass they turned to dust, and the grading against the
start of cycling with Marsal's B_g, Hardin's B_r and Indraratna's BBI (ballast.grading). The experiment keeps
`initial` (the grains' sieve diameters and masses at the start of cycling) and its parameters."""
import math

from yade import O

from .. import grading as gr
from ..engines import BallastAbrasionEngine, BallastCrushEngine
from . import grains


def gradedCycle(k):
    """Cycles whose grading is read: 1, 2, 5 times the powers of ten."""
    e = 10 ** int(math.floor(math.log10(k))) if k > 0 else 1
    return k in (e, 2 * e, 5 * e)


def engines():
    """The crushing and abrasion engines of the scene."""
    return [e for e in O.engines if isinstance(e, (BallastCrushEngine, BallastAbrasionEngine))]


def counts():
    """(grains crushed, abrasions, the largest sigma / f_t of a grain that can crush at the crushing engines' last
    check: NaN without one) so far, over the scene's engines."""
    found = engines()
    crush = [e for e in found if isinstance(e, BallastCrushEngine)]
    return (sum(e.nCrushed for e in crush), sum(e.nAbraded for e in found if isinstance(e, BallastAbrasionEngine)),
            max([e.maxCrushableRatio for e in crush], default=math.nan))


def massLost():
    """The mass [kg] the crushing and abrasion engines removed from the grains (their massLost)."""
    return float(sum(e.massLost for e in engines()))


def grading(exp, cycle):
    """The grading now: {'cycle', 'passing' [%] per sieve, 'Bg', 'Br', 'BBI'} against the start of cycling."""
    d, m = grains.sieve()
    fines = massLost() if exp.p['lostAsFines'] else 0.0
    before = gr.passing(exp.initial['diameters'], exp.initial['masses'])
    now = gr.passing(d, m, fines=fines)
    return {'cycle': cycle, 'passing': now.tolist(), 'Bg': float(gr.marsal(before, now)),
            'Br': float(gr.hardin(before, now)), 'BBI': float(gr.bbi(before, now))}
