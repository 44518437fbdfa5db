# -*- coding: utf-8 -*-
"""Oedometric test of crushable railway ballast (R. Dubina and J. Eliáš, sections 4 and 5).

    yade -n -x scripts/oedometer.py                 one realization with the defaults, then exit
    yade -n -x scripts/oedometer.py --f 2 --pattern 14   any parameter by name (see --help)
    yade scripts/oedometer.py ...                   the same, then stay in YADE's session: `run` is the
                                                    experiment (ballast.oedometer.Oedometer)
    yade-batch --log 'logs/$.@.log' TABLE scripts/oedometer.py   a realization per table row, same
                                                    names; the logs in logs/ (make it first)
    yade -n -x scripts/oedometer.py --rebuild RUNDIR   the outputs of a killed run up to its last state

Numbers are written in decimal (1e6, 0.5), flags as 0 or 1; an option is given once.

The experiment is the library ballast.oedometer; this is its command line. Results go to
<results>/<run id>/ (fd.csv, checks.csv, events.csv, grains.csv, summary.json, fd.png, the states
state-start.yade.gz and state-end.yade.gz, run.json, optional vtk/ with oedometer.pvd). See docs/oedometer.md.
"""
from ballast.oedometer.commandline import main

if __name__ == '__main__':
    run, summary = main()
