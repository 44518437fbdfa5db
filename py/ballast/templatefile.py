"""Clump templates from a CSV file (the experiments' ``clumpFile``; docs/grains.md, "Templates from a file"): read and
checked with the parameters, before any work. No YADE: the study runner checks a table's rows in plain Python."""
import numpy as np

from .grainparams import MAX_SPHERES


TEMPLATE_COLUMNS = ('template', 'x', 'y', 'z', 'r')


def readTemplates(path):
    """The clump templates of a CSV file, a row a member sphere: columns template (a name or number), x, y, z (its
    centre) and r (its radius), in any one length unit. Returns [(name, centres (n, 3), radii (n,))] in the order the
    templates first appear. ValueError saying what is wrong, with the file's line where a row is: unreadable, a
    column missing, a row without a template, x, y, z or r not a finite number, r <= 0, more than MAX_SPHERES spheres, or spheres that do not
    all hang together (their overlap graph is not connected: a clump is one body)."""
    import pandas as pd
    try:
        f = pd.read_csv(path)
    except (OSError, ValueError, pd.errors.ParserError) as e:   # EmptyDataError is a ValueError
        raise ValueError('not readable as CSV (%s)' % e) from None
    missing = [c for c in TEMPLATE_COLUMNS if c not in f.columns]
    if missing:
        raise ValueError('no column %s; expected the columns %s' % (', '.join(missing), ', '.join(TEMPLATE_COLUMNS)))
    if not len(f):
        raise ValueError('no rows: expected a row per member sphere')
    xyzr = f[list(TEMPLATE_COLUMNS[1:])].apply(pd.to_numeric, errors='coerce').to_numpy(float)

    def line(i):   # the file's line of row i: the header is line 1
        return int(i) + 2

    bad = np.flatnonzero(f['template'].isna().to_numpy())   # groupby would drop such rows without a word
    if len(bad):
        raise ValueError('line %d: no template' % line(bad[0]))
    bad = np.flatnonzero(~np.all(np.isfinite(xyzr), axis=1))
    if len(bad):
        raise ValueError('line %d: x, y, z and r must be finite numbers' % line(bad[0]))
    bad = np.flatnonzero(xyzr[:, 3] <= 0)
    if len(bad):
        raise ValueError('line %d: r = %g must be > 0' % (line(bad[0]), xyzr[bad[0], 3]))
    out = []
    for name, rows in f.groupby('template', sort=False).indices.items():
        c, r = xyzr[rows, :3], xyzr[rows, 3]
        if len(r) > MAX_SPHERES:
            raise ValueError('template %s: %d spheres, more than %d' % (name, len(r), MAX_SPHERES))
        if not connected(c, r):
            raise ValueError('template %s (lines %d-%d): its spheres do not all overlap into one body' % (
                name, line(rows.min()), line(rows.max())))
        out.append((name, c, r))
    return out


def connected(c, r):
    """Whether the overlap graph of the spheres is connected (every member touches the clump)."""
    seen, todo = {0}, [0]
    while todo:
        i = todo.pop()
        d = np.linalg.norm(c - c[i], axis=1)
        for j in np.nonzero(d < r + r[i])[0].tolist():
            if j not in seen:
                seen.add(j)
                todo.append(j)
    return len(seen) == len(c)
