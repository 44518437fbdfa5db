"""Instruction counts (valgrind's callgrind: repeatable, unlike wall time) of YADE steps with and
without the ballast engines, on the hexagonal packing of bench/bench_checks.py.

    bench/profile_checks.sh                 (runs every variant under callgrind and prints the table)
    yade -n -x bench/profile_checks.py VARIANT [GRAINS] [STEPS]

VARIANT: plain (no ballast engine), crush (crushing checked every step), both (crushing and abrasion
every step), bothFull (the same, the abrasion prefilter off). callgrind counts only inside
Scene::moveToNextTimeStep (--toggle-collect), so start-up and scene building are left out.
"""
import os
import sys

from yade import O

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))  # bench/
from bench_checks import hcpBox  # noqa: E402

from ballast.engines import BallastAbrasionEngine, BallastCrushEngine  # noqa: E402

VARIANTS = ('plain', 'crush', 'both', 'bothFull')
variant = sys.argv[1] if len(sys.argv) > 1 else 'both'
grains = int(sys.argv[2]) if len(sys.argv) > 2 else 200
steps = int(sys.argv[3]) if len(sys.argv) > 3 else 100
if variant not in VARIANTS or grains < 10 or steps < 1:
    sys.exit('profile_checks.py: VARIANT must be one of %s (got %r), GRAINS >= 10, STEPS >= 1' % (', '.join(VARIANTS), variant))
hcpBox(grains)
# strengths no grain reaches, so that every variant steps through the same scene: a crushing check
# costs the same whatever the stresses; an abrasion check with the prefilter then reads no contact
# (its best case), without it all contacts (its worst case)
if variant != 'plain':
    O.engines = O.engines + [BallastCrushEngine(ft0=1e30, iterPeriod=1)]
if variant in ('both', 'bothFull'):
    O.engines = O.engines + [BallastAbrasionEngine(strength=1e30, prefilter=variant == 'both', iterPeriod=1)]
O.run(steps, True)
print('profile_checks: %s, %d bodies, %d contacts, %d steps' % (variant, len(O.bodies), O.interactions.countReal(), steps))
