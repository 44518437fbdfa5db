"""The engine chain of the current scene, for every experiment: NewtonIntegrator, engines put just
before it (a plate's force or control, a time stepper), and an engine by its label."""
from yade import O
from yade.wrapper import NewtonIntegrator


def newton():
    return next(e for e in O.engines if isinstance(e, NewtonIntegrator))


def insertBeforeNewton(engines):
    """Put engines between the interaction loop and NewtonIntegrator."""
    chain = list(O.engines)
    k = next(i for i, e in enumerate(chain) if isinstance(e, NewtonIntegrator))
    O.engines = chain[:k] + list(engines) + chain[k:]


def engine(label):
    """The engine with this label in O.engines, or None."""
    return next((e for e in O.engines if e.label == label), None)
