"""What follows a replacement (docs/strength.md, issue 13): energy snapshots of the fragments and their
neighbours a few steps after it (energyAfter) and after their growth ended (energyGrown), and with
keep='volume' the growth of the fragments back to the parent's volume over growTime."""
from yade import O, Vector3

from .. import energy
from ..densityscaling import scaleDensities
from .base import resizeGrain

ENERGY_AFTER_STEPS = 10  # energyAfter: the first check at least this many steps after a replacement ("a few steps")


class Replacements:
    def __init__(self):
        self.pending = []   # energy snapshots due: {event, key, ids, neighbours, due (step)}
        self.growing = []   # keep='volume': {ids, neighbours, t0, event, grown, ratio}

    def added(self, event, newIds, neighbours, grow, ratio):
        """A replacement recorded as events[event]: its snapshot after ENERGY_AFTER_STEPS, and its growth."""
        self.pending.append({'event': event, 'key': 'energyAfter', 'ids': newIds, 'neighbours': neighbours,
                             'due': O.iter + ENERGY_AFTER_STEPS})
        if grow:
            self.growing.append({'ids': newIds, 'neighbours': neighbours, 't0': O.time, 'event': event,
                                 'grown': 1.0, 'ratio': ratio})

    def recordEnergies(self, events):
        """The snapshots that are due, into their events. The parent's neighbours are kept because the
        fragments, inside the parent, often touch none of them at first: the energy of the same bodies
        before and after is what the replacement destroys or injects. Returns whether any was due."""
        if not self.pending:
            return False
        due = [p for p in self.pending if O.iter >= p['due']]
        for p in due:
            events[p['event']][p['key']] = energy.snapshot(p['ids'], p['neighbours'])
        self.pending = [p for p in self.pending if O.iter < p['due']]
        return bool(due)

    def grow(self, tab, growTime, ledger):
        """Every growing replacement's fragments towards the parent's volume, by the share of growTime
        elapsed. The cluster of fragments is scaled about its centre of mass by a factor per check (radii
        and distances alike), so fragments never overlap each other; the neighbours are pushed out
        gradually. The contacts follow (ballast.contacts). ledger: the engine's dict with volumeLost and
        massLost, reduced by what grows back. Returns whether anything grew."""
        if not self.growing:
            return False
        still = []
        for g in self.growing:
            frac = 1.0 if growTime <= 0 else min(1.0, (O.time - g['t0']) / growTime)
            want = g['ratio'] ** frac                  # fragments' volume over their volume when placed
            f = (want / g['grown']) ** (1.0 / 3.0)
            alive = [O.bodies[i] for i in g['ids'] if O.bodies[i] is not None]  # crushed ones: their fragments grow
            if alive:
                mass = sum(b.state.mass for b in alive)
                centre = sum((b.state.pos * b.state.mass for b in alive), Vector3(0, 0, 0)) / mass
            for b in alive:
                b.state.pos = centre + (b.state.pos - centre) * f
                rs = resizeGrain(tab, b.id, f)  # the density stays: mass x f^3
                ledger['volumeLost'] -= rs.volumeBefore * (f ** 3 - 1)
                ledger['massLost'] -= rs.massAfter - rs.massBefore
            scaleDensities([b.id for b in alive], ledger['scaledPWaveStep'])  # larger: less scaling needed
            g['grown'] = want
            if frac < 1:
                still.append(g)
            else:
                self.pending.append({'event': g['event'], 'key': 'energyGrown', 'due': O.iter, 'ids': g['ids'],
                                     'neighbours': g.get('neighbours', [])})
        self.growing = still
        tab.commit()
        return True

    def state(self):
        return {'growing': self.growing, 'pending': self.pending}

    def setState(self, s):
        self.growing, self.pending = list(s['growing']), list(s['pending'])
