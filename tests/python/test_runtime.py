"""ballast.runtime: register, dispatch, save (one O.tags key), load in this and in a fresh process,
restore through one path, and the refusal of states of the older format."""
import json
import os
import struct
import subprocess
import sys
import textwrap

import pytest

pytest.importorskip('yade')
from yade import O, utils  # noqa: E402
from yade.wrapper import ForceResetter, NewtonIntegrator, PyRunner  # noqa: E402

from ballast import runtime  # noqa: E402


@runtime.persistent('test.Counter')
class Counter:
    """Counts its calls; refers to another registered object (its `other`)."""

    def __init__(self, start=0, other=None):
        self.calls, self.other, self.restoredCalled = start, other, False

    def tick(self):
        self.calls += 1

    def state(self):
        return {'calls': self.calls, 'other': runtime.ref(self.other)}

    @classmethod
    def fromState(cls, s, ref):
        return cls(s['calls'], ref(s['other']))

    def restored(self):
        self.restoredCalled = True


def scene(period=1):
    O.reset()
    O.bodies.append(utils.sphere((0, 0, 0), 0.01))
    O.engines = [ForceResetter(), NewtonIntegrator(gravity=(0, 0, -10))]
    O.dt = 1e-4
    c = Counter(other=Counter(100))
    O.engines = O.engines + [runtime.callback(c, 'tick', iterPeriod=period, initRun=True,
                                                      label='counter')]
    return c


def test_a_callback_calls_its_object_at_its_period():
    c = scene(period=3)
    O.run(9, True)
    assert c.calls == 3                      # steps 0, 3 and 6 (initRun: the first step too)
    assert runtime.get(runtime.register(c)) is c
    assert 'import ballast.runtime' in O.engines[-1].command


def test_nothing_is_written_while_running_and_one_key_when_saving(tmp_path):
    c = scene()
    O.run(5, True)
    assert runtime.TAG not in O.tags.keys()  # the doc is written at a save only
    O.save(str(tmp_path / 's.yade.gz'))
    keys = [k for k in O.tags.keys() if k.startswith('ballast')]
    assert keys == [runtime.TAG]
    doc = json.loads(O.tags[runtime.TAG])
    assert doc['format'] == runtime.FORMAT
    states = sorted(o['state']['calls'] for o in doc['objects'].values() if o['type'] == 'test.Counter')
    assert states == [5, 100]


def test_saving_as_yade_does_leaves_the_tags_as_they_are(tmp_path):
    c = scene()
    O.run(5, True)
    O.save(str(tmp_path / 'a.yade.gz'))      # the objects' states flushed into O.tags: 5 calls
    O.run(2, True)
    runtime.saveAsYade(str(tmp_path / 'b.yade.gz'))
    assert c.calls == 7 and 5 in [o['state']['calls'] for o in json.loads(O.tags[runtime.TAG])['objects'].values()]
    assert os.path.getsize(str(tmp_path / 'b.yade.gz')) > 0


def test_load_in_this_process_rebuilds_from_the_saved_state(tmp_path):
    c = scene()
    O.run(4, True)
    f = str(tmp_path / 's.yade.gz')
    O.save(f)
    O.run(10, True)
    assert c.calls == 14
    O.load(f)
    assert type(O.engines[-1]) is PyRunner     # what YADE gives back
    O.run(2, True)                             # the first call restores: a new object with the saved count
    assert c.calls == 14                       # the old object belongs to the old scene
    back = [o for o in runtime.restore().values() if isinstance(o, Counter) and o.other is not None]
    assert len(back) == 1 and back[0].calls == 4 + 2 and back[0].other.calls == 100 and back[0].restoredCalled
    assert isinstance(O.engines[-1], runtime.Callback)  # put back in place of the plain PyRunner
    O.run(3, True)
    assert back[0].calls == 9                  # no second restore: the object stays live


def test_load_in_a_fresh_process_goes_on(tmp_path):
    c = scene()
    O.run(7, True)
    f = str(tmp_path / 's.yade.gz')
    O.save(f)
    code = textwrap.dedent('''
        import sys
        sys.path.insert(0, %r)
        sys.path.append('/usr/lib/x86_64-linux-gnu/yade-double/py')
        import test_runtime  # registers the type test.Counter
        from yade import O
        from ballast import runtime
        O.load(%r)
        O.run(3, True)
        c = [o for o in runtime.restore().values() if getattr(o, 'other', None) is not None][0]
        print('calls', c.calls, c.other.calls)
    ''' % (os.path.dirname(__file__), f))
    out = subprocess.run([sys.executable, '-c', code], capture_output=True, text=True, timeout=120,
                         env=dict(os.environ, OMP_NUM_THREADS='1'))
    assert 'calls 10 100' in out.stdout, out.stdout + out.stderr


def test_reset_forgets_the_scene():
    c = scene()
    oid = runtime.register(c)
    O.reset()
    with pytest.raises(RuntimeError, match='no object'):
        runtime.get(oid)


def test_a_type_name_is_given_once():
    with pytest.raises(ValueError, match="'test.Counter' is taken"):
        runtime.persistent('test.Counter')(type('Other', (), {}))


def test_a_state_of_the_older_format_is_refused_in_one_line():
    O.reset()
    O.tags['ballast.oedometer'] = '{}'
    O.tags['ballast.0123456789ab'] = '{}'
    O.engines = [PyRunner(command="import ballast.engines as _be; _be._fire('0123456789ab')", iterPeriod=1)]
    with pytest.raises(runtime.StateFormatError) as e:
        runtime.restore()
    assert '\n' not in str(e.value) and 'older version' in str(e.value) and 'ba51e1d' in str(e.value)
    import ballast.engines
    with pytest.raises(runtime.StateFormatError, match='older version'):
        ballast.engines._fire('0123456789ab')


@pytest.mark.parametrize('tag,words', [('', 'blank'), ('{"format": 2, "tok', 'not a JSON document'),
                                       ('[1, 2]', 'expected a JSON object'),
                                       ('{"format": 2, "token": "t", "objects": {"a": 1}}', "object 'a' is not"),
                                       ('{"format": 2, "token": "t", "objects": {"a": {"type": "test.Counter", "state": {}}}}',
                                        'cannot be rebuilt')])
def test_a_damaged_document_is_refused_in_one_line(tag, words):
    """The audit: a blank or damaged O.tags['ballast'] gave a bare JSONDecodeError or 'PyRunner error.'."""
    O.reset()
    O.tags[runtime.TAG] = tag
    with pytest.raises(runtime.StateFormatError) as e:
        runtime.restore()
    assert words in str(e.value) and "O.tags['ballast']" in str(e.value) and '\n' not in str(e.value)
    O.reset()


def test_rows_pack_bitwise_with_their_ints_and_come_back_through_json():
    """A record as a state holds it (packRows): every float to the bit (NaN, infinities, -0.0, the smallest
    subnormal), ints back as ints; a list of rows of a state of before as tuples; rows of unequal length kept."""
    rows = [(0.1, 3, float('nan'), -0.0), (1e-300, -7, float('inf'), 5e-324), (2.0 / 3.0, 2 ** 40, -float('inf'), 1.0)]
    packed = json.loads(json.dumps(runtime.packRows(rows)))
    back = runtime.unpackRows(packed)
    assert packed['ints'] == [1] and len(back) == 3
    for r, b in zip(rows, back):
        assert [type(v) for v in b] == [float, int, float, float]
        assert struct.pack('<4d', *r) == struct.pack('<4d', *b)
    assert runtime.unpackRows([[1, 2.5], [3, 4.5]]) == [(1, 2.5), (3, 4.5)]
    ragged = [(1.0, 2), (1.0, 2, 3.0)]
    assert runtime.packRows(ragged) == [[1.0, 2], [1.0, 2, 3.0]] and runtime.unpackRows(runtime.packRows([])) == []
    mixed = [(1.0, 2), (1.0, 2.5)]                     # begun with an int, then a fraction: not cut to 2
    assert runtime.unpackRows(json.loads(json.dumps(runtime.packRows(mixed)))) == mixed
