"""ballast.experiments.parameters: the declarations every experiment shares, each declared once and taken by
the experiments (with their own defaults or docs where they say so), no experiment's declarations taken from
another's, and ExperimentParameters: the derived time steps and the checks between parameters, by hand."""
import math
import os
import re

import pytest

from ballast import experiments
from ballast.experiments.parameters import (CONTACT, CYCLE_JUMP, ENGINES, GRAIN, GRAINS, INTEGRATION, PREPARATION, RUN,
                                            SEED, STEEL, ExperimentParameters, grainKey,
                                            storeName)
from ballast.params import ParamError

NAMES = ('box', 'oedometer', 'single_particle')
GROUPS = dict(GRAINS=GRAINS, GRAIN=GRAIN, STEEL=STEEL, CONTACT=CONTACT, PREPARATION=PREPARATION, INTEGRATION=INTEGRATION,
              ENGINES=ENGINES, RUN=RUN, CYCLE_JUMP=CYCLE_JUMP)
# what an experiment declares in its own words (another default or doc of the shared declaration)
OWN = {'oedometer': {'seed'},
       'box': {'steelFriction', 'rollingFriction'},
       'single_particle': {'seed', 'Tc', 'rMin', 'densityStep'}}
# the paper's step at the defaults: dtSafety (dMin / 2) sqrt(density / young) = 0.8 x 0.01025 x 9.3095e-5 s
PAPER_STEP = 7.6338e-7


def params(name):
    return experiments.declaration(name).params


def check(name, **values):
    return experiments.declaration(name).check(values)


def test_the_groups_name_each_parameter_once():
    names = [n for g in GROUPS.values() for n in g]
    assert len(names) == len(set(names)) and 'seed' not in names


@pytest.mark.parametrize('name', NAMES)
def test_every_experiment_takes_the_shared_declarations_as_they_are(name):
    p, shared = params(name), dict(seed=SEED, **{k: v for g in GROUPS.values() for k, v in g.items()})
    taken = [k for k in p if k in shared]
    assert {'seed', 'dMin', 'dMax', 'young', 'density', 'law', 'dtSafety', 'results', 'progress'} <= set(taken)
    for k in taken:
        if k in OWN[name]:   # its own default or doc, the shared unit, range and reading
            assert (p[k].unit, p[k].check, p[k].allowed, p[k].parse) == (shared[k].unit, shared[k].check, shared[k].allowed,
                                                                          shared[k].parse), k
        else:
            assert p[k] is shared[k], k


def test_the_experiments_own_words_are_theirs():
    assert params('box')['rollingFriction'].default == 0.3 and CONTACT['rollingFriction'].default == 0.0
    assert params('single_particle')['Tc'].default == 0.0 and ENGINES['Tc'].default == 1e-4
    assert params('oedometer')['seed'].doc == SEED.doc + " (YADE's makeCloud takes a C int)"


@pytest.mark.parametrize('name', NAMES)
def test_no_experiment_declares_from_another(name):
    """Its declarations, declaration and command line import no other experiment's folder."""
    folder = os.path.dirname(experiments.__file__)
    others = [n for n in NAMES if n != name]
    for module in ('parameters.py', 'declaration.py', 'commandline.py'):
        with open(os.path.join(folder, name, module)) as fh:
            imports = [line for line in fh if re.match(r'\s*(from|import)\s', line)]
        assert not [line for line in imports if any(o in line for o in others)], (name, module)


@pytest.mark.parametrize('name', NAMES)
def test_the_time_steps_and_the_crushing_period_by_hand(name):
    p = check(name)
    assert isinstance(p, ExperimentParameters)
    assert p.startTimeStep() == pytest.approx(PAPER_STEP, rel=1e-4)
    assert p.startTimeStep() == pytest.approx(0.8 * 0.0205 / 2 * math.sqrt(2600 / 3e11), rel=1e-12)
    assert p.loadingTimeStep() == p.startTimeStep() and p.scaledPWaveStep() == 0.0
    # the single-particle test's platens slower, to close a grain over 100 steps of 1e-5 s: 0.01 x 0.0205 / 1e-4 = 2.05 ms
    q = check(name, densityStep=1e-5, Tc=0.0, **({'speed': 1e-4} if name == 'single_particle' else {}))
    assert q.loadingTimeStep() == 1e-5 and q.scaledPWaveStep() == pytest.approx(1.25e-5, rel=1e-12)   # 1e-5 / 0.8
    assert q.crushPeriod() == {'iterPeriod': 1} and check(name, Tc=2e-5).crushPeriod() == {'virtPeriod': 2e-5}


def test_the_single_particle_step_is_that_of_its_smallest_grain():
    """Given diameters, the smallest of them: 0.8 x 0.011 x 9.3095e-5 = 8.1924e-7 s."""
    p = check('single_particle', diameters=[0.03, 0.022])
    assert p.startTimeStep() == pytest.approx(8.1924e-7, rel=1e-4)


def refused(name, values):
    with pytest.raises(ParamError) as e:
        check(name, **values)
    return e.value.name, str(e.value)


@pytest.mark.parametrize('name', NAMES)
def test_the_shared_checks_hold_in_every_experiment(name):
    assert refused(name, {'dMin': 0.05})[1].endswith('dMin = 0.05 is not allowed: must be smaller than dMax = 0.0445')
    assert "below the paper's step 7.63e-07 s" in refused(name, {'densityStep': 5e-7})[1]
    assert 'density scaling sets the step itself' in refused(name, {'densityStep': 1e-5, 'timeStep': 'stiffness'})[1]


@pytest.mark.parametrize('name,values,param,words', [
    ('oedometer', {'rMin': 0.03}, 'rMin', 'larger than the largest grain radius dMax/2 = 0.02225'),
    ('box', {'rMin': 0.03}, 'rMin', 'larger than the largest grain radius dMax/2 = 0.02225'),
    ('oedometer', {'prepYoung': 4e11}, 'prepYoung', 'must not exceed young = 3e+11'),
    ('box', {'prepYoung': 4e11}, 'prepYoung', 'must not exceed young = 3e+11'),
    ('oedometer', {'law': 'hertz', 'rollingFriction': 0.1}, 'rollingFriction', "needs law = 'linear'"),
    ('box', {'law': 'hertz'}, 'rollingFriction', "needs law = 'linear'"),   # 0.3 by default in the box
    # a crushing check in every load cycle: 1/8 Hz = 0.125 s; the box's sine at 3 Hz, 0.333333 s
    ('oedometer', {'Tc': 0.2}, 'Tc', 'longer than the load cycle, 0.125 s'),
    ('box', {'Tc': 0.5}, 'Tc', 'longer than the load cycle, 0.333333 s'),
    # an abrasion check too: 0.125 s / 7.6338e-7 s = 163745 steps at most
    ('oedometer', {'abrasionPeriod': 163746}, 'abrasionPeriod', '(at most 163745 steps)'),
    ('oedometer', {'jump': True}, 'jump', 'needs fatigue = 1 and crush = 1'),
    ('box', {'jump': True, 'fatigue': True, 'crush': False}, 'jump', 'needs fatigue = 1 and crush = 1'),
    # 10 cycles of 1/3 s at 7.6338e-7 s: 4.37e6 steps; 2500 cycles 1.09e9, more than 1e9
    ('box', {'cycles': 2500}, 'cycles', 'take 1.09e+09 time steps'),
    ('oedometer', {'cycles': 6200}, 'f', 'take 1.02e+09 time steps'),
])
def test_the_bed_and_cycle_checks_of_the_cyclic_experiments(name, values, param, words):
    got, message = refused(name, values)
    assert got == param and words in message, message


def test_what_the_single_particle_test_does_not_check():
    """It has no bed and no cycles: rMin above dMax/2 (no grain crushes) and a long Tc are its to choose."""
    assert check('single_particle', rMin=0.03, Tc=10.0)['rMin'] == 0.03
    assert check('oedometer', abrasionPeriod=163745)['abrasionPeriod'] == 163745
    assert check('box', cycles=2200)['cycles'] == 2200   # 9.6e8 steps


# ---------------------------------------------------------------- the grain kind (issue 47, item 1)
ALL = NAMES + ('triaxial',)


@pytest.mark.parametrize('name', ALL)
@pytest.mark.parametrize('values,param,words', [
    ({'grain': 'tetrahedron'}, 'grain', "'sphere', 'clump' or 'polyhedron'"),
    ({'grain': 'clump', 'clumpElongation': 0.0}, 'clumpElongation', 'a number in (0, 1]'),
    ({'grain': 'clump', 'clumpFlatness': 1.2}, 'clumpFlatness', 'a number in (0, 1]'),
    ({'grain': 'clump', 'clumpSpheres': 4}, 'clumpSpheres', 'an integer in [5, 200]'),
    ({'grain': 'clump', 'clumpTemplates': 0}, 'clumpTemplates', 'an integer in [1, 1000]'),
    # 0.5 x 0.5 = 0.25 <= 1/3: the long tips (at L - S from the core, radius S) do not reach the core, a bridge each
    ({'grain': 'clump', 'clumpElongation': 0.5, 'clumpFlatness': 0.5, 'clumpSpheres': 6}, 'clumpSpheres',
     'the 2 bridges of their arms at clumpElongation = 0.5, clumpFlatness = 0.5, clumpRoundness = 1: give at least 7'),
    ({'grain': 'clump', 'clumpRoundness': 0.0}, 'clumpRoundness', 'a number in (0, 1]'),
    ({'clumpRoundness': 0.5}, 'clumpRoundness', "is used only with grain = 'clump' (got grain = 'sphere')"),
    ({'clumpSpheres': 12}, 'clumpSpheres', "is used only with grain = 'clump' (got grain = 'sphere')"),
    ({'clumpFile': 'shapes.csv'}, 'clumpFile', "is used only with grain = 'clump' (got grain = 'sphere')"),
    ({'grain': 'clump', 'clumpFile': '/nonexistent/shapes.csv'}, 'clumpFile', 'no such file'),
])
def test_the_grain_parameters_are_checked_in_every_experiment(name, values, param, words):
    got, message = refused(name, values)
    assert got == param and words in message and '\n' not in message, message


@pytest.mark.parametrize('name', ALL)
def test_every_experiment_takes_the_grain_declarations_and_accepts_a_clump(name):
    p = params(name)
    assert all(p[k] is GRAIN[k] for k in GRAIN) and p['grain'].default == 'sphere'
    c = check(name, grain='clump', clumpElongation=0.8, clumpFlatness=0.5, clumpSpheres=6, clumpTemplates=3)
    assert (c['grain'], c['clumpElongation'], c['clumpFlatness'], c['clumpSpheres']) == ('clump', 0.8, 0.5, 6)


def _oldKey(keys, version, extra, prefix, seed):
    """A store key and name as they were before the grain kind: the same hash of the same entries."""
    import hashlib
    import json
    d = dict(extra, version=version, **{k: v for k, v in keys.items()})
    return d, '%s-seed%d-%s.json' % (prefix, seed, hashlib.sha1(json.dumps(d, sort_keys=True).encode()).hexdigest()[:10])


def test_sphere_samples_keep_their_store_keys_and_a_clump_sample_has_its_own():
    from ballast.experiments.box import parameters as box
    from ballast.experiments.oedometer import parameters as oed
    from ballast.experiments.triaxial import parameters as tri
    for mod, keyOf, names, version, prefix, extra in (
            (oed, oed.packingKey, oed.PACKING_KEYS, oed.PACKING_VERSION, 'packing', {}),
            (box, box.bedKey, box.BED_KEYS, box.BED_VERSION, 'bed', {}),
            (tri, tri.specimenKey, tri.SPECIMEN_KEYS, tri.SPECIMEN_VERSION, 'specimen', {})):
        p = mod.check({'seed': 3})
        assert keyOf(p) == _oldKey({k: p[k] for k in names}, version, extra, prefix, 3), prefix
        q = mod.check({'seed': 3, 'grain': 'clump'})
        d, name = keyOf(q)
        # clumpFile and clumpRoundness in the key only when given: clump samples stored before them keep their names
        before = {'grain': 'clump', 'clumpElongation': 0.7, 'clumpFlatness': 0.6, 'clumpSpheres': 8,
                  'clumpTemplates': 20}
        assert {k: d[k] for k in GRAIN if k in d} == before
        assert name == _oldKey({k: q[k] for k in names}, version, dict(extra, **before), prefix, 3)[1]
        assert name != keyOf(p)[1] and name.startswith('%s-seed3-' % prefix)
        sharp, sharpName = keyOf(mod.check({'seed': 3, 'grain': 'clump', 'clumpRoundness': 0.5}))
        assert sharp['clumpRoundness'] == 0.5 and sharpName not in (name, keyOf(p)[1])
    # a name stored before this change (the default oedometer's packing, seed 1), held by hand
    assert oed.packingKey(oed.check({}))[1] == _oldKey({k: oed.check({})[k] for k in oed.PACKING_KEYS},
                                                       oed.PACKING_VERSION, {}, 'packing', 1)[1]


@pytest.mark.parametrize('name', ALL)
def test_a_clump_file_is_read_when_checked_and_keys_the_sample_by_its_content(name, tmp_path):
    """clumpFile: its templates read with the parameters (a bad row refused by its line, before any work), the
    builder's parameters refused beside it, and the store key holding the file's SHA-1, not its path."""
    import hashlib
    good = tmp_path / 'shapes.csv'
    good.write_text('template,x,y,z,r\n1,0,0,0,1\n1,1.2,0,0,1\n')
    c = check(name, grain='clump', clumpFile=str(good))
    assert c['clumpFile'] == str(good)
    bad = tmp_path / 'bad.csv'
    bad.write_text('template,x,y,z,r\n1,0,0,0,1\n1,0,0,0,-2\n')
    got, message = refused(name, {'grain': 'clump', 'clumpFile': str(bad)})
    assert got == 'clumpFile' and 'line 3: r = -2 must be > 0' in message, message
    got, message = refused(name, {'grain': 'clump', 'clumpFile': str(good), 'clumpSpheres': 12})
    assert got == 'clumpSpheres' and 'the templates of clumpFile' in message, message
    key = grainKey(c)
    assert key['clumpFile'] == hashlib.sha1(good.read_bytes()).hexdigest()
    copy = tmp_path / 'elsewhere.csv'
    copy.write_bytes(good.read_bytes())
    assert grainKey(check(name, grain='clump', clumpFile=str(copy))) == key   # the content, not the path


def test_a_stored_sample_is_named_by_its_keys_whatever_their_order():
    """storeName: the keys' SHA-1 over their sorted JSON, so the order a dict was built in changes nothing and any value
    that decides the sample (a float's last digit, the seed) changes the name."""
    import hashlib
    import json
    keys = {'seed': 1, 'young': 3e9, 'grain': 'clump'}
    name = storeName('bed', 1, keys)
    assert name == 'bed-seed1-%s.json' % hashlib.sha1(json.dumps(keys, sort_keys=True).encode()).hexdigest()[:10]
    assert storeName('bed', 1, dict(reversed(list(keys.items())))) == name
    assert storeName('bed', 1, dict(keys, young=3.0000000001e9)) != name
    assert storeName('bed', 2, keys).startswith('bed-seed2-') and storeName('packing', 1, keys).startswith('packing-')


def test_a_clump_file_is_checked_without_yade(tmp_path):
    """The study runner checks a table's rows in plain Python: checking a clumpFile reads it without importing YADE
    (before, reading it through the grain kinds' package imported yade and failed there)."""
    import subprocess
    import sys
    import ballast
    f = tmp_path / 'shapes.csv'
    f.write_text('template,x,y,z,r\n1,0,0,0,1\n1,1.2,0,0,1\n')
    code = ('import sys; from ballast.experiments import declaration; '
            "c = declaration('box').check({'grain': 'clump', 'clumpFile': %r}); "
            "print(c['clumpFile'], 'yade' in sys.modules)" % str(f))
    env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(ballast.__file__)))
    r = subprocess.run([sys.executable, '-c', code], capture_output=True, text=True, env=env)
    assert r.returncode == 0 and r.stdout.split() == [str(f), 'False'], r.stderr[-1500:]
