"""Fatigue of the grains (docs/fatigue.md): the state of every grain by body id, an (n, 4) array of
damage D [-], the running extreme of s = sigma_e / f_t [-], rising (1/0) and the damaging peaks;
the Basquin-Miner update is the C++ core's ``fatigueCheck``. Beside it, each grain's largest s since it was
last taken (what cycle jumping reads at each cycle's end, docs/cycles.md)."""
import numpy as np

from .. import _ballast, runtime

FRESH = (0.0, 0.0, 1.0, 0.0)  # a new grain: undamaged, no extreme yet, rising, no peak


class FatigueState:
    def __init__(self):
        self.rows = None   # (n, 4) by body id, grown on demand
        self.peaks = None  # (n,) by body id: the largest s since takePeaks, 0 if none

    def of(self, ids=None):
        """Rows of ids (default: every id up to the largest seen), fresh where never seen."""
        F = self.rows if self.rows is not None else np.empty((0, 4))
        if ids is None:
            return F.copy()
        ids = np.asarray(ids, dtype=np.int64)
        out = np.tile(FRESH, (len(ids), 1))
        known = ids < len(F)
        out[known] = F[ids[known]]
        return out

    def grown(self, ids):
        """The state array, grown to hold every id of `ids` (new rows fresh)."""
        F = self.rows
        need = int(np.max(ids)) + 1 if len(ids) else 0
        if F is None or len(F) < need:
            G = np.tile(FRESH, (max(need, 2 * (0 if F is None else len(F))), 1))
            if F is not None:
                G[:len(F)] = F
            self.rows = F = G
        return F

    def check(self, ratio, radii, ids, exponent, endurance, hysteresis, rMin):
        """One check of s = ratio for the grains ids: (crush, the damage D of each) (docs/fatigue.md)."""
        F = self.grown(ids)
        F[ids], crush = _ballast.fatigueCheck(ratio, radii, F[ids], exponent, endurance, hysteresis, rMin)
        P = self.peaksGrown(len(F))
        P[ids] = np.maximum(P[ids], ratio)
        return crush, F[ids, 0]

    def peaksGrown(self, n):
        if self.peaks is None or len(self.peaks) < n:
            P = np.zeros(n)
            if self.peaks is not None:
                P[:len(self.peaks)] = self.peaks
            self.peaks = P
        return self.peaks

    def takePeaks(self, ids):
        """The largest s of each of ids since the last take (0 if none); starts them afresh."""
        ids = np.asarray(ids, dtype=np.int64)
        P = self.peaksGrown(int(np.max(ids)) + 1 if len(ids) else 0)
        out = P[ids].copy()
        P[ids] = 0.0
        return out

    def advance(self, ids, damage, peaks):
        """Cycle jumping: the grains ids take `damage` [-] more damage and `peaks` more damaging peaks each."""
        F = self.grown(np.asarray(ids))
        F[ids, 0] += damage
        F[ids, 3] += peaks

    def fresh(self, ids):
        """Fragments start undamaged."""
        self.grown(np.asarray(ids))[ids] = FRESH
        if self.peaks is not None:
            self.peaksGrown(len(self.rows))[ids] = 0.0

    def state(self):
        """Bitwise (runtime.packArray; None before the first check)."""
        return runtime.packArray(self.rows)

    def peaksState(self):
        return runtime.packArray(self.peaks)

    def setState(self, s, peaks=None):
        """The arrays back (states saved before peaks were kept have none: they start at 0)."""
        self.rows = None if s is None else runtime.unpackArray(s).reshape(-1, 4)
        self.peaks = runtime.unpackArray(peaks)
