#!/usr/bin/python3
# -*- coding: utf-8 -*-
"""Aggregate a study run by scripts/study.py into tables and the paper's figures.

    scripts/aggregate.py results/studies/frequency            -> results/studies/frequency/aggregate/
    scripts/aggregate.py results/studies/Tc --param Tc --out docs/figures/Tc

Writes
    runs.csv         one line per finished run: the studied parameter, seed and the numbers of summary.json
    stats.csv        one line per value of the studied parameter: number of runs, mean and standard
                     deviation (sample, n-1) of the displacement at peak force and of the other results
    fd_curves.png    F-delta curves of all runs coloured by the studied parameter (paper, Fig. 4)
    delta_peak.png   displacement at peak force against the parameter: one grey line per realization,
                     mean +- standard deviation as error bars (paper, Fig. 5)
The studied parameter is the column of the table that varies besides the seed (--param if several).
Runs not finished are left out and listed. See docs/studies.md.
"""
import argparse
import ast
import csv
import json
import math
import os
import sys

# Results of summary.json carried into the tables; (key, unit)
RESULTS = [('peakForce', 'N'), ('deltaAtPeak', 'm'), ('deltaMax', 'm'), ('deltaFinal', 'm'), ('nCrushed', '-'),
           ('nAbraded', '-'), ('volumeLost', 'm^3'), ('massLost', 'kg'), ('massInitial', 'kg'), ('nGrainsInitial', '-'),
           ('porosity0', '-'), ('wallSeconds', 's'), ('cpuSeconds', 's'), ('steps', '-')]
STATS = ['deltaAtPeak', 'deltaMax', 'peakForce', 'nCrushed', 'nAbraded', 'massLost', 'wallSeconds']
LABELS = {'f': 'loading frequency f [Hz]', 'Tc': 'crushing period $T_c$ [s]', 'rMin': '$r_{min}$ [m]', 'ft0': '$f_{t0}$ [Pa m]',
          'gamma': r'reduction factor $\gamma$ [-]', 'pattern': 'replacement pattern'}


class AggregateError(Exception):
	"""Bad input; the message names the argument at fault."""


def cellValue(raw):
	try:
		v = ast.literal_eval(raw)
	except (ValueError, SyntaxError):
		return raw
	return v if isinstance(v, (int, float, str)) and not isinstance(v, bool) else raw


def label(v):
	if isinstance(v, float):
		return '%g' % v
	return str(v)


def mean(xs):
	return sum(xs) / len(xs)


def std(xs):
	"""Sample standard deviation (n-1); NaN for a single run."""
	if len(xs) < 2:
		return float('nan')
	m = mean(xs)
	return math.sqrt(sum((x - m)**2 for x in xs) / (len(xs) - 1))


def fmt(v):
	if v is None or (isinstance(v, float) and math.isnan(v)):
		return ''
	return repr(v) if isinstance(v, float) else str(v)


class StudyData:
	def __init__(self, path, param=None):
		self.dir = os.path.abspath(path)
		info = os.path.join(self.dir, 'study.json')
		if not os.path.isfile(info):
			raise AggregateError('STUDY: %s is not a study directory of scripts/study.py (no study.json)' % path)
		with open(info) as fh:
			self.info = json.load(fh)
		rows = self.info['rows']
		cols = [c for c in self.info['columns'] if c != 'description' and not c.startswith('!')]
		varying = [c for c in cols if c != 'seed' and len(set(r['row'][c] for r in rows)) > 1]
		if param is not None:
			if param not in cols:
				raise AggregateError('--param: %r is not a column of the study table (columns: %s)' % (param, ', '.join(cols)))
			self.param = param
		elif len(varying) == 1:
			self.param = varying[0]
		elif not varying:
			raise AggregateError('STUDY: no column but the seed varies in %s; nothing to aggregate against' % self.info['table'])
		else:
			raise AggregateError('--param: the table varies %s; say which one is studied' % ', '.join(varying))
		self.runs, self.missing = [], []
		for r in rows:
			d = os.path.join(self.dir, 'runs', r['runId'])
			try:
				with open(os.path.join(d, 'summary.json')) as fh:
					s = json.load(fh)
			except (OSError, ValueError):
				self.missing.append(r['runId'])
				continue
			row = r['row']
			params = s.get('params', {})
			value = cellValue(row[self.param]) if self.param in row else params.get(self.param)
			if isinstance(value, str):
				value = value.strip('\'"')
			seed = cellValue(row['seed']) if 'seed' in row else params.get('seed')
			self.runs.append({'line': r['line'], 'runId': r['runId'], 'value': value, 'seed': seed, 'summary': s, 'dir': d})
		if not self.runs:
			raise AggregateError('STUDY: no finished run in %s (run it with scripts/study.py run first)' % path)
		vals = [r['value'] for r in self.runs]
		self.numeric = all(isinstance(v, (int, float)) for v in vals)
		self.values = sorted(set(vals), key=(lambda v: v) if self.numeric else (lambda v: (isinstance(v, str), str(v).zfill(8))))
		self.seeds = sorted(set(r['seed'] for r in self.runs), key=lambda s: (str(type(s)), s))

	def stats(self):
		out = []
		for v in self.values:
			rs = [r for r in self.runs if r['value'] == v]
			st = {'value': v, 'n': len(rs)}
			for k in STATS:
				xs = [float(r['summary'][k]) for r in rs if r['summary'].get(k) is not None]
				st[k + '_mean'] = mean(xs) if xs else float('nan')
				st[k + '_std'] = std(xs) if xs else float('nan')
			out.append(st)
		return out


def writeCsv(data, outDir):
	runsCsv = os.path.join(outDir, 'runs.csv')
	with open(runsCsv, 'w', newline='') as fh:
		w = csv.writer(fh)
		w.writerow(['line', 'runId', data.param, 'seed'] + ['%s [%s]' % kv for kv in RESULTS])
		for r in sorted(data.runs, key=lambda r: r['line']):
			w.writerow([r['line'], r['runId'], label(r['value']), r['seed']] + [fmt(r['summary'].get(k)) for k, _ in RESULTS])
	statsCsv = os.path.join(outDir, 'stats.csv')
	units = dict(RESULTS)
	with open(statsCsv, 'w', newline='') as fh:
		w = csv.writer(fh)
		w.writerow([data.param, 'n'] + sum([['%s_mean [%s]' % (k, units[k]), '%s_std [%s]' % (k, units[k])] for k in STATS], []))
		for st in data.stats():
			w.writerow([label(st['value']), st['n']] + sum([[fmt(st[k + '_mean']), fmt(st[k + '_std'])] for k in STATS], []))
	return runsCsv, statsCsv


def axisPositions(data, xlog):
	"""x of each parameter value, tick labels and scale. Categories for names (pattern); for numbers
	spanning decades a log axis, with 0 (Tc = 0: every step) put one step left of the smallest."""
	vals = data.values
	if not data.numeric:
		return {v: i for i, v in enumerate(vals)}, [label(v) for v in vals], 'linear'
	pos = [v for v in vals if v > 0]
	useLog = xlog == 'yes' or (xlog == 'auto' and len(pos) >= 3 and min(pos) > 0 and max(pos) / min(pos) >= 20 and
	                           all(v >= 0 for v in vals))
	if not useLog:
		return {v: v for v in vals}, None, 'linear'
	ratio = (max(pos) / min(pos))**(1 / max(len(pos) - 1, 1))
	x = {v: (v if v > 0 else min(pos) / ratio) for v in vals}
	zero = 'every step' if data.param == 'Tc' else '0'
	return x, [(zero if v == 0 else '%.3g' % v) for v in vals], 'log'


def plots(data, outDir, xlog):
	import matplotlib
	matplotlib.use('Agg')
	import matplotlib.pyplot as plt
	import numpy as np
	name = LABELS.get(data.param, data.param)
	cmap = plt.get_cmap('tab10' if len(data.values) <= 10 else 'viridis')
	color = {v: cmap(i if len(data.values) <= 10 else i / max(len(data.values) - 1, 1)) for i, v in enumerate(data.values)}
	styles = ['-', '--', ':', '-.', (0, (5, 1, 1, 1, 1, 1))]
	style = {s: styles[i % len(styles)] for i, s in enumerate(data.seeds)}

	# Fig. 4: F-delta of every run
	fig, ax = plt.subplots(figsize=(8, 5.5))
	for r in sorted(data.runs, key=lambda r: (data.values.index(r['value']), str(r['seed']))):
		try:
			a = np.loadtxt(os.path.join(r['dir'], 'fd.csv'), delimiter=',', skiprows=1, ndmin=2)
		except (OSError, ValueError):
			continue
		ax.plot(a[:, 2] * 1e3, a[:, 1] / 1e3, linestyle=style[r['seed']], color=color[r['value']], lw=0.9)
	from matplotlib.lines import Line2D
	h1 = [Line2D([], [], color=color[v], lw=2, label='%s = %s' % (data.param, label(v))) for v in data.values]
	leg = ax.legend(handles=h1, fontsize=8, loc='upper left', title=None)
	if len(data.seeds) <= 10:
		ax.add_artist(leg)
		h2 = [Line2D([], [], color='k', linestyle=style[s], lw=1, label='seed %s' % s) for s in data.seeds]
		ax.legend(handles=h2, fontsize=8, loc='lower right')
	ax.set_xlabel(r'plate displacement $\delta$ [mm]')
	ax.set_ylabel('force F [kN]')
	ax.set_title('%s: %d runs, %d values of %s, %d realizations' % (os.path.basename(data.dir), len(data.runs), len(data.values),
	                                                                  data.param, len(data.seeds)), fontsize=10)
	ax.grid(alpha=0.3)
	fig.tight_layout()
	fd = os.path.join(outDir, 'fd_curves.png')
	fig.savefig(fd, dpi=130)
	plt.close(fig)

	# Fig. 5: displacement at peak force against the parameter
	x, ticks, scale = axisPositions(data, xlog)
	fig, ax = plt.subplots(figsize=(8, 5))
	for s in data.seeds:
		rs = sorted([r for r in data.runs if r['seed'] == s], key=lambda r: data.values.index(r['value']))
		ax.plot([x[r['value']] for r in rs], [r['summary']['deltaAtPeak'] * 1e3 for r in rs], '-', color='0.7', lw=0.8, zorder=1)
	st = data.stats()
	ax.errorbar([x[s['value']] for s in st], [s['deltaAtPeak_mean'] * 1e3 for s in st],
	            yerr=[0 if math.isnan(s['deltaAtPeak_std']) else s['deltaAtPeak_std'] * 1e3 for s in st],
	            fmt='o', color='C0', ecolor='C0', capsize=4, lw=1.5, zorder=3, label='mean $\\pm$ standard deviation')
	ax.plot([], [], '-', color='0.7', label='one realization (seed)')
	ax.set_xscale(scale)
	if ticks is not None:
		ax.set_xticks([x[v] for v in data.values])
		ax.set_xticklabels(ticks, rotation=45 if scale == 'log' else 0, ha='right' if scale == 'log' else 'center', fontsize=8)
		ax.minorticks_off()
	ax.set_xlabel(name)
	ax.set_ylabel(r'displacement at peak force $\delta$ [mm]')
	ax.set_title('%s: %d runs, %d realizations' % (os.path.basename(data.dir), len(data.runs), len(data.seeds)), fontsize=10)
	ax.grid(alpha=0.3)
	ax.legend(fontsize=8)
	fig.tight_layout()
	dp = os.path.join(outDir, 'delta_peak.png')
	fig.savefig(dp, dpi=130)
	plt.close(fig)
	return fd, dp


def main(argv=None):
	ap = argparse.ArgumentParser(prog='scripts/aggregate.py', description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
	ap.add_argument('study', metavar='STUDY', help='study directory written by scripts/study.py run (its --out)')
	ap.add_argument('--param', help='the studied column (default: the only one that varies besides seed)')
	ap.add_argument('--out', metavar='DIR', help='where to write (default STUDY/aggregate)')
	ap.add_argument('--xlog', choices=('auto', 'yes', 'no'), default='auto', help='log axis for the parameter in delta_peak.png')
	ap.add_argument('--no-plots', action='store_true', help='only the CSV tables')
	args = ap.parse_args(argv)
	try:
		if not os.path.isdir(args.study):
			raise AggregateError('STUDY: no such directory: %s' % args.study)
		outDir = args.out or os.path.join(args.study, 'aggregate')
		if os.path.exists(outDir) and not os.path.isdir(outDir):
			raise AggregateError('--out: %s exists and is not a directory' % outDir)
		data = StudyData(args.study, args.param)
	except AggregateError as e:
		sys.stderr.write('aggregate.py: %s\n' % e)
		return 2
	os.makedirs(outDir, exist_ok=True)
	runsCsv, statsCsv = writeCsv(data, outDir)
	print('%s: %d finished runs of %d rows; studied parameter %s (%d values), %d realizations' % (
	    data.dir, len(data.runs), len(data.info['rows']), data.param, len(data.values), len(data.seeds)))
	shas = set()
	for r in data.runs:
		try:
			with open(os.path.join(r['dir'], 'row.json')) as fh:
				shas.add(json.load(fh).get('scriptSha1'))
		except (OSError, ValueError):
			pass
	if len(shas) > 1:
		print('warning: the runs were made by %d versions of the simulation script (sha1 %s)' % (len(shas), ', '.join(sorted(str(x)[:10] for x in shas))))
	if data.missing:
		print('not finished (left out): %d: %s%s' % (len(data.missing), ', '.join(data.missing[:8]), ' ...' if len(data.missing) > 8 else ''))
	print('%-12s %3s  %22s  %22s  %16s' % (data.param, 'n', 'delta at peak [mm]', 'delta max [mm]', 'crushed'))
	for st in data.stats():
		print('%-12s %3d  %10.2f +- %8.2f  %10.2f +- %8.2f  %6.1f +- %5.1f' % (
		    label(st['value']), st['n'], st['deltaAtPeak_mean'] * 1e3, st['deltaAtPeak_std'] * 1e3, st['deltaMax_mean'] * 1e3,
		    st['deltaMax_std'] * 1e3, st['nCrushed_mean'], st['nCrushed_std']))
	print('tables: %s, %s' % (runsCsv, statsCsv))
	if not args.no_plots:
		print('figures: %s, %s' % plots(data, outDir, args.xlog))
	return 0


if __name__ == '__main__':
	sys.exit(main())
