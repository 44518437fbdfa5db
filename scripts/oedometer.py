# -*- coding: utf-8 -*-
"""Oedometric test of crushable railway ballast (R. Dubina and J. Eliáš, sections 4 and 5).

    yade scripts/oedometer.py                       one realization with the defaults
    yade scripts/oedometer.py --f 2 --pattern 14    any parameter by name (see --help)
    yade-batch TABLE scripts/oedometer.py           one realization per table row, same names

A steel cylinder of facets (inner diameter 300 mm, height 150 mm, closed bottom) is filled with
spherical grains (diameters uniform in [20.5, 44.5] mm) deposited under gravity, vibrated by a
horizontal acceleration of the cylinder, then loaded through a rigid plate by one cycle of
eq. 8, F(t) = Fmax/2 [sin(2 pi f t - pi/2) + 1], while BallastCrushEngine (section 2) and
BallastAbrasionEngine (section 3) degrade the grains.

Output in <results>/<run id>/ (run id = O.tags['d.id'], or --runId): fd.csv, events.csv,
summary.json, fd.png, grains.csv, optional vtk/. The packing after deposition and vibration is
stored in <results>/packings/ (or --packingDir) and reused by every later run with the same seed
and packing parameters. See docs/oedometer.md.
"""
import hashlib
import json
import math
import os
import sys
import time

import numpy as np

import yade
from yade import geom, utils

SCRIPT = 'oedometer'
T_START = time.time()


# ---------------------------------------------------------------------------------------------
# Parameters: declared once, here. The command line (--name value) and yade-batch tables
# (readParamsFromTable, a column per name) use exactly these names.
# ---------------------------------------------------------------------------------------------
class ParamError(Exception):
	"""A bad parameter; the message starts with the parameter's name."""


def _float(name, raw):
	if isinstance(raw, bool):
		raise ParamError('%s: expected a number, got %r' % (name, raw))
	try:
		v = float(raw)
	except (TypeError, ValueError):
		raise ParamError('%s: expected a number, got %r' % (name, raw))
	if not math.isfinite(v):
		raise ParamError('%s: expected a finite number, got %r' % (name, raw))
	return v


def _int(name, raw):
	v = _float(name, raw)
	if v != int(v):
		raise ParamError('%s: expected an integer, got %r' % (name, raw))
	return int(v)


def _flag(name, raw):
	s = str(raw).strip().lower()
	if s in ('1', '1.0', 'true', 'yes', 'on'):
		return 1
	if s in ('0', '0.0', 'false', 'no', 'off'):
		return 0
	raise ParamError('%s: expected 0 or 1, got %r' % (name, raw))


def _str(name, raw):
	return str(raw)


# Replacement patterns of Fig. 1 as the engine takes them; the canonical names are accepted too.
PATTERNS = {'4': 4, 'tetra4': 4, '6': 6, 'octa6': 6, '14': 14, 'fill14': 14, 'planar4': 'planar4'}


def _pattern(name, raw):
	s = str(raw).strip().strip('\'"').lower()
	if s.endswith('.0'):
		s = s[:-2]
	if s not in PATTERNS:
		raise ParamError("%s: expected 4, 6, 14 or 'planar4', got %r" % (name, raw))
	return PATTERNS[s]


class Param:
	def __init__(self, name, default, unit, doc, kind=_float, check=None):
		self.name, self.default, self.unit, self.doc, self.kind, self.check = name, default, unit, doc, kind, check


def positive(v):
	return None if v > 0 else 'must be > 0'


def nonNegative(v):
	return None if v >= 0 else 'must be >= 0'


def fraction(v):
	return None if 0 < v < 1 else 'must be in (0, 1)'


def dampingRange(v):
	return None if 0 <= v < 1 else 'must be in [0, 1)'


PARAMS = [
	# realization and geometry (section 4, Fig. 3)
	Param('seed', 1, '-', 'realization: grain sizes and positions, fragment orientations', _int, nonNegative),
	Param('diameter', 0.300, 'm', 'inner diameter of the steel cylinder', check=positive),
	Param('height', 0.150, 'm', 'height of the cylinder; the grains fill it after deposition', check=positive),
	Param('dMin', 0.0205, 'm', 'smallest grain diameter (diameters uniform in [dMin, dMax])', check=positive),
	Param('dMax', 0.0445, 'm', 'largest grain diameter', check=positive),
	Param('segments', 48, '-', 'facets around the cylinder (the flat inner faces are at diameter/2)', _int,
	      lambda v: None if v >= 12 else 'must be >= 12'),
	# materials (section 4)
	Param('young', 3e11, 'Pa', "ballast Young's modulus", check=positive),
	Param('poisson', 0.3, '-', 'ballast Poisson ratio', check=lambda v: None if 0 <= v < 0.5 else 'must be in [0, 0.5)'),
	Param('friction', 0.8, 'rad', 'ballast friction angle', check=lambda v: None if 0 <= v < math.pi / 2 else 'must be in [0, pi/2)'),
	Param('density', 2600., 'kg/m^3', 'ballast density', check=positive),
	Param('steelYoungRatio', 10., '-', "steel Young's modulus over the ballast's", check=positive),
	Param('steelPoisson', 0.25, '-', 'steel Poisson ratio', check=lambda v: None if 0 <= v < 0.5 else 'must be in [0, 0.5)'),
	Param('steelFriction', 0.0, 'rad', 'steel friction angle (cylinder and plate)', check=lambda v: None if 0 <= v < math.pi / 2 else 'must be in [0, pi/2)'),
	Param('steelDensity', 7850., 'kg/m^3', 'steel density', check=positive),
	# preparation: deposition and vibration
	Param('prepYoung', 3e8, 'Pa', "ballast Young's modulus while depositing and vibrating (time scaling; steel keeps "
	      "steelYoungRatio); restored to young before loading", check=positive),
	Param('prepDamping', 0.4, '-', 'local damping while depositing and vibrating', check=dampingRange),
	Param('depTime', 1.5, 's', 'longest deposition; it stops earlier once the grains rest', check=positive),
	Param('vibAcc', 50., 'm/s^2', 'amplitude of the horizontal acceleration of the cylinder', check=nonNegative),
	Param('vibFreq', 20., 'Hz', 'frequency of the vibration', check=positive),
	Param('vibTime', 0.2, 's', 'duration of the vibration (rounded up to whole periods; 0 = none)', check=nonNegative),
	Param('reusePacking', 1, '-', '1: load the stored packing of this seed and packing parameters if there is one', _flag),
	Param('packingDir', '', 'path', 'where packings are stored (default <results>/packings)', _str),
	# loading (eq. 8)
	Param('f', 8.0, 'Hz', 'loading frequency of eq. 8 (the paper: 0.25 to 8 Hz, almost no effect)', check=positive),
	Param('Fmax', 1.5e6, 'N', 'peak force of eq. 8', check=positive),
	Param('vMax', 5.0, 'm/s', 'fastest plate speed of the force control (the press\'s limit; sets how fast a crushing jump is)',
	      check=positive),
	Param('damping', 0.2, '-', 'local (Cundall) damping while loading', check=dampingRange),
	Param('dtSafety', 0.8, '-', 'time step = dtSafety * PWaveTimeStep() (eq. 5; conservative for Hertz contacts)', check=lambda v: None if 0 < v <= 1 else 'must be in (0, 1]'),
	# crushing (section 2) and abrasion (section 3)
	Param('crush', 1, '-', '1: BallastCrushEngine on', _flag),
	Param('ft0', 2.5e6, 'Pa m', 'reference strength of eq. 4, f_t = ft0 / r^m', check=positive),
	Param('m', 1.0, '-', 'size exponent of eq. 4 (the paper: 1)', check=nonNegative),
	Param('pattern', 6, '-', "replacement of a crushed grain (Fig. 1): 4, 6, 14 or 'planar4'", _pattern),
	Param('rMin', 0.010, 'm', 'grains with a smaller radius neither crush nor abrade', check=nonNegative),
	Param('Tc', 1e-4, 's', 'crushing period T_c: the crushing condition is checked every Tc (0 = every step)', check=nonNegative),
	Param('abrasion', 1, '-', '1: BallastAbrasionEngine on', _flag),
	Param('strength', 2.5e10, 'Pa', 'abrasion strength compared with the Hertz pressure p0 of eq. 6-7', check=positive),
	Param('gamma', 0.9, '-', 'radius reduction factor of an abraded grain, r_new = gamma r_old', check=fraction),
	Param('abrasionPeriod', 100, 'steps', 'the abrasion condition is checked every abrasionPeriod steps', _int,
	      lambda v: None if v >= 1 else 'must be >= 1'),
	# output
	Param('results', 'results', 'path', 'results root; this run writes <results>/<run id>/', _str),
	Param('runId', '', '-', "run id (default O.tags['d.id']); an existing directory gets a suffix, never overwritten", _str),
	Param('samples', 5000, '-', 'rows of fd.csv per loading cycle', _int, lambda v: None if v >= 10 else 'must be >= 10'),
	Param('vtk', 0.0, 's', 'VTKRecorder period while loading, simulated time (0 = no VTK output)', check=nonNegative),
	Param('progress', 10.0, 's', 'wall-clock seconds between progress lines', check=positive),
	Param('timing', 0, '-', "1: time every engine while loading (O.timingEnabled) and write timing.txt", _flag),
]
PARAM = {p.name: p for p in PARAMS}


def crossCheck(p):
	"""Checks between parameters; each message names the parameter at fault."""
	if p['dMin'] >= p['dMax']:
		raise ParamError('dMin: must be smaller than dMax (%g >= %g)' % (p['dMin'], p['dMax']))
	if p['dMax'] >= p['diameter'] / 2:
		raise ParamError('dMax: must be smaller than diameter/2 (%g >= %g)' % (p['dMax'], p['diameter'] / 2))
	if p['dMax'] >= p['height']:
		raise ParamError('dMax: must be smaller than height (%g >= %g)' % (p['dMax'], p['height']))
	if p['rMin'] > p['dMax'] / 2:
		raise ParamError('rMin: larger than the largest grain radius dMax/2 (%g > %g)' % (p['rMin'], p['dMax'] / 2))
	if p['prepYoung'] > p['young']:
		raise ParamError('prepYoung: must not exceed young (%g > %g)' % (p['prepYoung'], p['young']))


def convert(name, raw):
	par = PARAM[name]
	v = par.kind(name, raw)
	if par.check is not None:
		msg = par.check(v)
		if msg:
			raise ParamError('%s: %s, got %r' % (name, msg, raw))
	return v


def tableValues():
	"""Row of the yade-batch table, through readParamsFromTable (which evaluates each cell in
	Python, so strings are quoted: 'planar4'). Cells are checked first so that an error names the
	column instead of failing inside eval."""
	if not utils.runningInBatch():
		return {}
	tableFile, line = os.environ['YADE_BATCH'].split(':')[:2]
	row = utils.TableParamReader(tableFile).paramDict()[int(line)]
	for col, raw in row.items():
		if col == 'description' or col.startswith('!'):
			continue
		if col not in PARAM:
			raise ParamError('%s: unknown parameter (table column) in %s' % (col, tableFile))
		if raw == '*':
			continue
		try:
			eval(raw, dict(math.__dict__))
		except Exception:
			raise ParamError("%s: cannot read %r from the table (numbers as they are, strings quoted: 'planar4')" % (col, raw))
	utils.readParamsFromTable(noTableOk=True, **{p.name: p.default for p in PARAMS})
	from yade.params import table
	return {col: getattr(table, col) for col in row if col in PARAM}


def commandLine(argv):
	import argparse
	ap = argparse.ArgumentParser(prog='yade scripts/oedometer.py', description=__doc__.split('\n\n')[0] +
	                             ' Every parameter can also be a yade-batch table column of the same name.',
	                             formatter_class=argparse.RawDescriptionHelpFormatter)
	for p in PARAMS:
		ap.add_argument('--' + p.name, default=None, metavar=p.unit.upper().replace(' ', '').replace('^', '') if p.unit not in ('-', 'path') else
		                ('PATH' if p.unit == 'path' else 'V'), help='%s [%s] (default %s)' % (p.doc, p.unit, ('%g' % p.default) if isinstance(p.default, float) else repr(p.default)))
	ns = ap.parse_args(argv)
	return {k: v for k, v in vars(ns).items() if v is not None}


def readParams(argv):
	"""defaults <- yade-batch table row <- command line; all checked before any work."""
	raw = {p.name: p.default for p in PARAMS}
	raw.update(tableValues())
	raw.update(commandLine(argv))
	p = {name: convert(name, raw[name]) for name in raw}
	crossCheck(p)
	return p


# ---------------------------------------------------------------------------------------------
# Terminal: progress without flooding
# ---------------------------------------------------------------------------------------------
def fmtTime(s):
	if s is None or not math.isfinite(s):
		return '?'
	s = int(round(s))
	return '%dh%02dm' % (s // 3600, (s % 3600) // 60) if s >= 3600 else ('%dm%02ds' % (s // 60, s % 60) if s >= 60 else '%ds' % s)


def say(msg):
	print('[%s %7.1fs] %s' % (SCRIPT, time.time() - T_START, msg), flush=True)


# ---------------------------------------------------------------------------------------------
# The run
# ---------------------------------------------------------------------------------------------
class Oedometer:
	PACKING_KEYS = ('seed', 'diameter', 'height', 'dMin', 'dMax', 'segments', 'young', 'poisson', 'friction', 'density',
	                'steelYoungRatio', 'steelPoisson', 'steelFriction', 'steelDensity', 'prepYoung', 'prepDamping',
	                'depTime', 'vibAcc', 'vibFreq', 'vibTime')
	PACKING_VERSION = 2  # bump whenever the preparation changes: stored packings of older versions are not reused
	STIFFEN_TIME = 0.01  # [s] simulated time over which the soft preparation modulus is raised to young
	SERVO_PERIOD = 4  # [steps] between updates of the plate velocity
	SERVO_GAIN = 0.3  # [-] fraction of the force error the plate corrects per update, with the plate contacts' stiffness
	PREP_DT_SAFETY = 0.5  # [-] O.dt / PWaveTimeStep() while preparing: the packing does not depend on dtSafety

	def __init__(self, p):
		self.p = p
		self.Rin = p['diameter'] / 2
		self.engCrush = self.engAbrasion = None
		self.stepsByPhase = {}
		self.wallByPhase = {}
		self.maxProtrusion = 0.0
		self.nEscaped = 0
		self.packingReused = False

	# --- output directory -----------------------------------------------------------------
	def makeOutDir(self):
		p = self.p
		rid = p['runId'] or O.tags['d.id']
		rid = ''.join(c if (c.isalnum() or c in '._=,+-') else '_' for c in rid).strip('.') or 'run'
		os.makedirs(p['results'], exist_ok=True)
		for k in range(1, 10000):
			name = rid if k == 1 else '%s-%d' % (rid, k)
			path = os.path.join(p['results'], name)
			try:
				os.mkdir(path)  # atomic: two runs never get the same directory
			except FileExistsError:
				continue
			self.runId, self.out = name, path
			return
		raise RuntimeError('no free run directory for %s' % rid)

	# --- scene pieces ---------------------------------------------------------------------
	def materials(self, young):
		p = self.p
		self.ballast = FrictMat(young=young, poisson=p['poisson'], frictionAngle=p['friction'], density=p['density'], label='ballast')
		self.steel = FrictMat(young=p['steelYoungRatio'] * young, poisson=p['steelPoisson'], frictionAngle=p['steelFriction'],
		                      density=p['steelDensity'], label='steel')
		O.materials.append(self.ballast)
		O.materials.append(self.steel)

	def cylinder(self, height=None):
		p = self.p
		height = height or p['height']
		# facetCylinder's radius is the vertex radius: push it out so that the flat faces are at Rin.
		self.Rv = self.Rin / math.cos(math.pi / p['segments'])
		# wallMask: up 1, down 2, side 4 -> closed bottom, open top
		facets = geom.facetCylinder((0, 0, height / 2), self.Rv, height, segmentsNumber=p['segments'], wallMask=6,
		                            material=self.steel, color=(.6, .6, .6))
		self.cylIds = O.bodies.append(facets)
		self.cylPos0 = [Vector3(O.bodies[i].state.pos) for i in self.cylIds]

	def engines(self, damping):
		O.engines = [
			ForceResetter(),
			InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb(), Bo1_Wall_Aabb()]),
			# Hertz-Mindlin: normal force kno uN^1.5 is the Hertz solution behind p0 of eq. 7 (docs/oedometer.md)
			InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],
			                [Ip2_FrictMat_FrictMat_MindlinPhys()], [Law2_ScGeom_MindlinPhys_Mindlin()]),
			PyRunner(command='oedoPlateForce()', iterPeriod=self.SERVO_PERIOD, dead=True, label='oedoForce'),
			NewtonIntegrator(damping=damping, gravity=(0, 0, -9.81), label='newton'),
			PyRunner(command='oedoShake()', iterPeriod=10, dead=True, label='oedoShaker'),
		]

	def sphereBodies(self):
		return [b for b in O.bodies if b is not None and isinstance(b.shape, Sphere)]

	def grainArrays(self):
		bs = self.sphereBodies()
		if not bs:
			return np.zeros((0, 3)), np.zeros(0), np.zeros(0)
		x = np.array([[b.state.pos[0], b.state.pos[1], b.state.pos[2]] for b in bs])
		r = np.array([b.shape.radius for b in bs])
		m = np.array([b.state.mass for b in bs])
		return x, r, m

	def meanGrainVolume(self):
		a, b = self.p['dMin'], self.p['dMax']
		return math.pi / 6 * (b**4 - a**4) / (4 * (b - a))  # E[d^3] of a uniform diameter

	# --- running with progress ------------------------------------------------------------
	def runPhase(self, phase, done=None, tEnd=None, untilIter=None, simSpan=None, simStart=None, extra=None, checkEvery=200,
	             chunkWall=2.0):
		"""Run until tEnd [s] or untilIter is reached or done() is true, with a progress line every
		p['progress'] seconds. done() is evaluated by a PyRunner every checkEvery steps, which
		pauses O: where a phase ends never depends on how fast the machine is, so a seed always
		gives the same packing and the same run. simSpan: planned simulated duration of the phase
		(for % and ETA)."""
		global _check
		w0, i0 = time.time(), O.iter
		lastPrint = time.time()
		chunk = 500  # steps; grows to about chunkWall seconds (each O.run(wait=True) costs ~40 ms)
		hist = []  # (wall, sim) for the rate behind the ETA
		self.phaseDone = False
		if done is not None:
			_check = done
			O.engines = O.engines + [PyRunner(command='oedoPhaseCheck()', iterPeriod=checkEvery, label='oedoPhase')]
		while not self.phaseDone:
			if tEnd is not None and O.time >= tEnd - 0.5 * O.dt:
				break
			if untilIter is not None and O.iter >= untilIter:
				break
			tw = time.time()
			n = chunk if tEnd is None else max(1, min(chunk, int(math.ceil((tEnd - O.time) / O.dt - 0.5))))
			n = n if untilIter is None else max(1, min(n, untilIter - O.iter))
			O.run(n, True)
			dtw = time.time() - tw
			if n == chunk:
				chunk = int(min(max(chunk * chunkWall / max(dtw, 1e-3), 100), 50000))
			self.checkContainment()
			now = time.time()
			hist.append((now, O.time))
			hist = [h for h in hist if now - h[0] < 30] or hist[-1:]
			if now - lastPrint >= self.p['progress']:
				lastPrint = now
				line = '%-8s t=%.4f s  step %d  dt=%.2e s' % (phase, O.time, O.iter, O.dt)
				if simSpan:
					elapsed = O.time - simStart
					rate = (hist[-1][1] - hist[0][1]) / max(hist[-1][0] - hist[0][0], 1e-9) if len(hist) > 1 else 0
					eta = (simSpan - elapsed) / rate if rate > 0 else None
					line += '  %5.1f%% of %s  ETA %s' % (100 * min(elapsed / simSpan, 1), 'cycle' if phase == 'load' else 'phase', fmtTime(eta))
				if extra:
					line += '  ' + extra()
				say(line)
		if done is not None:
			O.engines = [e for e in O.engines if e.label != 'oedoPhase']
		self.stepsByPhase[phase] = self.stepsByPhase.get(phase, 0) + O.iter - i0
		self.wallByPhase[phase] = self.wallByPhase.get(phase, 0) + time.time() - w0

	def checkContainment(self):
		"""Largest protrusion of a grain out of the cylinder (through the side, the bottom or the
		plate) and the number of grains whose centre left it."""
		if getattr(self, 'plate', None) is None:
			return
		x, r, _ = self.grainArrays()
		if len(r) == 0:
			return
		c = O.bodies[self.cylIds[0]].state.pos - self.cylPos0[0]  # the cylinder moves while vibrating
		rho = np.hypot(x[:, 0] - c[0], x[:, 1] - c[1])
		zTop = O.bodies[self.plate].state.pos[2]
		prot = np.maximum.reduce([rho + r - self.Rv, c[2] - (x[:, 2] - r), x[:, 2] + r - zTop])
		self.maxProtrusion = max(self.maxProtrusion, float(prot.max()))
		esc = int(np.sum((rho > self.Rv) | (x[:, 2] < c[2]) | (x[:, 2] > zTop)))
		self.nEscaped = max(self.nEscaped, esc)

	def vRms(self):
		"""Root mean square grain speed [m/s], sqrt(2 Ek / mass): the grains rest when it is small."""
		_, _, m = self.grainArrays()
		return math.sqrt(2 * utils.kineticEnergy() / max(np.sum(m), 1e-300))

	def restInfo(self):
		return 'unbalanced %.3g  v_rms %.2g m/s' % (self.unbalanced(), self.vRms())

	def unbalanced(self):
		u = utils.unbalancedForce()
		return u if math.isfinite(u) else 1.0

	# --- packing: deposition, vibration, stiffening ---------------------------------------
	def packingKey(self):
		d = {k: self.p[k] for k in self.PACKING_KEYS}
		d['version'] = self.PACKING_VERSION
		h = hashlib.sha1(json.dumps(d, sort_keys=True).encode()).hexdigest()[:10]
		return d, 'packing-seed%d-%s.json' % (self.p['seed'], h)

	def packing(self):
		p = self.p
		pdir = p['packingDir'] or os.path.join(p['results'], 'packings')
		keyDict, fname = self.packingKey()
		path = os.path.join(pdir, fname)
		if p['reusePacking'] and os.path.exists(path):
			self.packingReused = True
			say('packing: reusing %s' % path)
		else:
			self.buildPacking()
			os.makedirs(pdir, exist_ok=True)
			x, r, _ = self.grainArrays()
			data = {'key': keyDict, 'created': time.strftime('%Y-%m-%dT%H:%M:%S'), 'runId': self.runId,
			        'steps': dict(self.stepsByPhase), 'wallSeconds': dict(self.wallByPhase),
			        'grains': [[repr(float(v)) for v in (xi[0], xi[1], xi[2], ri)] for xi, ri in zip(x, r)]}
			tmp = path + '.%d.tmp' % os.getpid()
			with open(tmp, 'w') as fh:
				json.dump(data, fh)
			os.replace(tmp, path)  # atomic: concurrent runs of the same seed never see half a file
			say('packing: %d grains saved to %s' % (len(r), path))
		self.packingFile = path
		# Fresh or stored, the loading always starts from the file: the same seed gives the same run.
		with open(path) as fh:
			data = json.load(fh)
		self.prepSteps, self.prepWall = self.stepsByPhase.copy(), self.wallByPhase.copy()
		self.stepsByPhase, self.wallByPhase = {}, {}
		self.plate = None
		O.reset()
		self.materials(p['young'])
		self.cylinder()
		self.engines(p['damping'])
		for g in data['grains']:
			x, y, z, r = (float(v) for v in g)
			O.bodies.append(utils.sphere((x, y, z), r, material=self.ballast))
		O.dt = p['dtSafety'] * utils.PWaveTimeStep()
		# contacts re-form with the stored overlaps; only the shear history is lost: let it settle
		tEnd = O.time + 0.01
		self.runPhase('settle', lambda: self.unbalanced() < 0.01, tEnd=tEnd, checkEvery=100)

	def cloud(self, rng, n):
		"""n grains, diameters uniform in [dMin, dMax], at random non-overlapping places in the
		cylinder, about 30 % solid so that they fall freely."""
		p = self.p
		d = rng.uniform(p['dMin'], p['dMax'], n)
		r = np.sort(d / 2)[::-1]  # big first: random sequential addition fails less
		gap = 0.05 * p['dMin']
		hCloud = np.sum(4 / 3 * math.pi * r**3) / (0.3 * math.pi * self.Rin**2)
		pos = np.zeros((n, 3))
		for i, ri in enumerate(r):
			for trial in range(100000):
				if trial and trial % 300 == 0:
					hCloud *= 1.1
				rho = (self.Rin - ri - gap) * math.sqrt(rng.uniform())
				phi = rng.uniform(0, 2 * math.pi)
				c = np.array([rho * math.cos(phi), rho * math.sin(phi), rng.uniform(ri + gap, max(hCloud - ri, ri + gap))])
				if i == 0 or np.all(np.sum((pos[:i] - c)**2, axis=1) > (r[:i] + ri + gap)**2):
					pos[i] = c
					break
			else:
				raise RuntimeError('could not place grain %d of %d in the cloud' % (i, n))
		return pos, r, hCloud

	def buildPacking(self):
		p = self.p
		O.reset()
		self.plate = None
		self.materials(p['prepYoung'])
		rng = np.random.default_rng(p['seed'])
		# enough grains to overfill the cylinder at solid fraction 0.64; the excess is cut off below
		n = int(math.ceil(0.64 * math.pi * self.Rin**2 * p['height'] / self.meanGrainVolume()))
		pos, rad, hCloud = self.cloud(rng, n)
		# while the cloud falls the wall reaches above it, or grains bounce out over the rim
		self.cylinder(max(p['height'], hCloud + p['dMax']))
		self.engines(p['prepDamping'])
		for c, r in zip(pos, rad):
			O.bodies.append(utils.sphere(tuple(c), float(r), material=self.ballast))
		O.dt = self.PREP_DT_SAFETY * utils.PWaveTimeStep()
		say('deposit: %d grains falling from up to %.3f m (E = %.3g Pa while preparing, dt = %.2e s)' % (n, hCloud, p['prepYoung'], O.dt))
		tFall = math.sqrt(2 * hCloud / 9.81)
		# at rest: forces balanced (grains on the frictionless steel may still slide, so not v = 0)
		self.runPhase('deposit', lambda: O.time > 1.2 * tFall and self.unbalanced() < 0.1, tEnd=p['depTime'],
		              simSpan=p['depTime'], simStart=0.0, extra=self.restInfo)
		# fill to the cylinder height: grains sticking out above it are removed
		cut = [b.id for b in self.sphereBodies() if b.state.pos[2] + b.shape.radius > p['height']]
		out = [b.id for b in self.sphereBodies() if math.hypot(b.state.pos[0], b.state.pos[1]) > self.Rv or b.state.pos[2] < 0]
		for i in set(cut + out):
			O.bodies.erase(i)
		self.prepLost = len(set(out) - set(cut))
		say('deposit: done at t=%.3f s, %d grains above %.3f m removed (%d escaped), %d left' % (
		    O.time, len(cut), p['height'], self.prepLost, len(self.sphereBodies())))
		self.vibrate()
		self.stiffen()

	def vibrate(self):
		p = self.p
		if p['vibTime'] <= 0 or p['vibAcc'] <= 0:
			return
		global _shake
		omega = 2 * math.pi * p['vibFreq']
		periods = math.ceil(p['vibTime'] * p['vibFreq'] - 1e-9)
		t0 = O.time
		tEnd = t0 + periods / p['vibFreq']
		# acceleration a cos(w tau): velocity (a/w) sin(w tau), displacement (a/w^2)(1 - cos(w tau)),
		# starting and ending at rest in the original place after whole periods
		_shake = (t0, p['vibAcc'], omega, self.cylIds)
		steps = max(1, int(1 / (p['vibFreq'] * O.dt * 200)))  # 200 velocity updates a period
		shaker = [e for e in O.engines if e.label == 'oedoShaker'][0]
		shaker.iterPeriod, shaker.dead = steps, False
		say('vibrate: %d periods of %.3g m/s^2 at %.3g Hz (amplitude %.2f mm)' % (periods, p['vibAcc'], p['vibFreq'], 1e3 * p['vibAcc'] / omega**2))
		self.runPhase('vibrate', tEnd=tEnd, simSpan=tEnd - t0, simStart=t0)
		shaker.dead = True
		for i, x0 in zip(self.cylIds, self.cylPos0):
			O.bodies[i].state.vel = Vector3(0, 0, 0)
			O.bodies[i].state.pos = x0
		tEnd = O.time + 0.2
		self.runPhase('vibrate', lambda: self.unbalanced() < 0.1, tEnd=tEnd, extra=self.restInfo)

	def stiffen(self):
		"""Back to the true modulus. New contacts take it from the materials at once; the existing
		ones are stiffened gradually (Hertz: kno and kso are proportional to E) over STIFFEN_TIME
		with strong damping, so that the overlaps of the soft packing relax quasi-statically
		instead of kicking the grains with a suddenly stiffer spring."""
		p = self.p
		ratio = p['young'] / p['prepYoung']
		self.ballast.young = p['young']
		self.steel.young = p['steelYoungRatio'] * p['young']
		O.dt = self.PREP_DT_SAFETY * utils.PWaveTimeStep()
		if ratio <= 1:
			return
		newton = [e for e in O.engines if e.label == 'newton'][0]
		newton.damping = max(p['prepDamping'], 0.8)
		soft = {(i.id1, i.id2): (i.phys.kno, i.phys.kso) for i in O.interactions if i.isReal}
		say('stiffen: E %.3g -> %.3g Pa over %.3g s, dt = %.2e s' % (p['prepYoung'], p['young'], self.STIFFEN_TIME, O.dt))
		global _stiffen
		_stiffen = (O.time, ratio, soft)
		stiffener = PyRunner(command='oedoStiffen()', iterPeriod=100, initRun=True, label='oedoStiffener')
		O.engines = O.engines + [stiffener]
		tEnd = O.time + self.STIFFEN_TIME
		self.runPhase('stiffen', tEnd=tEnd)
		O.engines = [e for e in O.engines if e.label != 'oedoStiffener']
		_stiffen = (O.time - 2 * self.STIFFEN_TIME, ratio, soft)
		oedoStiffen()  # the last step to the full modulus
		newton.damping = p['prepDamping']
		tEnd = O.time + 0.02
		self.runPhase('stiffen', lambda: self.unbalanced() < 0.02, tEnd=tEnd, extra=self.restInfo)

	# --- loading ---------------------------------------------------------------------------
	def addPlate(self):
		"""A rigid plate (an infinite wall; the grains stay inside the cylinder) resting on the
		highest grain. It is moved by the force control, like the ram of a servo-hydraulic press."""
		x, r, _ = self.grainArrays()
		self.zPlate0 = float(np.max(x[:, 2] + r))
		w = utils.wall(self.zPlate0, axis=2, sense=-1, material=self.steel)
		self.plate = O.bodies.append(w)
		self.Kmin = self.p['Fmax'] / 1e-3  # [N/m] stiffness assumed without contact: approach gently
		self.Kplate, self.servoCalls = 0.0, 0

	def addEngines(self):
		"""The engines of the engines issue, after NewtonIntegrator."""
		p = self.p
		if not (p['crush'] or p['abrasion']):
			return
		from ballast.engines import BallastCrushEngine, BallastAbrasionEngine
		extra = []
		if p['crush']:
			# the engine scales O.dt with the drop of PWaveTimeStep() after a replacement (eq. 5),
			# which keeps the dtSafety margin set here
			kw = dict(ft0=p['ft0'], m=p['m'], pattern=p['pattern'], rMin=p['rMin'], seed=p['seed'], mask=0, label='crush')
			if p['Tc'] > 0:
				kw['virtPeriod'] = p['Tc']
			else:
				kw['iterPeriod'] = 1
			self.engCrush = BallastCrushEngine(**kw)
			extra.append(self.engCrush)
		if p['abrasion']:
			self.engAbrasion = BallastAbrasionEngine(strength=p['strength'], gamma=p['gamma'], rMin=p['rMin'], mask=0,
			                                         iterPeriod=p['abrasionPeriod'], label='abrasion')
			extra.append(self.engAbrasion)
		O.engines = O.engines + extra

	def load(self):
		p = self.p
		self.addPlate()
		self.addEngines()
		self.T = 1.0 / p['f']
		x, r, m = self.grainArrays()
		self.massInitial = float(np.sum(m))
		self.nGrains = len(r)
		self.volumeGrains = float(np.sum(4 / 3 * math.pi * r**3))
		self.t0 = O.time
		self.fd = open(os.path.join(self.out, 'fd.csv'), 'w')
		self.fd.write('t,F,delta,nCrushed,nAbraded\n')
		self.rows = []
		O.engines = O.engines + [PyRunner(command='oedoRecord()', virtPeriod=self.T / p['samples'], initRun=True, label='oedoRecorder')]
		if p['vtk'] > 0:
			os.makedirs(os.path.join(self.out, 'vtk'), exist_ok=True)
			O.engines = O.engines + [VTKRecorder(fileName=os.path.join(self.out, 'vtk', 'oedo-'), recorders=['spheres', 'facets', 'velocity', 'stress'],
			                                     virtPeriod=p['vtk'], label='oedoVtk')]
		for e in O.engines:
			if e.label == 'oedoForce':
				e.dead = False
		if p['timing']:
			O.timingEnabled = True
		say('load: plate at %.4f m on %d grains (%.1f kg, porosity %.3f), F = Fmax/2 [sin(2 pi f t - pi/2) + 1], '
		    'Fmax = %.4g N, f = %g Hz, dt = %.2e s' % (self.zPlate0, self.nGrains, self.massInitial,
		                                              1 - self.volumeGrains / (math.pi * self.Rin**2 * self.zPlate0), p['Fmax'], p['f'], O.dt))
		self.runPhase('load', tEnd=self.t0 + self.T, simSpan=self.T, simStart=self.t0,
		              extra=lambda: 'F=%.0f kN  delta=%.1f mm  crushed %d  abraded %d' % (
		                  self.rows[-1][1] / 1e3 if self.rows else 0, self.rows[-1][2] * 1e3 if self.rows else 0, self.nCrushed(), self.nAbraded()))
		self.record()
		self.fd.close()
		if p['timing']:
			import contextlib
			import io
			from yade import timing
			buf = io.StringIO()
			with contextlib.redirect_stdout(buf):
				timing.stats()
			with open(os.path.join(self.out, 'timing.txt'), 'w') as fh:
				fh.write(buf.getvalue())

	def targetForce(self, t):
		"""Eq. 8."""
		p = self.p
		return p['Fmax'] / 2 * (math.sin(2 * math.pi * p['f'] * t - math.pi / 2) + 1)

	def applyPlateForce(self):
		"""Force control: every SERVO_PERIOD steps the plate gets the speed that removes SERVO_GAIN
		of the gap between eq. 8 and the force of the grains on it, estimated with the stiffness
		of its contacts, at most vMax. Between crushing events the force follows eq. 8; when a
		grain under the plate crushes the force drops and the plate moves down at up to vMax
		until the grains carry eq. 8 again: the horizontal jumps of the F-delta diagram."""
		p = self.p
		n = self.SERVO_PERIOD
		F = self.plateContactForce()
		if self.servoCalls % 25 == 0:
			# stiffness of the plate's contacts; the wall has an interaction (mostly potential) with
			# every grain, so this loop is done only now and then
			self.Kplate = sum(i.phys.kn for i in O.bodies[self.plate].intrs() if i.isReal)
		self.servoCalls += 1
		err = self.targetForce(O.time - self.t0 + n * O.dt) - F
		v = self.SERVO_GAIN * err / (max(self.Kplate, self.Kmin) * n * O.dt)
		O.bodies[self.plate].state.vel = Vector3(0, 0, -max(-p['vMax'], min(p['vMax'], v)))

	def plateContactForce(self):
		"""Force of the grains on the plate (= of the plate on the grains) [N]: the plate is moved
		kinematically, so the force container holds only its contact forces of this step."""
		return O.forces.f(self.plate)[2]

	def nCrushed(self):
		return self.engCrush.nCrushed if self.engCrush is not None else 0

	def nAbraded(self):
		return self.engAbrasion.nAbraded if self.engAbrasion is not None else 0

	def record(self):
		t = O.time - self.t0
		row = (t, self.plateContactForce(), self.zPlate0 - O.bodies[self.plate].state.pos[2], self.nCrushed(), self.nAbraded())
		if self.rows and row[0] <= self.rows[-1][0]:
			return
		self.rows.append(row)
		self.fd.write('%.9g,%.9g,%.9g,%d,%d\n' % row)

	# --- results ---------------------------------------------------------------------------
	def events(self):
		ev = []
		for e in (self.engCrush, self.engAbrasion):
			if e is not None:
				ev.extend(e.events)
		ev.sort(key=lambda e: (e['t'], e['iter'], e['id']))
		with open(os.path.join(self.out, 'events.csv'), 'w') as fh:
			fh.write('kind,t,iter,id,radius,value,strength,newIds\n')
			for e in ev:
				fh.write('%s,%.17g,%d,%d,%.17g,%.17g,%.17g,%s\n' % (e['kind'], e['t'] - self.t0, e['iter'], e['id'], e['radius'], e['value'],
				                                               e['strength'], ' '.join(str(i) for i in e.get('newIds', []))))
		return ev

	def writeGrains(self):
		with open(os.path.join(self.out, 'grains.csv'), 'w') as fh:
			fh.write('id,x,y,z,r,mass\n')
			for b in self.sphereBodies():
				fh.write('%d,%.9g,%.9g,%.9g,%.9g,%.9g\n' % (b.id, b.state.pos[0], b.state.pos[1], b.state.pos[2], b.shape.radius, b.state.mass))

	def summary(self, ev):
		p = self.p
		a = np.array(self.rows)
		k = int(np.argmax(a[:, 1]))
		x, r, m = self.grainArrays()
		massLost = sum(e.massLost for e in (self.engCrush, self.engAbrasion) if e is not None)
		volumeLost = sum(e.volumeLost for e in (self.engCrush, self.engAbrasion) if e is not None)
		loaded = a[:, 0] >= 0.05 * self.T
		target = np.array([self.targetForce(t) for t in a[:, 0]])
		s = {
			'runId': self.runId,
			'peakForce': float(a[k, 1]),
			'deltaAtPeak': float(a[k, 2]),
			'deltaMax': float(np.max(a[:, 2])),
			'deltaFinal': float(a[-1, 2]),
			'nCrushed': self.nCrushed(),
			'nAbraded': self.nAbraded(),
			'volumeLost': float(volumeLost),
			'massInitial': self.massInitial,
			'massFinal': float(np.sum(m)),
			'massLost': float(massLost),
			'wallSeconds': time.time() - T_START,
			'cpuSeconds': time.process_time(),  # = wallSeconds on an idle machine with one thread
			'steps': sum(self.prepSteps.values()) + sum(self.stepsByPhase.values()),
			'stepsByPhase': dict(list(self.prepSteps.items()) + list(self.stepsByPhase.items())),
			'wallSecondsByPhase': {k: round(v, 3) for k, v in list(self.prepWall.items()) + list(self.wallByPhase.items())},
			'nGrainsInitial': self.nGrains,
			'nSpheresFinal': len(r),
			'plateHeight0': self.zPlate0,
			'porosity0': 1 - self.volumeGrains / (math.pi * self.Rin**2 * self.zPlate0),
			'forceErrorRms': float(np.sqrt(np.mean((a[loaded, 1] - target[loaded])**2))) if loaded.any() else None,
			'dtFinal': O.dt,
			'checkSeconds': {k: getattr(e, 'checkSeconds', None) for k, e in (('crush', self.engCrush), ('abrasion', self.engAbrasion))
			                 if e is not None},
			'nChecks': {k: getattr(e, 'nChecks', None) for k, e in (('crush', self.engCrush), ('abrasion', self.engAbrasion)) if e is not None},
			'maxProtrusion': self.maxProtrusion,
			'nEscaped': self.nEscaped,
			'packingFile': self.packingFile,
			'packingReused': self.packingReused,
			'prepEscaped': getattr(self, 'prepLost', None),
			'threads': yade.runtime.opts.threads or int(os.environ.get('OMP_NUM_THREADS', 1)),
			'yade': yade.config.version if hasattr(yade, 'config') else '',
			'params': {k: p[k] for k in PARAM},
		}
		with open(os.path.join(self.out, 'summary.json'), 'w') as fh:
			json.dump(s, fh, indent=1, sort_keys=False)
		return s

	def plot(self, ev):
		import matplotlib
		matplotlib.use('Agg')
		import matplotlib.pyplot as plt
		a = np.array(self.rows)
		fig, (ax, ax2) = plt.subplots(1, 2, figsize=(11, 4.5), gridspec_kw={'width_ratios': [3, 2]})
		ax.plot(a[:, 2] * 1e3, a[:, 1] / 1e3, '-', lw=0.8, color='C0', label='plate force on the grains')
		crush = [e for e in ev if e['kind'] == 'crush']
		if crush:
			tc = np.array([e['t'] - self.t0 for e in crush])
			ax.plot(np.interp(tc, a[:, 0], a[:, 2]) * 1e3, np.interp(tc, a[:, 0], a[:, 1]) / 1e3, 'x', ms=4, color='C3',
			        label='crushing (%d)' % len(crush))
		ax.set_xlabel('plate displacement $\\delta$ [mm]')
		ax.set_ylabel('force F [kN]')
		ax.set_title('oedometric test, %s' % self.runId, fontsize=9)
		ax.grid(alpha=0.3)
		ax.legend(fontsize=8, loc='upper left')
		t = np.linspace(0, self.T, 400)
		ax2.plot(a[:, 0] * 1e3, a[:, 1] / 1e3, lw=0.8, label='measured')
		ax2.plot(t * 1e3, [self.targetForce(ti) / 1e3 for ti in t], '--', color='k', lw=0.8, label='eq. 8')
		ax2.set_xlabel('loading time t [ms]')
		ax2.set_ylabel('force F [kN]')
		ax2.grid(alpha=0.3)
		ax2.legend(fontsize=8)
		fig.tight_layout()
		fig.savefig(os.path.join(self.out, 'fd.png'), dpi=120)
		plt.close(fig)

	def run(self):
		global _run
		_run = self  # for the PyRunner callbacks below
		self.makeOutDir()
		say('run %s -> %s' % (self.runId, self.out))
		self.packing()
		self.load()
		ev = self.events()
		self.writeGrains()
		s = self.summary(ev)
		self.plot(ev)
		say('done in %s: peak F %.0f kN at delta %.2f mm, delta max %.2f mm, %d crushed, %d abraded, %d steps; results in %s' % (
		    fmtTime(s['wallSeconds']), s['peakForce'] / 1e3, s['deltaAtPeak'] * 1e3, s['deltaMax'] * 1e3, s['nCrushed'], s['nAbraded'],
		    s['steps'], self.out))
		return s


# Callbacks of the PyRunners (evaluated in this module's namespace, __main__ under yade).
_run = None
_shake = None
_stiffen = None
_check = None


def oedoPlateForce():
	_run.applyPlateForce()


def oedoRecord():
	_run.record()


def oedoPhaseCheck():
	if _check():
		_run.phaseDone = True
		O.pause()


def oedoStiffen():
	t0, ratio, soft = _stiffen
	fac = ratio**min((O.time - t0) / Oedometer.STIFFEN_TIME, 1.0)
	for i in O.interactions:
		k = soft.get((i.id1, i.id2))
		if k is not None and i.isReal:
			i.phys.kno, i.phys.kso = k[0] * fac, k[1] * fac


def oedoShake():
	t0, a, w, ids = _shake
	v = a / w * math.sin(w * (O.time - t0))
	for i in ids:
		O.bodies[i].state.vel = Vector3(v, 0, 0)


def main():
	try:
		params = readParams(sys.argv[1:])
		if params['crush'] or params['abrasion']:
			try:
				import ballast.engines  # noqa: F401  (fail now, not after the deposition)
			except ImportError as e:
				raise ParamError('crush: the ballast engines are not importable (%s); build the package or run with --crush 0 --abrasion 0' % e)
	except ParamError as e:
		sys.stderr.write('oedometer.py: bad parameter %s\n' % e)
		sys.exit(2)
	result = Oedometer(params).run()
	utils.waitIfBatch()
	if not utils.runningInBatch() and not yade.runtime.opts.exitAfter:
		sys.exit(0)  # a job, not a session: `yade scripts/oedometer.py` ends when the results are written
	return result


if __name__ == '__main__':
	main()
