"""The triaxial specimen's preparation (experiments/triaxial/specimen.py, docs/triaxial.md "Set-up"): layers compacted
to their marks (compaction 'height', Ladd's undercompaction) give the porosity asked, 1 - solidFraction, in the mould;
a solid fraction the grains cannot be packed to stops at refusal and says so; the specimens stored before the option
keep their names."""
import json
import math

import numpy as np
import pytest

pytest.importorskip('yade')
from ballast.experiments.triaxial import TriaxialTest  # noqa: E402
from ballast.experiments.triaxial.parameters import PARAMS, specimenKey  # noqa: E402

SMALL = dict(diameter=0.12, height=0.24, dMin=0.02, dMax=0.03, layers=2, young=3e9, prepYoung=3e8, progress=1e6,
             compaction='height', depFriction=0.3)


def build(tmp_path, **kw):
    """The specimen of SMALL and kw prepared (stored, placed in its mould): (its stored document, the log)."""
    t = TriaxialTest(results=str(tmp_path), runId='s', **dict(SMALL, **kw))
    said = []
    t.phases.say = lambda text, _say=t.phases.say: (said.append(text), _say(text))
    t.prepare()
    with open(t.specimenFile) as fh:
        return json.load(fh), said


def test_layers_compacted_to_their_marks_give_the_porosity_asked(tmp_path):
    """solidFraction 0.45 with deposition friction 0.3 rad: the grains lie looser (the small mould's frictionless
    layers pack to about 0.55), so each layer is driven to its mark; the specimen then fills the mould to its height:
    its porosity in the mould, 1 - V_s / (pi R^2 H) by hand from the stored grains, is the document's exactly and
    1 - 0.45 within one grain per layer (the cloud's last grain crosses the volume asked: 2 V_max / V = 0.012)."""
    doc, said = build(tmp_path, solidFraction=0.45)
    g = np.array(doc['grains'], float)
    vs = float(np.sum(4 / 3 * math.pi * g[:, 3] ** 3))
    mould = math.pi * 0.06 ** 2 * 0.24
    assert [s for s in said if 'compacted to' in s and 'its mark' in s and 'refusal' not in s and 'below' not in s]
    assert doc['porosity'] == pytest.approx(1 - vs / mould, abs=1e-12)
    assert doc['porosity'] == pytest.approx(0.55, abs=2 * 4 / 3 * math.pi * 0.015 ** 3 / mould)
    # held at the mark, no grain stands above it by more than its rebound once the plate is taken away (1 mm)
    assert float(np.max(g[:, 2] + g[:, 3])) < 0.24 + 1e-3


def test_a_solid_fraction_the_grains_cannot_reach_stops_at_refusal(tmp_path):
    """solidFraction 0.6 in the small mould with friction: the plate stops where the grains push on it with
    layerPressure, above the mark; the log says so and the porosity in the mould is above 1 - 0.6."""
    doc, said = build(tmp_path, solidFraction=0.6)
    assert [s for s in said if 'refusal' in s]
    assert doc['porosity'] > 0.4 + 0.02


def test_the_specimens_stored_before_the_option_keep_their_names():
    """compaction 'pressure' (the default) leaves the key as it was (no entry for it); 'height' is another specimen."""
    p = {k: v.default for k, v in PARAMS.items()}
    p.update(results='/tmp', seed=1)
    key, name = specimenKey(p)
    assert 'compaction' not in key
    key2, name2 = specimenKey(dict(p, compaction='height'))
    assert key2['compaction'] == 'height' and name2 != name and name2.startswith('specimen-seed1-')


def test_a_specimen_differing_in_young_or_friction_only_takes_the_stored_layers(tmp_path):
    """The layers (deposited frictionless and soft, pressed) read neither young nor friction: a specimen that differs
    from a stored one in those only places the stored layers, exactly, and only stiffens and settles them (no deposit,
    no press); a fresh build of it elsewhere stores the same layers bit for bit. The layers' key leaves out just those
    two: prepYoung or depFriction changes it. Layers deposited with friction (SMALL's 0.3 rad) are neither stored nor
    reused."""
    from ballast.experiments.triaxial.parameters import layersKey
    first, _ = build(tmp_path, depFriction=0.0)
    layers = [f for f in (tmp_path / 'specimens').iterdir() if f.name.startswith('layers-')]
    assert len(layers) == 1
    stored = json.loads(layers[0].read_text())
    second, said = build(tmp_path, young=5e9, friction=0.6, depFriction=0.0)
    assert [s for s in said if s.startswith('layers: reusing') and layers[0].name in s]
    assert set(second['steps']) == {'stiffen', 'settle'} and {'deposit', 'press'} <= set(first['steps'])
    # the same grains, settled where they lay: each within a fifth of dMin of its stored place, as in a fresh build
    # (measured with the default set: 2.1 mm both; 23 mm, a top grain kicked up, when the reused contacts were first
    # made at the true modulus), and the porosity the stored top gives, 1 - V_s / (pi R^2 top)
    g, lay = np.array(second['grains'], float), np.array(stored['grains'], float)
    assert np.array_equal(g[:, 3], lay[:, 3])
    assert np.max(np.linalg.norm(g[:, :3] - lay[:, :3], axis=1)) < 0.02 / 5
    vs = float(np.sum(4 / 3 * math.pi * g[:, 3] ** 3))
    assert second['porosity'] == pytest.approx(1 - vs / (math.pi * 0.06 ** 2 * stored['top']), rel=1e-12)
    fresh, _ = build(tmp_path / 'fresh', young=5e9, friction=0.6, depFriction=0.0)
    again = json.loads((tmp_path / 'fresh' / 'specimens' / layers[0].name).read_text())
    assert again['grains'] == stored['grains'] and again['top'] == stored['top']
    f = np.array(fresh['grains'], float)
    assert np.max(np.linalg.norm(f[:, :3] - lay[:, :3], axis=1)) < 0.02 / 5
    p = {k: v.default for k, v in PARAMS.items()}
    p.update(results='/tmp', seed=1)
    name = layersKey(p)[1]
    assert name.startswith('layers-seed1-') and layersKey(dict(p, young=9e9, friction=0.1))[1] == name
    assert layersKey(dict(p, prepYoung=1e8))[1] != name and layersKey(dict(p, depFriction=0.1))[1] != name
    # layers deposited with friction are not stored (so never reused): their contacts' shear history is their state
    _, said = build(tmp_path / 'rough')
    assert not list((tmp_path / 'rough' / 'specimens').glob('layers-*'))
    assert [s for s in said if 'layer 1 of 2' in s]
