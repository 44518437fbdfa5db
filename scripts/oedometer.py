# -*- coding: utf-8 -*-
"""Oedometric test of crushable railway ballast (R. Dubina and J. Eliáš, sections 4 and 5).

    yade scripts/oedometer.py                       one realization with the defaults
    yade scripts/oedometer.py --f 2 --pattern 14    any parameter by name (see --help)
    yade-batch TABLE scripts/oedometer.py           one realization per table row, same names
    yade -x scripts/oedometer.py ...                the same, then stay in the session: `run` is the
                                                    experiment (ballast.oedometer.Oedometer)

The experiment is the library ballast.oedometer; this is its command line. Results go to
<results>/<run id>/ (fd.csv, checks.csv, events.csv, grains.csv, summary.json, fd.png, the states
state-start.yade.gz and state-end.yade.gz, optional vtk/ with oedometer.pvd). See docs/oedometer.md.
"""
from ballast.oedometer.commandline import main

if __name__ == '__main__':
    run, summary = main()
