#!/usr/bin/python3
# -*- coding: utf-8 -*-
"""Parameter studies of the oedometric test: one row of a yade-batch table is one run of
scripts/oedometer.py.

    scripts/study.py run studies/frequency.table                      all cores of this machine
    scripts/study.py run studies/frequency.table --executor dask --scheduler tcp://HOST:8786
    scripts/study.py status results/studies/frequency                what is done, what failed
    scripts/study.py grid seed=1:5 f=0.25,0.5,1,2,4,8 -o studies/frequency.table

A study directory (--out, default results/studies/<table name>) holds
    runs/<run id>/      finished runs: the output of oedometer.py (summary.json, fd.csv, ...) and row.json
    logs/<run id>.log   the log of the last attempt of every run, with yade-batch's job summary at the end
    failed/<run id>/    what the last failed attempt left (removed once the run succeeds)
    status.csv          one line per table row: status, exit code, duration, host
    journal.jsonl       every attempt, appended
    table               the table as it was run (the runs read their row from it, as under yade-batch)
The run id is the row's description as yade-batch builds it (the 'description' column, else
name=value of the 'name!' columns, else of all columns). A run counts as finished when
runs/<run id>/summary.json exists: a study started again skips those and redoes the rest.

Packings (deposited and vibrated grains) are stored per seed in --packings (default: a
'packings' directory next to --out, shared by the studies there) and reused by every run with the
same seed and packing parameters, so the realizations are the same grains in every study. Of the
rows that need the same packing, one runs first and builds it; the others wait for it.

Each run is `yade -n -x oedometer.py --results ... --runId ... --packingDir ...` with
YADE_BATCH=table:line and OMP_NUM_THREADS=1, whichever executor starts it: the same row and
packing give the same command, so the same result. Dask workers that do not see --out (no shared
file system) get the script, the table and the packings with the task and send the results back.
See docs/studies.md.
"""
import argparse
import ast
import hashlib
import json
import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time
import uuid

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_SCRIPT = os.path.join(HERE, 'oedometer.py')
T_START = time.time()
# Set by Ctrl-C in the local executor: every running run kills its yade and returns. A plain dict,
# not a threading.Event: runRow is pickled by value for Dask workers, and locks do not pickle.
STOP = {'set': False}


class StudyError(Exception):
	"""Bad input; the message names the argument (or table line) at fault."""


def say(msg):
	print('[study %8s] %s' % (fmtTime(time.time() - T_START), msg), flush=True)


def fmtTime(s):
	if s is None:
		return '?'
	s = int(round(s))
	if s >= 3600:
		return '%dh%02dm' % (s // 3600, (s % 3600) // 60)
	return '%dm%02ds' % (s // 60, s % 60) if s >= 60 else '%ds' % s


def sha1(data):
	return hashlib.sha1(data if isinstance(data, bytes) else data.encode()).hexdigest()


def writeAtomic(path, data):
	"""Readers never see half a file (a status.csv being written, a packing being shipped)."""
	tmp = '%s.%d.%s.tmp' % (path, os.getpid(), uuid.uuid4().hex[:6])
	with open(tmp, 'wb' if isinstance(data, bytes) else 'w') as fh:
		fh.write(data)
	os.replace(tmp, path)


# ---------------------------------------------------------------------------------------------
# yade-batch tables
# ---------------------------------------------------------------------------------------------
def cellValue(raw):
	"""A cell as YADE evaluates it (numbers, quoted strings); anything else stays the raw text."""
	try:
		return ast.literal_eval(raw)
	except (ValueError, SyntaxError):
		return raw


def sanitize(s):
	# the same characters oedometer.py keeps in a run id, so that it does not rename the run
	s = ''.join(c if (c.isalnum() or c in '._=,+-') else '_' for c in s).strip('.') or 'run'
	return s if len(s) <= 180 else s[:170] + '_' + sha1(s)[:8]


class Table:
	"""The rows of a yade-batch table, numbered and described as yade.utils.TableParamReader does
	(1-based line numbers of the file, '#' comments, '=' repeats the cell above, 'description'
	column or one built from 'name!' columns or from all of them), read without importing YADE."""

	def __init__(self, path, text=None):
		self.path = path
		if text is None:
			with open(path) as fh:
				text = fh.read()
		# TableParamReader cuts the last character of every line (the newline): make sure there is one
		self.text = text if text.endswith('\n') else text + '\n'
		self.rows = []  # (line, {column: raw cell}) in file order
		lines = {}
		for n, l in enumerate(self.text.split('\n')[:-1], 1):
			l = re.sub(r'\s*#.*', '', l)
			if l.strip():
				lines[n] = l.split()
		if not lines:
			raise StudyError('%s: the table is empty (the first non-empty line names the columns)' % path)
		first = min(lines)
		heads = lines.pop(first)
		self.hasDescription = 'description' in heads
		if self.hasDescription:
			self.idColumns = None
		else:
			self.idColumns = [h[:-1] for h in heads if h.endswith('!')] or None
			heads = [h[:-1] if h.endswith('!') else h for h in heads]
			if self.idColumns is None:
				self.idColumns = list(heads)
		dup = sorted(set(h for h in heads if heads.count(h) > 1))
		if dup:
			raise StudyError('%s:%d: column %s appears twice' % (path, first, ', '.join(dup)))
		self.columns = heads
		prev = None
		for n in sorted(lines):
			cells = lines[n]
			if len(cells) != len(heads):
				raise StudyError('%s:%d: %d cells, but line %d names %d columns (cells are separated by blanks, no quoting of blanks)' % (
				    path, n, len(cells), first, len(heads)))
			row = dict(zip(heads, cells))
			for h in heads:
				if row[h] == '=':
					if prev is None:
						raise StudyError("%s:%d: '=' in column %s repeats the line above, but this is the first row" % (path, n, h))
					row[h] = prev[h]
			self.rows.append((n, row))
			prev = row
		if not self.rows:
			raise StudyError('%s: no rows below the column names on line %d' % (path, first))
		self.ids = {}
		seen = {}
		for n, row in self.rows:
			if self.hasDescription:
				desc = row['description']
			else:
				desc = ','.join('%s=%s' % (h, row[h]) for h in self.idColumns).replace("'", '').replace('"', '')
			rid = sanitize(desc)
			if rid in seen:
				raise StudyError('%s:%d: row gives the same run id %r as line %d; make the rows differ or add a description column' % (
				    path, n, rid, seen[rid]))
			seen[rid] = n
			self.ids[n] = rid

	def runId(self, line):
		return self.ids[line]

	def parameterColumns(self):
		"""Columns that are parameters of the script (not description, not yade-batch's !COLUMNS)."""
		return [c for c in self.columns if c != 'description' and not c.startswith('!')]


def parseLines(spec, table):
	"""yade-batch's --lines format: 2,3-5,8."""
	out = []
	for part in spec.split(','):
		m = re.fullmatch(r'\s*(\d+)\s*(?:-\s*(\d+)\s*)?', part)
		if not m:
			raise StudyError('--lines: %r is not a line list like 2,3-5,8' % spec)
		a, b = int(m.group(1)), int(m.group(2) or m.group(1))
		out.extend(range(a, b + 1))
	have = set(n for n, _ in table.rows)
	bad = [n for n in out if n not in have]
	if bad:
		raise StudyError('--lines: line(s) %s of %s hold no row; rows are on lines %s' % (
		    ','.join(map(str, bad)), table.path, ','.join(str(n) for n, _ in table.rows)))
	return sorted(set(out))


# ---------------------------------------------------------------------------------------------
# What the study needs to know of oedometer.py, read from its source (importing it needs YADE)
# ---------------------------------------------------------------------------------------------
class Script:
	def __init__(self, path):
		self.path = os.path.abspath(path)
		with open(self.path) as fh:
			self.text = fh.read()
		self.sha1 = sha1(self.text)
		self.params = {}  # name -> default (None if not a plain literal)
		self.packingKeys = None
		self.packingVersion = None
		try:
			tree = ast.parse(self.text)
		except SyntaxError as e:
			raise StudyError('--script: %s does not parse: %s' % (path, e))
		for node in ast.walk(tree):
			if isinstance(node, ast.Call) and getattr(node.func, 'id', None) == 'Param' and len(node.args) >= 2:
				try:
					self.params[ast.literal_eval(node.args[0])] = ast.literal_eval(node.args[1])
				except ValueError:
					pass
			if isinstance(node, ast.ClassDef):
				for st in node.body:
					if isinstance(st, ast.Assign) and len(st.targets) == 1 and isinstance(st.targets[0], ast.Name):
						try:
							if st.targets[0].id == 'PACKING_KEYS':
								self.packingKeys = list(ast.literal_eval(st.value))
							elif st.targets[0].id == 'PACKING_VERSION':
								self.packingVersion = ast.literal_eval(st.value)
						except ValueError:
							pass

	def packingKey(self, row):
		"""What decides the packing of a row: its seed and preparation parameters (the script's
		PACKING_KEYS; the seed alone if the script does not say)."""
		keys = self.packingKeys or ['seed']
		return tuple((k, cellValue(row[k]) if k in row else self.params.get(k)) for k in keys)

	def seed(self, row):
		return cellValue(row['seed']) if 'seed' in row else self.params.get('seed', 1)


def sameValue(a, b):
	if isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool):
		return a == b or abs(a - b) <= 1e-12 * max(abs(a), abs(b))
	return str(a).strip('\'"') == str(b).strip('\'"')


def packingExists(script, key, packings):
	"""Whether a stored packing already matches this key (then no run has to build it first)."""
	if script.packingKeys is None or script.packingVersion is None or not os.path.isdir(packings):
		return False
	want = dict(key)
	want['version'] = script.packingVersion
	if any(v is None for v in want.values()):
		return False
	prefix = 'packing-seed%s-' % want.get('seed')
	for name in os.listdir(packings):
		if name.startswith(prefix) and name.endswith('.json'):
			try:
				with open(os.path.join(packings, name)) as fh:
					have = json.load(fh).get('key', {})
			except (OSError, ValueError):
				continue
			if set(have) == set(want) and all(sameValue(have[k], want[k]) for k in want):
				return True
	return False


# ---------------------------------------------------------------------------------------------
# One run. The same function runs in a thread of this process (local) and on a Dask worker; it
# never raises, a failure is a result like any other.
# ---------------------------------------------------------------------------------------------
def seesStudy(out, token):
	"""True if this machine sees the study directory (a shared file system)."""
	try:
		with open(os.path.join(out, '.study-token')) as fh:
			return fh.read().strip() == token
	except OSError:
		return False


def batchTrailer(runId, rc, state, wall, cmd, started, finished):
	# the job summary yade-batch appends to each log
	return ('\n=================== JOB SUMMARY ================\nid      : %s\nstatus  : %d (%s)\nduration: %s\n'
	        'command : %s\nstarted : %s\nfinished: %s\n' % (
	            runId, rc, state, '%02d:%02d:%02d' % (wall // 3600, (wall % 3600) // 60, wall % 60),
	            cmd, time.asctime(time.localtime(started)), time.asctime(time.localtime(finished))))


def readFiles(top):
	files = {}
	for d, _, names in os.walk(top):
		for n in names:
			p = os.path.join(d, n)
			with open(p, 'rb') as fh:
				files[os.path.relpath(p, top)] = fh.read()
	return files


def runRow(spec, leader=None):
	"""Run one table row; returns a dict (status 'ok', 'failed', 'timeout' or 'stopped')."""
	import shlex
	runId, line = spec['runId'], spec['line']
	host = socket.gethostname()
	started = time.time()
	res = {'runId': runId, 'line': line, 'host': host, 'started': started, 'status': 'failed', 'rc': None, 'error': '',
	       'shared': False, 'files': None, 'packings': {}, 'log': None, 'summary': None}
	work = None
	try:
		shared = not spec.get('ship') and seesStudy(spec['out'], spec['token'])
		res['shared'] = shared
		if shared:
			base = os.path.join(spec['out'], 'work')
			os.makedirs(base, exist_ok=True)
			work = tempfile.mkdtemp(prefix=runId + '.', dir=base)
		else:
			work = tempfile.mkdtemp(prefix='study-%s.' % runId)
		table = os.path.join(work, 'table')
		with open(table, 'w') as fh:
			fh.write(spec['tableText'])
		# the script the client read, wherever this runs: its own file if identical, else the copy sent
		script = spec['scriptPath']
		try:
			with open(script) as fh:
				same = sha1(fh.read()) == spec['scriptSha1']
		except OSError:
			same = False
		if not same:
			script = os.path.join(work, os.path.basename(spec['scriptPath']))
			with open(script, 'w') as fh:
				fh.write(spec['scriptText'])
		if shared:
			pdir = spec['packings']
		else:
			pdir = os.path.join(work, 'packings')
			os.makedirs(pdir)
			sent = dict(spec['packingFiles'])
			if leader and leader.get('packings'):
				sent.update(leader['packings'])
			for name, data in sent.items():
				with open(os.path.join(pdir, name), 'wb') as fh:
					fh.write(data)
			before = set(sent)
		results = os.path.join(work, 'results')
		cmd = [spec['yade']] + (['--nice=%d' % spec['nice']] if spec['nice'] is not None else []) + [
		    '-n', '-x', script, '--results', results, '--runId', runId, '--packingDir', pdir]
		env = dict(os.environ)
		env.update(spec['env'])
		env.update({'YADE_BATCH': '%s:%d' % (table, line), 'DISPLAY': ''})
		res['command'] = ' '.join('%s=%s' % kv for kv in sorted(spec['env'].items())) + ' YADE_BATCH=%s:%d ' % (table, line) + \
		    ' '.join(shlex.quote(c) for c in cmd)
		logPath = os.path.join(work, 'run.log')
		stopEvent = None
		if spec.get('stopEvent'):
			try:
				from distributed import Event
				stopEvent = Event(spec['stopEvent'])
			except Exception:
				stopEvent = None
		with open(logPath, 'w') as log:
			proc = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL, env=env, cwd=work,
			                        start_new_session=True)  # own process group: a kill takes yade's children too
			lastAsk = time.time()
			why = None
			while True:
				try:
					proc.wait(timeout=0.5)
					break
				except subprocess.TimeoutExpired:
					pass
				if spec['timeout'] and time.time() - started > spec['timeout']:
					why = 'timeout'
				elif STOP['set']:
					why = 'stopped'
				elif stopEvent is not None and time.time() - lastAsk > 5:
					lastAsk = time.time()
					try:
						if stopEvent.is_set():
							why = 'stopped'
					except Exception:
						pass
				if why:
					for sig in (signal.SIGTERM, signal.SIGKILL):
						try:
							os.killpg(proc.pid, sig)
						except ProcessLookupError:
							break
						try:
							proc.wait(timeout=10)
							break
						except subprocess.TimeoutExpired:
							continue
					proc.wait()
					break
		finished = time.time()
		res.update(rc=proc.returncode, finished=finished, wall=finished - started)
		runDir = os.path.join(results, runId)
		summaryPath = os.path.join(runDir, 'summary.json')
		if os.path.exists(summaryPath):
			with open(summaryPath) as fh:
				res['summary'] = json.load(fh)
		ok = why is None and proc.returncode == 0 and res['summary'] is not None
		res['status'] = 'ok' if ok else (why or 'failed')
		if why == 'timeout':
			res['error'] = 'killed after the --timeout of %g s' % spec['timeout']
		elif why == 'stopped':
			res['error'] = 'stopped (the study was interrupted)'
		elif not ok:
			res['error'] = lastError(logPath) or ('exit code %d, no summary.json' % proc.returncode)
		with open(logPath, 'a') as log:
			log.write(batchTrailer(runId, proc.returncode, 'OK' if ok else ('STOPPED' if why == 'stopped' else 'FAILED'),
			                       int(finished - started), res['command'], started, finished))
		if ok:
			with open(os.path.join(runDir, 'row.json'), 'w') as fh:
				json.dump({'line': line, 'row': spec['row'], 'table': spec['tableName'], 'tableSha1': sha1(spec['tableText']),
				           'script': spec['scriptPath'], 'scriptSha1': spec['scriptSha1'], 'host': host, 'executor': spec['executor'],
				           'command': res['command'], 'started': started, 'wallSeconds': finished - started}, fh, indent=1)
		if shared:
			finalize(spec['out'], runId, res, runDir, logPath)
		else:
			# no shared file system: everything goes back to the client with the result
			with open(logPath) as fh:
				res['log'] = fh.read()
			res['files'] = readFiles(runDir) if os.path.isdir(runDir) else {}
			res['packings'] = {n: open(os.path.join(pdir, n), 'rb').read() for n in os.listdir(pdir)
			                   if n.endswith('.json') and n not in before}
	except Exception as e:  # a failure of the machinery is recorded like a failed run
		import traceback
		res['status'] = 'failed'
		res['error'] = 'study.py on %s: %s: %s' % (host, type(e).__name__, e)
		res['log'] = (res.get('log') or '') + traceback.format_exc()
		res.setdefault('finished', time.time())
		res['wall'] = res['finished'] - started
	finally:
		if work and os.path.isdir(work):
			shutil.rmtree(work, ignore_errors=True)
	return res


def leaderPackings(res):
	"""What a run waiting for a leader's packing needs of the leader's result."""
	return {'packings': res.get('packings') or {}}


def lastError(logPath):
	"""The line that says why a run failed: oedometer.py's 'bad parameter', else the exception."""
	try:
		with open(logPath, errors='replace') as fh:
			lines = [l.rstrip() for l in fh if l.strip()]
	except OSError:
		return ''
	for l in reversed(lines):
		if 'bad parameter' in l or re.match(r'^[A-Za-z_.]*(Error|Exception)\b', l):
			return l[:300]
	return lines[-1][:300] if lines else ''


def finalize(out, runId, res, runDir, logPath):
	"""Move a run's output into the study: runs/<id>/ if it finished, failed/<id>/ if not; its log
	to logs/<id>.log. Renames within one file system, so a run directory is never half there."""
	os.makedirs(os.path.join(out, 'logs'), exist_ok=True)
	os.replace(logPath, os.path.join(out, 'logs', runId + '.log'))
	res['finalized'] = True
	failed = os.path.join(out, 'failed', runId)
	if res['status'] == 'stopped':
		return  # interrupted, not failed: redone next time, even with --skip-failed
	if res['status'] == 'ok':
		final = os.path.join(out, 'runs', runId)
		os.makedirs(os.path.dirname(final), exist_ok=True)
		if os.path.exists(final):
			res['duplicate'] = True  # a worker lost and its task rerun elsewhere: keep the first
		else:
			os.rename(runDir, final)
		shutil.rmtree(failed, ignore_errors=True)
	else:
		shutil.rmtree(failed, ignore_errors=True)
		if os.path.isdir(runDir):
			os.makedirs(os.path.dirname(failed), exist_ok=True)
			os.rename(runDir, failed)


def finalizeShipped(out, packings, res):
	"""The client's half of a run done where --out is not visible: write what came back."""
	for name, data in (res.get('packings') or {}).items():
		if not os.path.exists(os.path.join(packings, name)):
			writeAtomic(os.path.join(packings, name), data)
	work = tempfile.mkdtemp(prefix=res['runId'] + '.', dir=os.path.join(out, 'work'))
	try:
		runDir = os.path.join(work, res['runId'])
		for rel, data in (res.get('files') or {}).items():
			p = os.path.join(runDir, rel)
			os.makedirs(os.path.dirname(p), exist_ok=True)
			with open(p, 'wb') as fh:
				fh.write(data)
		logPath = os.path.join(work, 'run.log')
		with open(logPath, 'w') as fh:
			fh.write(res.get('log') or '')
		finalize(out, res['runId'], res, runDir, logPath)
	finally:
		shutil.rmtree(work, ignore_errors=True)
	res['files'] = res['packings'] = res['log'] = None  # not kept in memory


# ---------------------------------------------------------------------------------------------
# Executors: both take the runs in order, a leader before the runs waiting for its packing
# ---------------------------------------------------------------------------------------------
class LocalExecutor:
	name = 'local'

	def __init__(self, jobs):
		self.jobs = jobs
		self.slots = jobs

	def run(self, tasks, onDone, onStart):
		from concurrent.futures import ThreadPoolExecutor, FIRST_COMPLETED, wait
		waiting = {}  # leader run id -> tasks needing its packing
		ready = []
		for t in tasks:
			(waiting.setdefault(t['leader'], []) if t['leader'] else ready).append(t)
		pool = ThreadPoolExecutor(self.jobs)
		running = {}

		def start(t, leaderRes):
			def job():
				if STOP['set']:
					return None
				onStart(t)
				return runRow(t['spec'], leaderRes)
			running[pool.submit(job)] = t

		for t in ready:
			start(t, None)
		try:
			while running:
				done, _ = wait(list(running), timeout=1.0, return_when=FIRST_COMPLETED)
				for fut in done:
					t = running.pop(fut)
					res = fut.result()
					if res is None:
						continue
					onDone(t, res)
					for d in waiting.pop(t['spec']['runId'], []):
						start(d, res)
		except KeyboardInterrupt:
			STOP['set'] = True  # every running run kills its yade, queued ones do not start
			for fut in running:
				fut.cancel()
			pool.shutdown(wait=True)
			raise
		pool.shutdown(wait=True)


class DaskExecutor:
	name = 'dask'

	def __init__(self, address, connectTimeout, schedulerFile=None):
		try:
			from distributed import Client
		except ImportError as e:
			raise StudyError('--executor dask: Dask distributed is not importable (%s); apt-get install python3-distributed' % e)
		try:
			if schedulerFile:
				self.client = Client(scheduler_file=schedulerFile, timeout='%ds' % connectTimeout, set_as_default=False)
			else:
				self.client = Client(address, timeout='%ds' % connectTimeout, set_as_default=False)
		except (OSError, TimeoutError, ValueError) as e:
			raise StudyError('%s: no Dask scheduler answers at %s (%s: %s)' % (
			    '--scheduler-file' if schedulerFile else '--scheduler', schedulerFile or address, type(e).__name__, e))
		self.address = self.client.scheduler.address
		self.slots = max(1, sum(self.client.nthreads().values()))

	def workersInfo(self):
		nt = self.client.nthreads()
		hosts = sorted(set(re.sub(r'^\w+://', '', a).rsplit(':', 1)[0] for a in nt))
		return '%d workers, %d threads, on %s' % (len(nt), sum(nt.values()), ', '.join(hosts) or 'no machine yet (tasks wait for workers)')

	def processing(self):
		"""Run ids the workers hold (running, or queued on a worker)."""
		try:
			keys = [k for ks in self.client.processing().values() for k in ks]
		except Exception:
			return None
		return [re.sub(r'^oedometer-(.*)-[0-9a-f]{8}$', r'\1', str(k)) for k in keys]

	def run(self, tasks, onDone, onStart):
		from distributed import as_completed, Event
		session = uuid.uuid4().hex[:8]
		stopName = 'study-stop-' + session
		stop = Event(stopName, client=self.client)
		futures = {}
		byId = {}
		# leaders first and with priority: the runs waiting for their packings can then start sooner
		packingsOf = {}
		for t in sorted(tasks, key=lambda t: t['leader'] is not None):
			spec = dict(t['spec'], stopEvent=stopName)
			dep = None
			if t['leader']:
				# the waiting runs need only the leader's new packings, not all its files
				lead = t['leader']
				if lead not in packingsOf:
					packingsOf[lead] = self.client.submit(leaderPackings, byId[lead], key='packings-%s-%s' % (lead, session), pure=False)
				dep = packingsOf[lead]
			key = 'oedometer-%s-%s' % (t['spec']['runId'], session)
			fut = self.client.submit(runRow, spec, dep, key=key, pure=False, priority=0 if t['leader'] else 10)
			futures[fut] = t
			byId[t['spec']['runId']] = fut
			onStart(t, quiet=True)
		try:
			for fut in as_completed(list(futures), loop=self.client.loop):
				t = futures[fut]
				try:
					res = fut.result()
				except Exception as e:  # e.g. KilledWorker: the worker died running it, too often
					res = {'runId': t['spec']['runId'], 'line': t['spec']['line'], 'status': 'failed', 'rc': None, 'host': '?',
					       'error': 'Dask: %s: %s' % (type(e).__name__, e), 'wall': None, 'shared': False, 'files': {}, 'packings': {},
					       'log': 'the task failed in Dask, not in yade: %s: %s\n' % (type(e).__name__, e), 'summary': None}
				onDone(t, res)
				byId.pop(t['spec']['runId'], None)  # lets Dask forget results nobody needs any more
				fut.release()
		except KeyboardInterrupt:
			stop.set()  # the running tasks kill their yade within a few seconds
			self.client.cancel(list(futures))
			time.sleep(6)
			raise
		finally:
			try:
				self.client.close()
			except Exception:
				pass


# ---------------------------------------------------------------------------------------------
# The study: which rows to run, bookkeeping, progress
# ---------------------------------------------------------------------------------------------
class Study:
	def __init__(self, args):
		self.args = args
		self.table = Table(args.table)
		self.script = Script(args.script)
		self.out = os.path.abspath(args.out or os.path.join('results', 'studies', re.sub(r'\.table$', '', os.path.basename(args.table))))
		self.packings = os.path.abspath(args.packings or os.path.join(os.path.dirname(self.out), 'packings'))
		for name, p in (('--out', self.out), ('--packings', self.packings)):
			if ':' in p:
				raise StudyError("%s: %s contains ':', which YADE_BATCH (table:line) cannot carry" % (name, p))
			if os.path.exists(p) and not os.path.isdir(p):
				raise StudyError('%s: %s exists and is not a directory' % (name, p))
		cols = self.table.parameterColumns()
		if self.script.params:
			unknown = [c for c in cols if c not in self.script.params]
			if unknown:
				raise StudyError('%s: column(s) %s are not parameters of %s (see yade -x %s --help)' % (
				    args.table, ', '.join(unknown), self.script.path, self.script.path))
		for c in ('results', 'runId', 'packingDir'):
			if c in cols:
				raise StudyError('%s: column %s is set by study.py for every run; remove it from the table' % (args.table, c))
		self.lines = parseLines(args.lines, self.table) if args.lines else [n for n, _ in self.table.rows]
		self.rows = dict(self.table.rows)

	def lock(self):
		import fcntl
		os.makedirs(self.out, exist_ok=True)
		self.lockFile = open(os.path.join(self.out, '.lock'), 'a+')
		try:
			fcntl.flock(self.lockFile, fcntl.LOCK_EX | fcntl.LOCK_NB)
		except OSError:
			raise StudyError('--out: %s is being run by another study.py right now' % self.out)

	def finishedRow(self, line):
		"""None if the run is not finished; else its row.json (checked against the table)."""
		rid = self.table.runId(line)
		d = os.path.join(self.out, 'runs', rid)
		if not os.path.exists(os.path.join(d, 'summary.json')):
			return None
		try:
			with open(os.path.join(d, 'row.json')) as fh:
				return json.load(fh)
		except (OSError, ValueError):
			return {}

	def prepare(self):
		"""Everything checked and set up before the first run starts."""
		self.lock()
		for d in ('runs', 'logs', 'failed'):
			os.makedirs(os.path.join(self.out, d), exist_ok=True)
		os.makedirs(self.packings, exist_ok=True)
		# a finished run made from a row that has changed since would be mixed into the results
		stale = []
		for n in self.lines:
			rr = self.finishedRow(n)
			if rr and rr.get('row') is not None and rr['row'] != self.rows[n]:
				diff = ', '.join('%s %s -> %s' % (k, rr['row'].get(k), self.rows[n].get(k))
				                 for k in sorted(set(rr['row']) | set(self.rows[n])) if rr['row'].get(k) != self.rows[n].get(k))
				stale.append('%s (line %d: %s)' % (self.table.runId(n), n, diff))
		if stale:
			raise StudyError('%s: finished run(s) in %s/runs were made from other values than the table now gives: %s. '
			                 'Remove those run directories or choose another --out.' % (self.args.table, self.out, '; '.join(stale[:5])))
		# attempts an interrupted study left unfinished are redone from scratch
		work = os.path.join(self.out, 'work')
		left = os.listdir(work) if os.path.isdir(work) else []
		shutil.rmtree(work, ignore_errors=True)
		os.makedirs(work)
		self.token = uuid.uuid4().hex
		writeAtomic(os.path.join(self.out, '.study-token'), self.token)
		writeAtomic(os.path.join(self.out, 'table'), self.table.text)
		info = {'table': os.path.abspath(self.args.table), 'tableSha1': sha1(self.table.text), 'script': self.script.path,
		        'scriptSha1': self.script.sha1, 'packings': self.packings, 'columns': self.table.columns,
		        'rows': [{'line': n, 'runId': self.table.runId(n), 'row': r} for n, r in self.table.rows]}
		writeAtomic(os.path.join(self.out, 'study.json'), json.dumps(info, indent=1))
		self.status = {}
		for n in self.lines:
			self.status[n] = {'status': 'finished' if self.finishedRow(n) is not None else self.previousStatus(n)}
		return len(left)

	def previousStatus(self, line):
		return 'failed' if os.path.isdir(os.path.join(self.out, 'failed', self.table.runId(line))) else 'todo'

	def tasks(self, todo):
		"""Runs in table order; of the runs that need the same, not yet stored packing, the one with
		the shortest loading cycle (highest f) runs first and the others wait for it."""
		groups = {}
		for n in todo:
			groups.setdefault(self.script.packingKey(self.rows[n]), []).append(n)
		leaderOf = {}
		for key, lines in groups.items():
			if len(lines) < 2 or packingExists(self.script, key, self.packings):
				continue

			def period(n):
				f = cellValue(self.rows[n].get('f', self.script.params.get('f', 1)))
				return 1 / f if isinstance(f, (int, float)) and f > 0 else float('inf')
			lead = min(lines, key=lambda n: (period(n), lines.index(n)))
			for n in lines:
				if n != lead:
					leaderOf[n] = self.table.runId(lead)
		env = {'OMP_NUM_THREADS': '1'}
		tasks = []
		for n in todo:
			row = self.rows[n]
			tenv = dict(env)
			for c, v in row.items():  # yade-batch's !COLUMNS: threads of the run, or an environment variable
				if c in ('!OMP_NUM_THREADS', '!THREADS'):
					tenv['OMP_NUM_THREADS'] = str(v)
				elif c.startswith('!') and c not in ('!SCRIPT', '!EXEC', '!AFFINITY', '!COUNT'):
					tenv[c[1:]] = str(v)
			seed = self.script.seed(row)
			pfiles = {}
			for name in sorted(os.listdir(self.packings)):
				if name.startswith('packing-seed%s-' % seed) and name.endswith('.json'):
					with open(os.path.join(self.packings, name), 'rb') as fh:
						pfiles[name] = fh.read()
			spec = {'runId': self.table.runId(n), 'line': n, 'row': row, 'tableText': self.table.text,
			        'tableName': os.path.abspath(self.args.table), 'scriptPath': self.script.path, 'scriptText': self.script.text,
			        'scriptSha1': self.script.sha1, 'yade': self.args.yade, 'nice': self.args.nice, 'env': tenv,
			        'out': self.out, 'token': self.token, 'packings': self.packings, 'packingFiles': pfiles,
			        'timeout': self.args.timeout, 'executor': self.args.executor, 'ship': self.args.ship}
			tasks.append({'spec': spec, 'leader': leaderOf.get(n)})
		return tasks

	def writeStatus(self):
		import csv
		import io
		buf = io.StringIO()
		w = csv.writer(buf, lineterminator='\n')  # run ids hold commas: quoted
		w.writerow(['line', 'runId', 'status', 'exitCode', 'wallSeconds', 'host', 'error'])
		for n in self.lines:
			s = self.status[n]
			w.writerow([n, self.table.runId(n), s['status'], '' if s.get('rc') is None else s['rc'],
			            '' if s.get('wall') is None else '%.1f' % s['wall'], s.get('host', ''), s.get('error') or ''])
		writeAtomic(os.path.join(self.out, 'status.csv'), buf.getvalue())

	def run(self, executor):
		args = self.args
		cleaned = self.prepare()
		todo = [n for n in self.lines if self.status[n]['status'] != 'finished']
		if args.skip_failed:
			todo = [n for n in todo if self.status[n]['status'] != 'failed']
		nDone = len(self.lines) - len([n for n in self.lines if self.status[n]['status'] != 'finished'])
		say('%s: %d rows%s, %d finished before (skipped), %d to run; results in %s' % (
		    args.table, len(self.lines), ' (--lines)' if args.lines else '', nDone, len(todo), self.out))
		if cleaned:
			say('removed %d unfinished attempt(s) left by an interrupted study; their runs are redone' % cleaned)
		old = {}
		for n in self.lines:
			rr = self.finishedRow(n)
			if rr and rr.get('scriptSha1') not in (None, self.script.sha1):
				old[rr['scriptSha1']] = old.get(rr['scriptSha1'], 0) + 1
		if old:
			say('warning: %d finished run(s) were made by another version of %s (sha1 %s); they are kept, not redone' % (
			    sum(old.values()), self.script.path, ', '.join(k[:10] for k in old)))
		tasks = self.tasks(todo)
		nLead = len(set(t['leader'] for t in tasks if t['leader']))
		if nLead:
			say('%d run(s) wait for the packing one of %d other run(s) builds first' % (len([t for t in tasks if t['leader']]), nLead))
		say('executor %s: %s' % (executor.name, executor.workersInfo() if executor.name == 'dask' else '%d parallel runs' % executor.jobs))
		self.writeStatus()
		if not todo:
			say('nothing to run')
			return 0
		counts = {'ok': 0, 'failed': 0}
		walls = []
		lock = threading.Lock()
		running = {}
		t0 = time.time()
		journal = open(os.path.join(self.out, 'journal.jsonl'), 'a')

		def onStart(t, quiet=False):
			with lock:
				running[t['spec']['runId']] = time.time()
				self.status[t['spec']['line']]['status'] = 'running' if not quiet else 'submitted'
			if not quiet and args.verbose:
				say('start  %s (line %d)' % (t['spec']['runId'], t['spec']['line']))

		def onDone(t, res):
			if not res.get('finalized'):
				if res.get('files') is not None:
					finalizeShipped(self.out, self.packings, res)
				elif res.get('log'):
					# the machinery failed before the run had output: what is known goes to its log
					writeAtomic(os.path.join(self.out, 'logs', res['runId'] + '.log'), res['log'])
			n = t['spec']['line']
			with lock:
				running.pop(res['runId'], None)
				ok = res['status'] == 'ok'
				counts['ok' if ok else 'failed'] += 1
				if ok and res.get('wall'):
					walls.append(res['wall'])
				self.status[n] = {'status': 'finished' if ok else res['status'], 'rc': res.get('rc'), 'wall': res.get('wall'),
				                  'host': res.get('host', ''), 'error': res.get('error', '')}
				rec = {k: res.get(k) for k in ('runId', 'line', 'status', 'rc', 'host', 'started', 'wall', 'error', 'command')}
				rec['executor'] = executor.name
				journal.write(json.dumps(rec) + '\n')
				journal.flush()
				self.writeStatus()
				done = counts['ok'] + counts['failed']
				left = len(todo) - done
				eta = ''
				if walls and left:
					# remaining runs spread over the slots, at the mean duration so far
					eta = ', ETA %s' % fmtTime(sum(walls) / len(walls) * -(-left // max(1, min(executor.slots, left))))
				if ok:
					s = res['summary'] or {}
					say('ok     %s (line %d) %s on %s: peak F %.0f kN at delta %.2f mm, %s crushed  [%d/%d, %d failed%s]' % (
					    res['runId'], n, fmtTime(res.get('wall')), res.get('host'), s.get('peakForce', float('nan')) / 1e3,
					    s.get('deltaAtPeak', float('nan')) * 1e3, s.get('nCrushed', '?'), done, len(todo), counts['failed'], eta))
				else:
					say('%-6s %s (line %d) %s: %s; log %s  [%d/%d, %d failed%s]' % (
					    res['status'].upper(), res['runId'], n, fmtTime(res.get('wall')), res.get('error'),
					    os.path.join(self.out, 'logs', res['runId'] + '.log'), done, len(todo), counts['failed'], eta))

		stopBeat = threading.Event()

		def heartbeat():
			while not stopBeat.wait(args.progress):
				with lock:
					now = time.time()
					run = sorted(running.items(), key=lambda kv: kv[1])
					done = counts['ok'] + counts['failed']
				if executor.name == 'local':
					what = ', '.join('%s %s' % (k, fmtTime(now - v)) for k, v in run[:6]) + (' ...' if len(run) > 6 else '')
					say('%d/%d done, running: %s' % (done, len(todo), what or '-'))
				else:
					held = executor.processing()
					if held is None:
						say('%d/%d done, %d queued or running on the cluster' % (done, len(todo), len(run)))
					else:
						say('%d/%d done, %d on the workers (%s%s), %d waiting' % (done, len(todo), len(held), ', '.join(sorted(held)[:6]),
						                                                         ' ...' if len(held) > 6 else '', len(run) - len(held)))

		beat = threading.Thread(target=heartbeat, daemon=True)
		beat.start()
		try:
			executor.run(tasks, onDone, onStart)
		except KeyboardInterrupt:
			stopBeat.set()
			for n in self.lines:
				if self.status[n]['status'] in ('running', 'submitted'):
					self.status[n]['status'] = 'todo'
			self.writeStatus()
			say('interrupted: %d ok, %d failed; the same command carries on where this stopped' % (counts['ok'], counts['failed']))
			return 130
		finally:
			stopBeat.set()
			journal.close()
		self.writeStatus()
		say('done in %s: %d ok, %d failed%s; status in %s' % (
		    fmtTime(time.time() - t0), counts['ok'], counts['failed'],
		    ' (their logs: %s/logs)' % self.out if counts['failed'] else '', os.path.join(self.out, 'status.csv')))
		rel = lambda p: p if os.path.relpath(p).startswith('..') else os.path.relpath(p)
		say('tables and figures: %s %s' % (rel(os.path.join(HERE, 'aggregate.py')), rel(self.out)))
		return 0 if counts['failed'] == 0 else 1


# ---------------------------------------------------------------------------------------------
# grid: write a table
# ---------------------------------------------------------------------------------------------
def gridValues(spec):
	"""NAME=V1,V2,... or NAME=A:B (integers A to B)."""
	m = re.fullmatch(r'([A-Za-z_]\w*!?)=(.+)', spec)
	if not m:
		raise StudyError('grid: %r is not NAME=V1,V2,... or NAME=A:B' % spec)
	name, vals = m.group(1), m.group(2)
	r = re.fullmatch(r'(-?\d+):(-?\d+)', vals)
	if r:
		a, b = int(r.group(1)), int(r.group(2))
		if b < a:
			raise StudyError('grid: %s: empty range %s' % (name, vals))
		return name, [str(v) for v in range(a, b + 1)]
	out = [v.strip() for v in vals.split(',')]
	if any(not v or re.search(r'\s', v) for v in out):
		raise StudyError('grid: %s: empty value or blank inside a value in %r' % (name, vals))
	return name, out


def grid(args):
	import itertools
	axes = [gridValues(s) for s in args.axes]
	fixed = [gridValues(s) for s in args.fixed]
	for name, vals in fixed:
		if len(vals) != 1:
			raise StudyError('--fixed: %s takes one value' % name)
	names = [n for n, _ in axes] + [n for n, _ in fixed]
	if len(set(n.rstrip('!') for n in names)) != len(names):
		raise StudyError('grid: a column is given twice')
	rows = [list(c) + [v[0] for _, v in fixed] for c in itertools.product(*[v for _, v in axes])]
	widths = [max(len(x) for x in [n] + [r[i] for r in rows]) for i, n in enumerate(names)]
	text = ''.join('# %s\n' % c for c in args.comment)
	text += '# written by: scripts/study.py grid %s\n' % ' '.join(
	    [a for a in args.axes] + ['--fixed %s' % f for f in args.fixed])
	text += ' '.join(n.ljust(w) for n, w in zip(names, widths)).rstrip() + '\n'
	for r in rows:
		text += ' '.join(x.ljust(w) for x, w in zip(r, widths)).rstrip() + '\n'
	Table(args.output or '<grid>', text)  # the table it writes must read back
	if args.output:
		writeAtomic(args.output, text)
		print('%s: %d rows' % (args.output, len(rows)), file=sys.stderr)
	else:
		sys.stdout.write(text)
	return 0


# ---------------------------------------------------------------------------------------------
# status: what a study directory holds
# ---------------------------------------------------------------------------------------------
def status(args):
	out = os.path.abspath(args.out)
	path = os.path.join(out, 'study.json')
	if not os.path.exists(path):
		raise StudyError('OUT: %s is not a study directory (no study.json)' % args.out)
	with open(path) as fh:
		info = json.load(fh)
	counts = {}
	for r in info['rows']:
		rid = r['runId']
		if os.path.exists(os.path.join(out, 'runs', rid, 'summary.json')):
			st = 'finished'
		elif os.path.isdir(os.path.join(out, 'failed', rid)) or failedLog(os.path.join(out, 'logs', rid + '.log')):
			st = 'failed'
		else:
			st = 'todo'
		counts.setdefault(st, []).append(rid)
	print('%s (%s): %d rows: %s' % (out, info['table'], len(info['rows']), ', '.join('%d %s' % (len(v), k) for k, v in sorted(counts.items()))))
	for rid in counts.get('failed', []):
		print('  failed: %s: %s (log %s)' % (rid, lastError(os.path.join(out, 'logs', rid + '.log')), os.path.join(out, 'logs', rid + '.log')))
	return 0


def failedLog(path):
	try:
		with open(path, errors='replace') as fh:
			return '(FAILED)' in fh.read()
	except OSError:
		return False


# ---------------------------------------------------------------------------------------------
def main(argv=None):
	ap = argparse.ArgumentParser(prog='scripts/study.py', description=__doc__.split('\n\n')[0],
	                             epilog='See docs/studies.md.', formatter_class=argparse.RawDescriptionHelpFormatter)
	sub = ap.add_subparsers(dest='command', metavar='COMMAND')
	ar = sub.add_parser('run', help='run (or carry on) a study table', description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
	ar.add_argument('table', metavar='TABLE', help='yade-batch table, one run per row, columns named as the parameters of the script')
	ar.add_argument('--executor', choices=('local', 'dask'), default='local', help='local: parallel runs on this machine; dask: through a Dask scheduler')
	ar.add_argument('--jobs', '-j', type=int, default=None, help='local: parallel runs (default: the cores of this machine, %d)' % len(os.sched_getaffinity(0)))
	ar.add_argument('--scheduler', metavar='ADDRESS', help='dask: address of the scheduler, e.g. tcp://127.0.0.1:8786')
	ar.add_argument('--scheduler-file', metavar='JSON', help='dask: instead of --scheduler, the file dask-scheduler --scheduler-file wrote')
	ar.add_argument('--connect-timeout', type=int, default=20, metavar='S', help='dask: seconds to wait for the scheduler (default 20)')
	ar.add_argument('--out', metavar='DIR', help='study directory (default results/studies/<table name without .table>)')
	ar.add_argument('--packings', metavar='DIR', help='stored packings (default: "packings" next to --out, shared by the studies there)')
	ar.add_argument('--script', default=DEFAULT_SCRIPT, metavar='PY', help='the simulation (default %(default)s)')
	ar.add_argument('--yade', default='yade', metavar='EXE', help='YADE executable on the machines that run (default %(default)s)')
	ar.add_argument('--ship', action='store_true', help='dask: send script, table and packings with every task and the results '
	                'back, even to workers that see --out (as for machines without a shared file system)')
	ar.add_argument('--lines', '-l', metavar='LIST', help="only these lines of the table, yade-batch's format 2,3-5,8")
	ar.add_argument('--timeout', type=float, default=None, metavar='S', help='kill a run after S seconds of wall time (a failed run)')
	ar.add_argument('--nice', type=int, default=10, help="nice value of the runs, as yade-batch's (default 10)")
	ar.add_argument('--skip-failed', action='store_true', help='do not redo the runs that failed before')
	ar.add_argument('--progress', type=float, default=60, metavar='S', help='seconds between progress lines (default 60)')
	ar.add_argument('--verbose', '-v', action='store_true', help='a line also when a run starts')
	ar.add_argument('--dry-run', action='store_true', help='list what would run and stop')
	ag = sub.add_parser('grid', help='write a table: every combination of the values given',
	                    description='Write a yade-batch table with every combination of the values. The first NAME varies slowest. '
	                    'Example: scripts/study.py grid seed=1:60 Tc=0,7.8125e-5,0.04 -o studies/Tc.table')
	ag.add_argument('axes', nargs='+', metavar='NAME=VALUES', help='V1,V2,... or A:B (integers A to B); NAME! marks the run id columns')
	ag.add_argument('--fixed', action='append', default=[], metavar='NAME=V', help='a column with the same value in every row')
	ag.add_argument('--comment', action='append', default=[], help='a comment line at the top')
	ag.add_argument('--output', '-o', metavar='FILE', help='write here (default: standard output)')
	ast_ = sub.add_parser('status', help='what a study directory holds')
	ast_.add_argument('out', metavar='OUT', help='the study directory')
	args = ap.parse_args(argv)

	def interrupt(signum, frame):
		raise KeyboardInterrupt  # a killed study (ssh hang-up, scancel) stops its runs as Ctrl-C does
	for sig in (signal.SIGTERM, signal.SIGHUP):
		signal.signal(sig, interrupt)
	if args.command is None:
		ap.print_help()
		return 2
	try:
		if args.command == 'grid':
			return grid(args)
		if args.command == 'status':
			return status(args)
		# every argument checked before any run starts
		if not os.path.isfile(args.table):
			raise StudyError('TABLE: no such file: %s' % args.table)
		if not os.path.isfile(args.script):
			raise StudyError('--script: no such file: %s' % args.script)
		if args.timeout is not None and args.timeout <= 0:
			raise StudyError('--timeout: must be > 0 seconds, got %g' % args.timeout)
		if args.progress <= 0:
			raise StudyError('--progress: must be > 0 seconds, got %g' % args.progress)
		if args.executor == 'local':
			if args.scheduler or args.scheduler_file:
				raise StudyError('--scheduler: only with --executor dask')
			jobs = args.jobs if args.jobs is not None else len(os.sched_getaffinity(0))
			if jobs < 1:
				raise StudyError('--jobs: must be >= 1, got %d' % jobs)
			if not shutil.which(args.yade):
				raise StudyError('--yade: %s is not an executable on this machine' % args.yade)
		else:
			if args.jobs is not None:
				raise StudyError('--jobs: only with --executor local (Dask runs as many as its workers have threads)')
			if args.scheduler and args.scheduler_file:
				raise StudyError('--scheduler-file: give either --scheduler or --scheduler-file')
			if args.scheduler_file and not os.path.isfile(args.scheduler_file):
				raise StudyError('--scheduler-file: no such file: %s' % args.scheduler_file)
			if not args.scheduler and not args.scheduler_file:
				raise StudyError('--scheduler: --executor dask needs the address of a running scheduler, e.g. tcp://127.0.0.1:8786')
			if args.scheduler and not re.match(r'^(tcp|tls|inproc|ucx)://\S+$', args.scheduler) and not re.match(r'^[\w.-]+:\d+$', args.scheduler):
				raise StudyError('--scheduler: %r is not an address like tcp://host:8786' % args.scheduler)
		study = Study(args)
		if args.dry_run:
			for n in study.lines:
				fin = study.finishedRow(n) is not None
				print('%4d  %-40s %s' % (n, study.table.runId(n), 'finished (skipped)' if fin else 'to run'))
			return 0
		executor = LocalExecutor(jobs) if args.executor == 'local' else DaskExecutor(args.scheduler, args.connect_timeout, args.scheduler_file)
		return study.run(executor)
	except StudyError as e:
		sys.stderr.write('study.py: %s\n' % e)
		return 2


if __name__ == '__main__':
	try:
		sys.exit(main())
	except BrokenPipeError:  # output piped into head & co.
		sys.exit(0)
