"""Shared by the bench scripts (run under `yade -x`, which puts bench/ on sys.path by hand)."""
import time


def best(f, repeat):
    """Smallest wall time of f over repeat calls [s]: the least disturbed measurement."""
    out = []
    for _ in range(repeat):
        t = time.perf_counter()
        f()
        out.append(time.perf_counter() - t)
    return min(out)
