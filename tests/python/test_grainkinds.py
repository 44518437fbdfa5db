"""ballast.grainkinds (its __init__): the registry, the scene's kind (saved with the scene, the default
otherwise), and a body that is not a grain left out by every piece: a GridNode (a membrane's node, a
Sphere to Python's isinstance) squeezed exactly as a grain beside it is not selected, not crushed, not
abraded, not graded. Runs in Debian's /usr/bin/python3 with YADE imported as a module (conftest.py)."""
import json
import math

import pytest
from yade import O, utils
from yade.wrapper import GridNode

from ballast import grainkinds, harvest, runtime
from ballast.engines import BallastAbrasionEngine, BallastCrushEngine
from ballast.experiments import grains
from ballast.grainkinds.sphere import SphereKind
from ballast.scenes import grainBetweenWalls
from engine_scenes import OVERLAP, R, add


def grainAndNode():
    """A grain at the origin and a GridNode of the same radius and material at x = 5 R, both pressed by the
    same two walls (the node is a body of its own, made as utils.sphere makes a grain). After one step
    both carry the same load. Returns (grain id, node id)."""
    g, w0, w1 = grainBetweenWalls(r=R, overlap=OVERLAP)
    b = utils.sphere((5 * R, 0, 0), R, material=O.bodies[g].material)
    b.shape = GridNode(radius=R)
    b.state.blockedDOFs = 'xyXYZ'
    n = O.bodies.append(b)
    O.run(1, True)
    return g, n


def test_the_default_kind_is_the_sphere_and_unknown_names_are_refused():
    assert grainkinds.kind() is grainkinds.kind('sphere')
    assert grainkinds.DEFAULT == 'sphere' and grainkinds.kind().name == 'sphere' and 'sphere' in grainkinds.names()
    with pytest.raises(ValueError, match="'cube'.*known kinds: .*sphere"):
        grainkinds.kind('cube')
    with pytest.raises(TypeError):
        grainkinds.register(object())


def test_a_grid_node_is_not_a_grain_but_keeps_its_contact_radius():
    g, n = grainAndNode()
    sz = utils.bodyStressTensors()
    assert sz[n][2, 2] == pytest.approx(sz[g][2, 2], rel=1e-9) and sz[g][2, 2] < 0   # loaded alike
    k = grainkinds.current()
    assert k.name == 'sphere' and k.isGrain(O.bodies[g]) and not k.isGrain(O.bodies[n])
    assert [b.id for b in grains.bodies()] == [g] == [b.id for b in grains.spheres()]
    tab = harvest.grains()
    assert tab.ids.tolist() == [g] and tab.radii.tolist() == [R]
    assert tab.radiusById[n] == R   # as a contact's partner it is a sphere (Ig2 sees one), not a wall
    x, r, m = grains.arrays()
    assert r.tolist() == [R] and m.tolist() == [O.bodies[g].state.mass] and x.tolist() == [[0.0, 0.0, 0.0]]


def test_a_grid_node_is_not_graded_nor_drawn():
    g, n = grainAndNode()
    d, m = grains.sieve()
    assert d.tolist() == [2 * R] and m.tolist() == [O.bodies[g].state.mass]
    x, r, ids = grains.vtk()   # nor drawn as a grain
    assert ids.tolist() == [g] and r.tolist() == [R] and x.tolist() == [[0.0, 0.0, 0.0]]


def test_a_grid_node_is_not_crushed():
    """Both bodies far above the strength: only the grain crushes (6 fragments), the node stays."""
    g, n = grainAndNode()
    c = add(BallastCrushEngine(ft0=1.0, m=0.0, rMin=0.0, iterPeriod=1, maxPerCheck=0))
    O.run(1, True)
    assert c.nCrushed == 1 and [e['id'] for e in c.events] == [g]
    assert O.bodies[g] is None and O.bodies[n] is not None and O.bodies[n].shape.radius == R


def test_a_grid_node_is_not_abraded():
    """Both contacts far above the strength: the grain's radius x gamma, the node's stays."""
    g, n = grainAndNode()
    a = add(BallastAbrasionEngine(strength=1.0, gamma=0.9, rMin=0.0, iterPeriod=1, prefilter=False))
    O.run(1, True)
    assert a.nAbraded == 1 and a.events[0]['id'] == g
    assert O.bodies[g].shape.radius == pytest.approx(0.9 * R, rel=1e-15) and O.bodies[n].shape.radius == R


class _NoGrains(SphereKind):
    """A kind for the test: nothing is a grain."""
    name = 'test-nothing'

    def isGrain(self, body):
        return False


@pytest.fixture
def nothingKind():
    grainkinds.register(_NoGrains())
    yield 'test-nothing'
    grainkinds._kinds.pop('test-nothing', None)
    O.reset()


def _savedKinds():
    doc = json.loads(O.tags[runtime.TAG])
    return [o['state']['name'] for o in doc['objects'].values() if o['type'] == 'GrainKind']


def test_the_scene_kind_is_saved_loaded_and_forgotten_on_reset(nothingKind):
    g, w0, w1 = grainBetweenWalls(r=R, overlap=OVERLAP)
    assert harvest.grains().ids.tolist() == [g]
    assert grainkinds.use(nothingKind).name == nothingKind
    assert grainkinds.current().name == nothingKind and harvest.grains().ids.tolist() == []  # the table follows
    O.saveTmp('kinds')
    assert _savedKinds() == [nothingKind]
    O.reset()
    assert grainkinds.current().name == 'sphere'
    O.loadTmp('kinds')
    assert grainkinds.current().name == nothingKind and harvest.grains().ids.tolist() == []
    grainkinds.use('sphere')                  # back to the default: nothing of it is saved
    O.saveTmp('kinds')
    assert _savedKinds() == [] and grainkinds.current().name == 'sphere' and harvest.grains().ids.tolist() == [g]


def test_a_scene_of_the_default_kind_saves_no_kind_object():
    """Scenes of spheres keep the document they had before this layer (saved states load as they are)."""
    grainBetweenWalls(r=R, overlap=OVERLAP)
    add(BallastCrushEngine(ft0=1e12, iterPeriod=1))
    O.run(1, True)
    O.saveTmp('kinds')
    assert _savedKinds() == [] and grainkinds.current().name == 'sphere'


def test_a_kind_of_other_grains_turns_the_prefilter_off(nothingKind):
    """The prefilter's bounds take a grain's contacts at its own radius: only for kinds of one sphere."""
    class Clumpish(SphereKind):
        name = 'test-clumpish'
        oneSphere = False
    grainkinds.register(Clumpish())
    try:
        grainBetweenWalls(r=R, overlap=OVERLAP)
        grainkinds.use('test-clumpish')
        a = add(BallastAbrasionEngine(strength=1e15, iterPeriod=1))
        O.run(2, True)
        assert not a.prefilterActive and 'test-clumpish' in a.prefilterNote
        assert math.isfinite(a.maxPressureRatio)
    finally:
        grainkinds._kinds.pop('test-clumpish', None)


def test_positions_are_read_in_cplusplus_as_yade_holds_them_and_follow_an_erase():
    """harvest.positions: the centres of the table's grains, exactly b.state.pos, with a wall and an erased grain
    among them (YADE's list skips the erased one); a grain erased by hand within the step rebuilds the table."""
    O.reset()
    O.bodies.append(utils.wall(0, axis=2))
    ids = [O.bodies.append(utils.sphere((0.1 * k, 0.01 * k, 0.3 + 0.02 * k), 0.04)) for k in range(6)]
    O.bodies.erase(ids[2])
    harvest.refresh()
    table, x = harvest.positions()
    assert table.ids.tolist() == [i for i in ids if i != ids[2]]
    assert x.tolist() == [list(O.bodies[int(i)].state.pos) for i in table.ids]
    O.bodies.erase(ids[4])   # by hand, no refresh: the table no longer matches the bodies there are
    table, x = harvest.positions()
    assert table.ids.tolist() == [ids[0], ids[1], ids[3], ids[5]]
    assert x.tolist() == [list(O.bodies[int(i)].state.pos) for i in table.ids]
