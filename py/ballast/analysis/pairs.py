"""Runs paired by seed: the one rule every analysis that compares two groups of runs seed by seed uses. A seed is one
realization (one stored packing or bed), so two runs of the same seed differ only by what their groups change; a
group that holds two runs of one seed would make the pair ambiguous, and is refused. No YADE."""


def oneRunPerSeed(frame, what, seed='seed', run=None):
    """`frame` (a DataFrame, a row per run, or with `run` a column naming the run of each row: several rows per run)
    itself, after checking that no seed (a column name, or a list of them: the key) holds two runs. ValueError naming
    `what`, the seed and its runs otherwise."""
    keys = [seed] if isinstance(seed, str) else list(seed)
    counts = frame.groupby(keys)[run].nunique() if run else frame.groupby(keys).size()
    twice = counts[counts > 1]
    if len(twice):
        key = twice.index[0]
        mine = frame.set_index(keys).loc[[key]]
        names = sorted(map(str, mine[run].unique())) if run else ['%d rows' % len(mine)]
        raise ValueError('%s holds %d runs of seed %s (%s): which to pair is ambiguous' % (
            what, twice.iloc[0], key, ', '.join(names)))
    return frame


def keyed(items, what):
    """{key: value} of the (key, value) pairs `items`, a key a seed (or a seed with what else tells runs apart);
    ValueError naming `what` and the key if it comes twice."""
    out = {}
    for k, v in items:
        if k in out:
            raise ValueError('%s holds 2 runs of seed %s: which to pair is ambiguous' % (
                what, '%s (%s)' % (k[0], ', '.join(map(str, k[1:]))) if isinstance(k, tuple) else k))
        out[k] = v
    return out


def bySeed(frame, what, seed='seed'):
    """`frame` indexed by its seed column (or columns), after oneRunPerSeed."""
    return oneRunPerSeed(frame, what, seed).set_index(seed)


def common(*groups):
    """The seeds (or keys) every group has, sorted: a group is a DataFrame or Series (its index), a dict (its keys),
    or any iterable of keys."""
    sets = [set(g.index if hasattr(g, 'index') and not isinstance(g, (list, tuple)) else g) for g in groups]
    return sorted(set.intersection(*sets)) if sets else []
