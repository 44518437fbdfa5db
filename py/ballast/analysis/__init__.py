"""The analyses of the studies: each answers a question of the docs, on the runs ballast.study.data
reads back (a study folder or its records, as DataFrames), and names the section it serves.

For any study:
    report       a study's runs.csv, stats.csv, test.json and figures, by its experiment's declaration
                 (scripts/aggregate.py; docs/studies.md)
    effects      does the studied parameter change a result: Kruskal-Wallis, Friedman and Page within seeds
    pairs        runs paired by seed (one rule for every analysis that compares runs seed by seed)
    figures      the response against the parameter, Fig. 4 and the per-check figure of a study
    settlement   settlement against the number of cycles of cyclic studies (scripts/box_settlement.py; docs/box.md)
    jumps        cycle jumping against direct simulation (scripts/jump_validation.py; docs/cycles.md)
For one past study each (their command lines beside the tables, studies/README.md):
    mechanisms   why delta depends on T_c: the variants (studies/tc_mechanisms.py; docs/studies.md)
    halfload     the force network at Fmax/2 against f: the study of studies/halfload.table (studies/halfload.py)
    choices      the criteria's onset strengths and the options of issue 13 (studies/choices.py; docs/strength.md)
    options      the fast options of issue 25 against the paper's settings (studies/fast_options.py;
                 docs/performance.md)
    manycycles   settlement and breakage over many cycles (studies/cycles_figure.py; docs/oedometer.md)

Needs no running YADE: the runs are the study machinery's (ballast.study).
"""
