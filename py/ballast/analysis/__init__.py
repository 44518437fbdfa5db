"""The analyses of the studies: each answers a question of the docs, on the runs ballast.study.data
reads back (a study folder or its records, as DataFrames), and names the section it serves.

    report       a study's runs.csv, stats.csv, test.json and figures (scripts/aggregate.py; docs/studies.md)
    effects      does the studied parameter change a result: Kruskal-Wallis, Friedman and Page within seeds
    figures      Fig. 4 and Fig. 5 of the paper and the per-check figure of a study
    checks       what the per-check log says: the onset, the force network at half the peak load
    mechanisms   why delta depends on T_c: the variants (scripts/tc_mechanisms.py; docs/studies.md)
    halfload     the force network at Fmax/2 against f: the study of studies/halfload.table (scripts/halfload.py)
    choices      the criteria's onset strengths and the options of issue 13 (scripts/choices.py; docs/strength.md)
    manycycles   settlement and breakage over many cycles (scripts/cycles_figure.py; docs/oedometer.md)

Needs no running YADE: the runs are the study machinery's (ballast.study).
"""
