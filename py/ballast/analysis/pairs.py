"""Runs paired by seed: the one rule every analysis that compares two groups of runs seed by seed uses. A seed is one
realization (one stored packing or bed), so two runs of the same seed differ only by what their groups change; a
group that holds two runs of one seed would make the pair ambiguous, and is refused. No YADE."""
import re


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


def parseSelection(text, what):
    """A study's runs as a command line names them: 'PATH', or 'PATH[NAME=VALUE ...]' for its runs with those
    parameter values (a study whose table holds the rows of both sides). Returns (PATH, {NAME: VALUE}), a value a
    float where it reads as a number, else text. ValueError (its message begins with `what`) for a selection that is
    not NAME=VALUE pairs."""
    m = re.fullmatch(r'(.+)\[(.*)\]', text)
    if m is None:
        return text, {}
    path, pairs = m.group(1), m.group(2).split()
    if not pairs or not all(re.fullmatch(r'[A-Za-z_]\w*=\S+', x) for x in pairs):
        raise ValueError('%s: %r: a selection is PATH[NAME=VALUE ...], e.g. docs/studies/qs-box-crush'
                         '[quasiStatic=1e-3]' % (what, text))
    return path, {k: _number(v) for k, v in (x.split('=', 1) for x in pairs)}


def _number(text):
    """A selection's value as a run's parameter holds it: a number as a float, else text."""
    try:
        return float(text)
    except ValueError:
        return text
