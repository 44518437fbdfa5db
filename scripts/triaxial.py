#!/usr/bin/python3
# -*- coding: utf-8 -*-
"""The cyclic triaxial test (docs/triaxial.md): a crushable ballast specimen under a membrane at the confining
pressure, the deviator cycled.

    yade -n -x scripts/triaxial.py --cycles 3            the defaults (300 x 600 mm, p' 60 kPa, q 45-230 kPa at 5 Hz)
    yade -n -x scripts/triaxial.py --quasiStatic 1e-3 --reference ../shared/data/cyclic-triaxial-p60-q230-f5-axial.csv

Results go to <results>/<run id>/: cycles.csv, samples.csv, grading.csv, summary.json, strains.png and the states.
The experiment is the library ballast.experiments.triaxial.
"""
import sys

from ballast.experiments.triaxial.commandline import main

if __name__ == '__main__':
    status = main()
    if status:
        sys.exit(status)
