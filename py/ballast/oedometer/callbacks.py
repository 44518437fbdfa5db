"""The PyRunners of the oedometer call the live experiment through this module, never through names
in ``__main__``. In a fresh process after ``O.load()`` the first callback rebuilds the experiment
from the state it saved in ``O.tags`` (see :meth:`Oedometer.save`)."""

_live = {'experiment': None}


def command(piece, method):
    """The PyRunner command that calls experiment.<piece>.<method>()."""
    return 'import ballast.oedometer.callbacks as _oc; _oc.fire(%r, %r)' % (piece, method)


def setLive(experiment):
    _live['experiment'] = experiment


def live():
    """The experiment of this scene: the one running, else the one saved in O.tags (rebuilt)."""
    exp = _live['experiment']
    if exp is None or not exp.ownsScene():
        from .experiment import Oedometer
        exp = Oedometer.fromScene()
    return exp


def fire(piece, method):
    exp = live()
    getattr(exp if piece == 'experiment' else getattr(exp, piece), method)()
