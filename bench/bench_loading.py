"""Overhead of the ballast engines on the loading phase of the oedometric test, side by side.

    yade -n -x bench/bench_loading.py [--seed 1] [--steps 2000] [--repeat 3] [--out FILE.json]
    yade -j2 -n -x bench/bench_loading.py ...            (YADE's OpenMP threads)

The stored packing of the seed (ballast.oedometer's, built once if missing) is prepared by the
library (Oedometer.prepare), the plate seated (startLoading) and the loading of eq. 8 run with the
experiment's default engines (crushing every 1e-4 s, abrasion every 100 steps). Two windows of the
loading are saved in memory, without the ballast engines: its start (F = 0) and 40 % of the cycle
(F = 0.9 Fmax, nearly the peak load). From each window the same `--steps` steps are run again and
again, interleaved so that a disturbance of the machine hits every variant alike:

    plain          no ballast engine (the oedometer's own engines: plate servo, Newton, ...)
    Tc             crushing and abrasion checked every T_c = 3.12e-4 s (the paper's Fig. 5 plateau)
    everyStep      crushing checked at every step (the left end of Fig. 5), abrasion every T_c
    everyStepBoth  both checked at every step
    everyStepFull  both at every step, the abrasion prefilter off (every contact read at every check)

The model parameters are the experiment's defaults, so a grain may crush in a window; the events are
counted per variant. Then one crushing check and one abrasion check are timed on their own (huge
strengths: a check without events; the step's cached reads forgotten before each call) next to one
step, and yade.bf's stressTensor + checkFailure over the same grains. Ratios, not seconds, are the
result: the median of the rounds.
"""
import argparse
import json
import os
import statistics
import sys
import tempfile
import time

from yade import O, utils

from ballast import harvest, runtime
from ballast.engines import BallastAbrasionEngine, BallastCrushEngine
from ballast.oedometer import Oedometer

# under `yade -x` __file__ is yade's own; sys.argv[0] is this script
HERE = os.path.dirname(os.path.abspath(sys.argv[0] if sys.argv[0].endswith('.py') else __file__))
ROOT = os.path.dirname(HERE)
TC = 3.12e-4          # [s] the crushing period of the comparison (Fig. 5)
sys.path.insert(0, HERE)
from timing import best, bestCheck, stamped  # noqa: E402

WARMUP = 50          # untimed steps of each variant before the timed ones
PEAK_FRACTION = 0.4   # window 2 starts at 40 % of the cycle: F = Fmax (1 - cos(0.8 pi)) / 2 = 0.905 Fmax


def prepare(a):
    """The stored packing with the plate, saved in memory at the two windows; returns the experiment
    and the names of the saved windows."""
    run = Oedometer(seed=a.seed, results=tempfile.mkdtemp(prefix='bench_loading_'), packingDir=a.packingDir,
                    progress=30, samples=100)
    run.prepare()
    run.startLoading()
    out = run.outputs
    # the servo stays, the file writers go
    O.engines = [e for e in O.engines if e.label not in (out.RECORDER, out.CHECKLOG, out.VTK)]
    saved = {}
    for name, tEnd in (('start', None), ('peak', run.loading.t0 + PEAK_FRACTION * run.T)):
        if tEnd is not None:
            print('bench: running the loading to %.0f %% of the cycle (%d steps)' % (
                100 * PEAK_FRACTION, int((tEnd - O.time) / O.dt)), flush=True)
            O.run(int((tEnd - O.time) / O.dt), True)
        keep = list(O.engines)
        O.engines = [e for e in keep if e.label not in ('crush', 'abrasion')]
        saveWindow(run, saved, name)
        O.engines = keep
    print('bench: %d grains crushed and %d abraded before the peak window' % (
        run.counter('crush', 'nCrushed'), run.counter('abrasion', 'nAbraded')), flush=True)
    return run, saved


def ballastEngines(p, crushEvery, abrasionEvery, prefilter=True):
    def per(every):
        return dict(iterPeriod=1) if every else dict(virtPeriod=TC)
    return [BallastCrushEngine(ft0=p['ft0'], m=p['m'], pattern=p['pattern'], rMin=p['rMin'], seed=p['seed'], **per(crushEvery)),
            BallastAbrasionEngine(strength=p['strength'], gamma=p['gamma'], rMin=p['rMin'], prefilter=prefilter,
                                  **per(abrasionEvery))]


def saveWindow(run, saved, name):
    O.saveTmp('bench-' + name)  # with the state of the plate servo (ballast.runtime)
    saved[name] = 'bench-' + name


def restoreWindow(run, saved, name):
    O.loadTmp(saved[name])
    runtime.restore()  # the servo as it was at the window, not as the experiment left it
    harvest.refresh()


VARIANTS = {'plain': None, 'Tc': dict(crushEvery=False, abrasionEvery=False),
            'everyStep': dict(crushEvery=True, abrasionEvery=False),
            'everyStepBoth': dict(crushEvery=True, abrasionEvery=True),
            'everyStepFull': dict(crushEvery=True, abrasionEvery=True, prefilter=False)}


def timeVariants(run, saved, name, a):
    """Each variant from the same window: WARMUP steps untimed (a fresh engine builds its grain table
    and verifies its bounds once), then the timed steps; rounds interleaved."""
    out = {k: {'wall': [], 'cpu': []} for k in VARIANTS}
    for rep in range(a.repeat):
        for k, kw in VARIANTS.items():
            restoreWindow(run, saved, name)
            engs = ballastEngines(run.p, **kw) if kw is not None else []
            O.engines = O.engines + engs
            O.run(WARMUP, True)
            c = time.process_time()
            out[k]['wall'].append(stamped(a.steps))
            out[k]['cpu'].append(time.process_time() - c)
            if engs:
                out[k]['nCrushed'], out[k]['nAbraded'] = engs[0].nCrushed, engs[1].nAbraded
                out[k]['checks'] = [engs[0].nChecks, engs[1].nChecks]
                out[k]['crushCheckSeconds'], out[k]['abrasionCheckSeconds'] = engs[0].checkSeconds, engs[1].checkSeconds
                out[k]['prefilterActive'], out[k]['prefilterNote'] = engs[1].prefilterActive, engs[1].prefilterNote
                out[k]['contactsRead'] = engs[1].contactsRead
            O.engines = [e for e in O.engines if not any(e is x for x in engs)]
        print('bench: window %s, round %d/%d: %s' % (name, rep + 1, a.repeat, '  '.join(
            '%s %.3f s' % (k, v['wall'][-1]) for k, v in out.items())), flush=True)
    for k, v in out.items():
        v['wallMedian'], v['cpuMedian'] = statistics.median(v['wall']), statistics.median(v['cpu'])
    return out


def timeChecks(run, saved, name):
    """One check of each kind at the window, no events (huge strengths), against one step and yade.bf."""
    from yade.bf import bf
    restoreWindow(run, saved, name)
    O.run(1, True)
    saveWindow(run, saved, 'check')
    step = min(stamped(500) for _ in range(3)) / 500
    restoreWindow(run, saved, 'check')
    O.run(1, True)  # a loaded scene's contact geometry (overlaps) is computed again by the next step
    grains = [b for b in O.bodies if b is not None and b.dynamic and b.shape.__class__.__name__ == 'Sphere']
    nContacts = O.interactions.countReal()
    crush = BallastCrushEngine(ft0=1e30)
    abr = BallastAbrasionEngine(strength=1e30)
    abrFull = BallastAbrasionEngine(strength=1e30, prefilter=False)
    stressOnly = best(lambda: utils.bodyStressTensors(), 20)

    tCrush = bestCheck(crush, 20)
    tAbrFull = bestCheck(abrFull, 20)
    abr.fire()  # the first check verifies the bound with a full read; time the ones after it
    tAbr = bestCheck(abr, 20)
    # the prefilter at the real strength: how many grains are candidates here
    real = BallastAbrasionEngine(strength=run.p['strength'])
    real.fire()
    real.fire()

    def bfCheck():
        for b in grains:
            bf.stressTensor(b, stress_correction=True)
            bf.checkFailure(b, 1e30, 1e30, wei_m=3)
    tBf = best(bfCheck, 2)
    return {'grains': len(grains), 'contacts': nContacts, 'step_s': step, 'bodyStressTensors_s': stressOnly,
            'crush_check_s': tCrush, 'abrasion_check_s': tAbr, 'abrasion_check_full_s': tAbrFull, 'bf_check_s': tBf,
            'crush_per_grain_s': tCrush / len(grains), 'abrasion_full_per_contact_s': tAbrFull / max(nContacts, 1),
            'crush_check_in_steps': tCrush / step, 'abrasion_check_in_steps': tAbr / step,
            'abrasion_check_full_in_steps': tAbrFull / step, 'speedup_vs_bf': tBf / tCrush,
            'prefilter_candidates_at_real_strength': real.nCandidates, 'prefilter_active': real.prefilterActive,
            'prefilter_note': real.prefilterNote, 'max_pressure_ratio': real.maxPressureRatio}


def main():
    ap = argparse.ArgumentParser(prog='yade -n -x bench/bench_loading.py', description=__doc__.split('\n\n')[0])
    ap.add_argument('--seed', type=int, default=1)
    ap.add_argument('--steps', type=int, default=3000, help='steps per window and variant (default 3000)')
    ap.add_argument('--repeat', type=int, default=3, help='rounds of all variants (default 3)')
    ap.add_argument('--packingDir', default=os.path.join(ROOT, 'results', 'packings'),
                    help='stored packings (default results/packings, as the README main command)')
    ap.add_argument('--out', default=os.path.join(HERE, 'results_loading_j%d.json' % O.numThreads))
    a = ap.parse_args(sys.argv[1:])
    if a.steps < 1 or a.repeat < 1:
        sys.exit('bench_loading.py: --steps and --repeat must be >= 1, got %d and %d' % (a.steps, a.repeat))
    run, saved = prepare(a)
    res = {'threads': O.numThreads, 'seed': a.seed, 'steps': a.steps, 'repeat': a.repeat, 'Tc': TC, 'windows': {}}
    for name in ('start', 'peak'):
        v = timeVariants(run, saved, name, a)
        c = timeChecks(run, saved, name)
        plain = v['plain']['wallMedian']
        res['windows'][name] = {'variants': v, 'checks': c, 'overhead_Tc': v['Tc']['wallMedian'] / plain,
                                'overhead_every_step': v['everyStep']['wallMedian'] / plain,
                                'overhead_every_step_both': v['everyStepBoth']['wallMedian'] / plain,
                                'overhead_every_step_full': v['everyStepFull']['wallMedian'] / plain}
        w = res['windows'][name]
        print('bench: window %-5s %d grains %d contacts | plain %.3f ms/step | Tc x%.3f | crushing every step x%.3f, '
              'both x%.3f (prefilter off x%.3f) | crush check %.2f steps, abrasion %.2f steps (full read %.2f) | '
              'yade.bf %.0fx slower' % (
                  name, c['grains'], c['contacts'], 1e3 * plain / a.steps, w['overhead_Tc'], w['overhead_every_step'],
                  w['overhead_every_step_both'], w['overhead_every_step_full'], c['crush_check_in_steps'],
                  c['abrasion_check_in_steps'], c['abrasion_check_full_in_steps'], c['speedup_vs_bf']), flush=True)
    with open(a.out, 'w') as fh:
        json.dump(res, fh, indent=1)
    print('bench: wrote %s' % a.out)


main()
