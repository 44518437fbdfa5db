"""Shared by the bench scripts (run under `yade -x`; they put bench/ on sys.path by hand)."""
import argparse
import time

import __main__


def best(f, repeat):
    """Smallest wall time of f over repeat calls [s]: the least disturbed measurement."""
    out = []
    for _ in range(repeat):
        t = time.perf_counter()
        f()
        out.append(time.perf_counter() - t)
    return min(out)


def bestCheck(engine, repeat):
    """Smallest wall time of one check of a ballast engine [s], as at a new step: what the engines
    cache within a step (stresses, signature) is forgotten before each call."""
    from ballast import harvest

    def check():
        harvest.invalidate()
        engine.fire()
    return best(check, repeat)


def stamped(steps):
    """Wall time of `steps` steps of the current scene [s], stamped by a PyRunner inside the simulation
    loop: O.run(wait=True) itself returns only at its next poll (tens of ms), too coarse for steps of a
    fraction of a millisecond."""
    from yade import O
    from yade.wrapper import PyRunner
    stamps = []
    __main__._benchStamp = lambda: stamps.append(time.perf_counter())
    stamp = PyRunner(command='_benchStamp()', iterPeriod=steps, initRun=True, label='benchStamp')
    O.engines = [stamp] + O.engines  # first engine: the stamps bracket whole steps
    O.run(steps + 1, True)
    O.engines = [e for e in O.engines if e.label != 'benchStamp']
    return stamps[1] - stamps[0]


def optionList(options):
    """An argparse type: a comma-separated list of the names in `options` (a bench's set-ups), in the order given;
    an unknown name is refused with the names there are."""
    def names(text):
        got = text.split(',')
        unknown = [n for n in got if n not in options]
        if unknown:
            raise argparse.ArgumentTypeError('%s unknown; options: %s' % (', '.join(unknown), ', '.join(options)))
        return got
    return names
