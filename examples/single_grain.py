"""Demo: one ballast grain squeezed between two walls until it crushes (Dubina & Eliáš, section 2).

    yade -n -x examples/single_grain.py

The top wall moves down at constant speed; the crushing engine checks every step and the grain
breaks into six fragments when its von Mises stress (eqs. 2-3) exceeds f_t = ft0 / r (eq. 4).
"""
import argparse
import math
import sys

from yade import O, utils

from ballast import sizeStrength
from ballast.engines import BallastCrushEngine
from ballast.scenes import grainBetweenWalls

argparse.ArgumentParser(prog='yade -n -x examples/single_grain.py', description=__doc__.split('\n\n')[0]).parse_args(
    sys.argv[1:])   # it takes no argument: one given is refused, not ignored

r, ft0 = 0.02, 2.0e5                      # grain radius [m], reference strength [Pa m]
g, w0, w1 = grainBetweenWalls(r=r, overlap=0.0, block=False)
O.bodies[w1].state.vel = (0, 0, -0.05)    # loading speed [m/s]
crush = BallastCrushEngine(ft0=ft0, pattern=6, iterPeriod=1, label='crush')
O.engines = O.engines + [crush]
print('grain r = %.3f m, strength f_t = ft0/r = %.3g Pa' % (r, sizeStrength(ft0, r)))
for chunk in range(200):
    O.run(100, True)
    if crush.nCrushed:
        break
    F = abs(O.forces.f(w1)[2])
    print('t = %.3e s  wall force %.3e N  sigma_e/f_t = %.3f' % (O.time, F, crush.maxStressRatio))
if not crush.nCrushed:
    raise SystemExit('the grain did not crush: check ft0')
e = crush.events[0]
print('crushed at t = %.4e s (iteration %d): sigma_e = %.9g Pa > f_t = %.9g Pa (sigma_e/f_t = 1 + %.2g)' % (
    e['t'], e['iter'], e['value'], e['strength'], e['value'] / e['strength'] - 1))
print('%d fragments %s, volume lost %.3g m^3 (%.1f %% of the grain), mass lost %.3g kg'
      % (len(e['newIds']), e['newIds'], crush.volumeLost, 100 * crush.volumeLost / (4 / 3 * math.pi * r ** 3),
         crush.massLost))
O.run(500, True)
print('after 500 more steps: %d bodies, kinetic energy %.3g J' % (len(O.bodies), utils.kineticEnergy()))
