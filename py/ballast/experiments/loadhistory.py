"""The load of a cyclic experiment over one cycle (docs/box.md, "Load"; docs/triaxial.md): a sine between the
seating and the peak load at a frequency, or a history read from a CSV (a measured train passage on a sleeper, a
recorded deviator stress), repeated cycle after cycle. The box's load is a force F [N], the triaxial test's a
deviator stress q [Pa]: the same history, its column named. Plain NumPy: no YADE.

    h = LoadHistory.sine(seat=3e3, peak=40e3, f=3.0)
    h = LoadHistory.fromCsv('passage.csv')          # columns t [s] and F [N], a row per sample
    h = LoadHistory.fromCsv('q.csv', LoadHistory.DEVIATOR)   # columns t [s] and q [Pa]
    h.at(tau)                                       # the load [N] at time tau [s] since the start of cycling
    h.table()                                       # (times, forces) of one cycle for YADE's force engine

A CSV history is one cycle: it starts at t = 0, its times rise strictly, its forces are finite and not
negative, and it ends at the load it starts at (the next cycle repeats it, so a jump there would be a
blow); its first force is the seating load. Between the rows the load is interpolated linearly, as
YADE's InterpolatingDirectedForceEngine does.
"""
import csv
import io
import math

import numpy as np

from .. import textfile

SINE_SAMPLES = 2000   # [-] rows of one sine cycle: linear interpolation errs by at most (peak - seat) pi^2 / (4 N^2)
#                       (6e-7 of the amplitude)
CLOSE = 1e-3          # [-] a CSV cycle must end within CLOSE (peak - min) of the load it starts at


class LoadHistoryError(ValueError):
    """A load history that cannot be used: the message names the file and the row."""


class LoadHistory:
    """One cycle of the load: times [s] from 0 to the period, loads (forces [N] or stresses [Pa]); see the module
    doc."""

    FORCE = ('F', 'N', 'load')                   # the column, its unit and its name: the box's
    DEVIATOR = ('q', 'Pa', 'deviator stress')    # the triaxial test's

    def __init__(self, times, forces, source):
        self.times, self.forces, self.source = np.asarray(times, float), np.asarray(forces, float), source

    @classmethod
    def sine(cls, seat, peak, f):
        """F = seat + (peak - seat) (1 - cos 2 pi f tau) / 2: from the seating load up to the peak at tau = T/2 and
        back, period T = 1/f."""
        if not (0 <= seat < peak and math.isfinite(peak)) or not (f > 0 and math.isfinite(f)):
            raise LoadHistoryError('sine: expected 0 <= seat < peak and f > 0, got seat = %r N, peak = %r N, f = %r Hz'
                                   % (seat, peak, f))
        tau = np.linspace(0.0, 1.0 / f, SINE_SAMPLES + 1)
        return cls(tau, seat + (peak - seat) * 0.5 * (1 - np.cos(2 * math.pi * f * tau)), 'sine')

    @classmethod
    def fromCsv(cls, path, column=FORCE):
        """The history of a CSV file with a header naming the columns t [s] and the load's (`column`: (name, unit,
        what), FORCE by default: F [N]); other columns ignored."""
        c, unit, what = column
        try:
            text = textfile.read(path)
        except OSError as e:
            raise LoadHistoryError('loadFile: cannot read %s (%s)' % (path, e.strerror)) from None
        except textfile.NotText as e:
            raise LoadHistoryError('loadFile %s' % e) from None
        rows = csv.reader(io.StringIO(text, newline=''))
        header = next(rows, None)
        names = [h.strip() for h in header] if header else []
        if 't' not in names or c not in names:
            raise LoadHistoryError('loadFile %s: line 1 must name the columns t (time [s]) and %s (%s [%s]), got %r'
                                   % (path, c, what, unit, ','.join(names)))
        it, iF = names.index('t'), names.index(c)
        times, forces = [], []
        for line, row in enumerate(rows, start=2):
            if not row or all(not c.strip() for c in row):
                continue
            try:
                t, F = float(row[it]), float(row[iF])
            except (IndexError, ValueError):
                raise LoadHistoryError('loadFile %s: line %d: expected numbers in columns t and %s, got %r'
                                       % (path, line, c, ','.join(row))) from None
            if not (math.isfinite(t) and math.isfinite(F)) or F < 0:
                raise LoadHistoryError('loadFile %s: line %d: t = %r s, %s = %r %s: expected finite values, %s >= 0'
                                       % (path, line, t, c, F, unit, c))
            if not times and t != 0:
                raise LoadHistoryError('loadFile %s: line %d: the history starts at t = 0, got t = %r s'
                                       % (path, line, t))
            if times and t <= times[-1]:
                raise LoadHistoryError('loadFile %s: line %d: t = %r s does not rise (the row before: %r s)'
                                       % (path, line, t, times[-1]))
            times.append(t)
            forces.append(F)
        if len(times) < 2:
            raise LoadHistoryError('loadFile %s: %d row(s) of data; a cycle needs at least 2' % (path, len(times)))
        span = max(forces) - min(forces)
        if span <= 0:
            raise LoadHistoryError('loadFile %s: the %s never changes (%s = %r %s throughout): not a load cycle'
                                   % (path, what, c, forces[0], unit))
        if abs(forces[-1] - forces[0]) > CLOSE * span:
            raise LoadHistoryError('loadFile %s: line %d: the cycle ends at %s = %r %s but starts at %r %s; the next '
                                   'cycle repeats it, so it must end where it starts' % (
                                       path, line, c, forces[-1], unit, forces[0], unit))
        return cls(times, forces, path)

    @property
    def period(self):
        """The cycle's duration [s]."""
        return float(self.times[-1])

    @property
    def seat(self):
        """The seating load [N, Pa]: the load at the start (and end) of a cycle."""
        return float(self.forces[0])

    @property
    def peak(self):
        """The largest load of the cycle [N, Pa]."""
        return float(np.max(self.forces))

    def at(self, tau):
        """The load [N, Pa] at time tau [s] since cycling began (cycle after cycle), interpolated linearly."""
        return np.interp(np.mod(tau, self.period), self.times, self.forces)

    def table(self):
        """(times [s], forces [N]) of one cycle, as lists for InterpolatingDirectedForceEngine."""
        return list(map(float, self.times)), list(map(float, self.forces))
