#!/usr/bin/python3
# -*- coding: utf-8 -*-
"""The box test (docs/box.md): a sleeper section on a crushable ballast bed under repeated loads.

    yade -n -x scripts/box_test.py --cycles 3                    the defaults (a 0.7 x 0.3 m box, 3-40 kN at 3 Hz)
    yade -n -x scripts/box_test.py --loadFile passage.csv --fatigue 1 --densityStep 2e-6

Results go to <results>/<run id>/: cycles.csv, samples.csv, grading.csv, crushes.csv, zones.csv,
summary.json, settlement.png, breakage.png, grading.png, the states and, with --vtk 1, boxes.pvd.
The experiment is the library ballast.experiments.box.
"""
import sys

from ballast.experiments.box.commandline import main

if __name__ == '__main__':
    status = main()
    if status:
        sys.exit(status)
