#!/usr/bin/python3
"""All performance figures of the README in one command; writes bench/results.json.

    /usr/bin/python3 bench/run_all.py [--quick] [--threads 1,2]

For each thread count (yade -jN) it runs
  bench/bench_loading.py  the loading phase of the stored default oedometer packing: plain YADE against
                          the engines at T_c = 3.12e-4 s and at every step, one check of each kind against
                          one step, and our crushing check against yade.bf's over the same grains;
  bench/bench_checks.py   the cost of one check for about 200, 2 000 and 20 000 grains (scaling).
The ratios below are taken from the one-thread runs, over the costlier of the two loading windows:
overhead_Tc (both engines every T_c), overhead_every_step (crushing, the paper's T_c, every step),
overhead_every_step_both (abrasion every step too). Targets (issue 6): overhead_Tc <= 1.05,
overhead_every_step <= 2, speedup_vs_bf >= 10, checks linear in grains and contacts.
The machine should be otherwise idle; the load average before and after is recorded.
"""
import argparse
import datetime
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
TARGETS = {'overhead_Tc': ('<=', 1.05), 'overhead_every_step': ('<=', 2.0), 'speedup_vs_bf': ('>=', 10.0)}


def yade(threads, script, args, log):
    cmd = ['yade', '-j%d' % threads, '-n', '-x', os.path.join(HERE, script)] + args
    print('bench: ' + ' '.join(cmd), flush=True)
    env = dict(os.environ, OMP_NUM_THREADS=str(threads))
    t = time.time()
    with open(log, 'w') as fh:
        p = subprocess.run(cmd, stdout=fh, stderr=subprocess.STDOUT, env=env, cwd=os.path.dirname(HERE))
    with open(log) as fh:
        lines = [l.rstrip() for l in fh if l.startswith('bench:') or ' grains ' in l]
    print('\n'.join('  ' + l for l in lines[-6:]), flush=True)
    if p.returncode != 0:
        sys.exit('bench: %s failed (exit %d); its log: %s' % (script, p.returncode, log))
    return time.time() - t


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('--threads', default='1,2', help='YADE thread counts, comma-separated (default 1,2)')
    ap.add_argument('--quick', action='store_true', help='fewer steps and rounds (a smoke run, not for the README)')
    ap.add_argument('--out', default=os.path.join(HERE, 'results.json'))
    a = ap.parse_args()
    try:
        threads = [int(t) for t in a.threads.split(',')]
        if any(t < 1 for t in threads):
            raise ValueError
    except ValueError:
        sys.exit('run_all.py: --threads must be positive integers separated by commas, got %r' % a.threads)
    tmp = tempfile.mkdtemp(prefix='bench_')
    res = {'date': datetime.datetime.now().isoformat(timespec='seconds'), 'nproc': os.cpu_count(),
           'loadavgBefore': os.getloadavg(), 'quick': a.quick, 'loading': {}, 'checks': {}}
    extra = ['--steps', '300', '--repeat', '1'] if a.quick else []
    for j in threads:
        out = os.path.join(tmp, 'loading-j%d.json' % j)
        yade(j, 'bench_loading.py', extra + ['--out', out], os.path.join(tmp, 'loading-j%d.log' % j))
        with open(out) as fh:
            res['loading']['j%d' % j] = json.load(fh)
        if not a.quick:
            out = os.path.join(tmp, 'checks-j%d.json' % j)
            yade(j, 'bench_checks.py', [out], os.path.join(tmp, 'checks-j%d.log' % j))
            with open(out) as fh:
                res['checks']['j%d' % j] = json.load(fh)
    res['loadavgAfter'] = os.getloadavg()
    one = res['loading']['j%d' % threads[0]]['windows']
    res['overhead_Tc'] = max(w['overhead_Tc'] for w in one.values())
    res['overhead_every_step'] = max(w['overhead_every_step'] for w in one.values())
    res['overhead_every_step_both'] = max(w['overhead_every_step_both'] for w in one.values())
    res['overhead_every_step_no_prefilter'] = max(w['overhead_every_step_full'] for w in one.values())
    res['speedup_vs_bf'] = min(w['checks']['speedup_vs_bf'] for w in one.values())
    res['targets'] = {k: {'target': '%s %g' % t, 'met': (res[k] <= t[1]) if t[0] == '<=' else (res[k] >= t[1])}
                      for k, t in TARGETS.items()}
    with open(a.out, 'w') as fh:
        json.dump(res, fh, indent=1)
    print('\n%-34s %8s   %s' % ('ratio (1 thread, worse window)', 'value', 'target'))
    for k in ('overhead_Tc', 'overhead_every_step', 'overhead_every_step_both', 'overhead_every_step_no_prefilter',
              'speedup_vs_bf'):
        t = res['targets'].get(k)
        print('%-34s %8.3f   %s' % (k, res[k], '' if t is None else '%s: %s' % (t['target'], 'met' if t['met'] else 'MISSED')))
    for j, r in res['loading'].items():
        for name, w in r['windows'].items():
            c = w['checks']
            print('%s %-5s %4d grains %4d contacts: step %.3f ms, crush check %.2f steps, abrasion check %.2f steps '
                  '(%.2f without prefilter), Tc x%.3f, crushing every step x%.3f, both x%.3f' % (
                      j, name, c['grains'], c['contacts'], 1e3 * c['step_s'], c['crush_check_in_steps'],
                      c['abrasion_check_in_steps'], c['abrasion_check_full_in_steps'], w['overhead_Tc'],
                      w['overhead_every_step'], w['overhead_every_step_both']))
    for j, r in res['checks'].items():
        for row in r['rows']:
            print('%s %6d grains %6d contacts: crush check %.3g us/grain, abrasion (full read) %.3g us/contact, '
                  'yade.bf %.0fx slower' % (j, row['grains'], row['contacts'], 1e6 * row['crush_per_grain_s'],
                                            1e6 * row['abrasion_per_contact_s'], row['speedup_vs_bf']))
    print('bench: wrote %s (logs in %s)' % (a.out, tmp))


if __name__ == '__main__':
    main()
