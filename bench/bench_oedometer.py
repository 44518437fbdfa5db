#!/usr/bin/python3
"""Wall time of the default oedometric test (the README main command), as on a fresh machine.

    /usr/bin/python3 bench/bench_oedometer.py [--runs N] [--reuse] [--threads J] [-- extra script options]

Runs `yade -n -x scripts/oedometer.py` with the default parameters in a temporary results
directory, so the packing is built (deposition, vibration) as on a fresh machine; with --reuse the
second and later runs load it, as every later run of the same seed does. Reports per run the wall
time, the time per phase, steps and steps/s, crushes and the peak F / delta, plus the load average
of the machine (other processes slow the run down; a benchmark is only meaningful on an otherwise
idle machine). The ballast package must be importable by yade (installed, or PYTHONPATH=<build>/py).
"""
import argparse
import json
import resource
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, '..', 'scripts', 'oedometer.py')
BUDGET = 600.0  # [s] the default run must finish within 10 minutes on a 2-core machine


def busyProcesses():
	"""Other processes using the CPU now (a benchmark on a busy machine overstates the time)."""
	try:
		out = subprocess.run(['ps', '-eo', 'stat=,pcpu=,pid=,args='], capture_output=True, text=True).stdout
	except OSError:
		return []
	busy = []
	for line in out.splitlines():
		parts = line.split(None, 3)
		# ps's %CPU is over the process's life; a stopped process (state T) uses no CPU now
		if len(parts) == 4 and not parts[0].startswith('T') and float(parts[1]) > 20 and int(parts[2]) != os.getpid():
			busy.append('%s%% %s' % (parts[1], parts[3][:100]))
	return busy


def engineShares(path):
	"""The top-level lines of YADE's timing.stats() (timing.txt): engine, calls, seconds, share."""
	lines = []
	with open(path) as fh:
		for l in fh:
			parts = l.rstrip().rsplit(None, 3)
			if len(parts) == 4 and not l.startswith(' ') and parts[3].endswith('%') and parts[2].endswith('us'):
				lines.append('  %-28s %9s calls %8.2f s %8s' % (parts[0], parts[1], float(parts[2][:-2]) / 1e6, parts[3]))
	return 'bench: loading, per engine (yade.timing):\n' + '\n'.join(lines)


def main():
	ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
	ap.add_argument('--runs', type=int, default=1, help='number of runs (default 1)')
	ap.add_argument('--reuse', action='store_true', help='runs after the first reuse the packing the first one built')
	ap.add_argument('--threads', type=int, default=1, help='yade -j (default 1, as the README command)')
	ap.add_argument('--keep', action='store_true', help='keep the results directory')
	ap.add_argument('--timing', action='store_true', help="time every engine while loading (the script's --timing 1) and "
	                'print the share of each')
	ap.add_argument('extra', nargs='*', help='further script options after --, e.g. -- --f 4')
	a = ap.parse_args()
	root = tempfile.mkdtemp(prefix='bench_oedometer_')
	print('bench: results in %s; load average %s; nproc %d' % (root, ' '.join('%.2f' % v for v in os.getloadavg()), os.cpu_count()))
	busy = busyProcesses()
	if busy:
		print('bench: WARNING, other busy processes (the times below are then pessimistic):\n  ' + '\n  '.join(busy))
	rows = []
	for k in range(a.runs):
		cmd = ['yade', '-j', str(a.threads), '-n', '-x', SCRIPT, '--results', root, '--runId', 'bench%d' % k, '--progress', '30']
		if k > 0 and not a.reuse:
			cmd += ['--packingDir', os.path.join(root, 'packings%d' % k)]
		cmd += a.extra + (['--timing', '1'] if a.timing else [])
		print('bench: ' + ' '.join(cmd), flush=True)
		t0 = time.time()
		load0 = os.getloadavg()[0]
		cpu0 = resource.getrusage(resource.RUSAGE_CHILDREN)
		proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
		wall = time.time() - t0
		cpu1 = resource.getrusage(resource.RUSAGE_CHILDREN)
		cpu = (cpu1.ru_utime - cpu0.ru_utime) + (cpu1.ru_stime - cpu0.ru_stime)
		progress = [l for l in proc.stdout.splitlines() if l.startswith('[oedometer')]
		print('\n'.join('  ' + l for l in progress[-4:]))
		if proc.returncode != 0:
			print(proc.stdout[-3000:])
			sys.exit('bench: run %d failed (exit %d)' % (k, proc.returncode))
		with open(os.path.join(root, 'bench%d' % k, 'summary.json')) as fh:
			s = json.load(fh)
		if a.timing:
			print(engineShares(os.path.join(root, 'bench%d' % k, 'timing.txt')))
		steps = s['steps']
		rows.append({'run': k, 'wall': wall, 'cpu': cpu, 'loadavg': [load0, os.getloadavg()[0]], 'packingReused': s['packingReused'],
		             'phases': s['wallSecondsByPhase'], 'steps': steps, 'stepsPerSecond': steps / max(s['wallSeconds'], 1e-9),
		             'loadStepsPerSecond': s['stepsByPhase'].get('load', 0) / max(s['wallSecondsByPhase'].get('load', 1e-9), 1e-9),
		             'nGrains': s['nGrainsInitial'], 'nSpheresFinal': s['nSpheresFinal'], 'nCrushed': s['nCrushed'],
		             'nAbraded': s['nAbraded'], 'peakForce': s['peakForce'], 'deltaMax': s['deltaMax']})
	print('\nrun  wall[s]  cpu[s]  reused  steps    steps/s  load steps/s  grains->spheres  crushed  abraded  peakF[kN]  deltaMax[mm]  phases[s]')
	for r in rows:
		print('%3d  %7.1f  %6.1f  %-6s  %7d  %7.0f  %12.0f  %6d->%-6d  %7d  %7d  %9.0f  %12.1f  %s' % (
		    r['run'], r['wall'], r['cpu'], r['packingReused'], r['steps'], r['stepsPerSecond'], r['loadStepsPerSecond'], r['nGrains'],
		    r['nSpheresFinal'], r['nCrushed'], r['nAbraded'], r['peakForce'] / 1e3, r['deltaMax'] * 1e3,
		    ' '.join('%s=%.0f' % kv for kv in r['phases'].items())))
	worst = max(r['wall'] for r in rows)
	worstCpu = max(r['cpu'] for r in rows)
	print('\nbench: slowest run %.0f s = %.1f min wall, %.0f s CPU (budget %.0f s): %s' % (
	    worst, worst / 60, worstCpu, BUDGET, 'OK' if worst <= BUDGET else 'OVER BUDGET'))
	if worst > 1.2 * worstCpu:
		print('bench: the wall time exceeds the CPU time by %.0f %%: the machine was busy; on an idle machine a '
		      'one-thread run takes about its CPU time' % (100 * (worst / worstCpu - 1)))
	print(json.dumps(rows))
	if not a.keep:
		import shutil
		shutil.rmtree(root, ignore_errors=True)


if __name__ == '__main__':
	main()
