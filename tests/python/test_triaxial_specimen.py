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
