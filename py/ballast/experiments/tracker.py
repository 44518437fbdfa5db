"""The grain tracker every experiment with crushing and abrasion uses: per-grain state by body id, derived from
the engines' events (generation, parent, times abraded), and the colours of YADE's 3D view by that state."""
import numpy as np
from yade import O


# colours in the 3D view: original grains, fragments by generation (1, 2, 3+), abraded grains get bluer
COLOR_ORIGINAL = (0.80, 0.75, 0.60)
COLOR_GENERATION = ((1.0, 0.55, 0.0), (0.90, 0.15, 0.10), (0.55, 0.0, 0.35))
COLOR_ABRADED = (0.20, 0.45, 1.0)


class GrainStates:
    """Per-grain state by body id, derived from the engines' events: generation (0 original, 1 a
    fragment, ...), parent id (-1 for originals) and how often the grain was abraded."""

    def __init__(self):
        self.generation = np.zeros(0, dtype=np.int64)
        self.parent = np.zeros(0, dtype=np.int64)
        self.nAbraded = np.zeros(0, dtype=np.int64)
        self.seen = {}  # engine label -> events already taken in

    def _grow(self, n):
        if n > len(self.generation):
            k = n - len(self.generation)
            self.generation = np.concatenate([self.generation, np.zeros(k, dtype=np.int64)])
            self.parent = np.concatenate([self.parent, np.full(k, -1, dtype=np.int64)])
            self.nAbraded = np.concatenate([self.nAbraded, np.zeros(k, dtype=np.int64)])

    def update(self, engines):
        """Take in the new events of the engines; returns the ids whose state changed."""
        self._grow(len(O.bodies))
        changed = []
        for eng in engines:
            events = eng.events
            for e in events[self.seen.get(eng.label, 0):]:
                if e['kind'] == 'crush':
                    self._grow(max(e['newIds']) + 1)
                    for i in e['newIds']:
                        self.generation[i] = self.generation[e['id']] + 1
                        self.parent[i] = e['id']
                    changed.extend(e['newIds'])
                else:
                    self.nAbraded[e['id']] += 1
                    changed.append(e['id'])
            self.seen[eng.label] = len(events)
        return changed

    def color(self, i):
        g = int(self.generation[i])
        base = COLOR_ORIGINAL if g == 0 else COLOR_GENERATION[min(g, len(COLOR_GENERATION)) - 1]
        w = min(int(self.nAbraded[i]), 3) / 4.0  # each abrasion a quarter of the way to blue, at most 3/4
        return tuple((1 - w) * b + w * a for b, a in zip(base, COLOR_ABRADED))
