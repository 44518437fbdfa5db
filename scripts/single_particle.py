#!/usr/bin/python3
# -*- coding: utf-8 -*-
"""The single-particle crushing test (docs/calibration.md): what strength the model gives a grain.

    yade -n -x scripts/single_particle.py                     30 grains of 20.5-44.5 mm, the defaults
    yade -n -x scripts/single_particle.py --n 100 --weibullModulus 3 --criterion maxContactForce
    scripts/single_particle.py calibrate measured.csv --criterion vonMises --out calibration

Results go to <results>/<run id>/: strengths.csv, curves.csv, summary.json, weibull.png, size.png and
state-end.yade.gz. The experiment is the library ballast.experiments.single_particle.
"""
import sys

from ballast.experiments.single_particle.commandline import main

if __name__ == '__main__':
    status = main()
    if status:
        sys.exit(status)
