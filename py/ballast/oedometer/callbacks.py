"""The command of oedometer callbacks saved by state format 1 (commit ba51e1d and before): refused in
one line (:mod:`ballast.runtime`)."""
from .. import runtime


def fire(piece, method):
    runtime.checkFormat()
    raise runtime.StateFormatError('ballast: this callback (%s.%s) was saved by an older version; continue it with '
                                   'commit ba51e1d or run it again' % (piece, method))
