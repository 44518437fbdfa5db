"""What a study says of its runs: while it runs (:class:`Progress`: status.csv, journal.jsonl, a line per finished
run and the runs going on) and afterwards, from its directory alone (:func:`status`)."""
import json
import os
import threading
import time

from ..names import fmtTime
from ..runfiles import readSummary, writeAtomic
from .attempts import KEEP, failedLog, keptState, lastError, newestLog, rowHeld, runProgress
from .options import StudyError
from .runner import finalizeShipped


class Progress:
    """The bookkeeping while a study runs: status.csv, journal.jsonl, a line per finished run and
    every `progress` seconds a line on the runs going on."""

    def __init__(self, study, executor, nTodo):
        self.study, self.executor, self.nTodo = study, executor, nTodo
        self.counts = {'ok': 0, 'failed': 0}
        self.walls = []
        self.running = {}  # run id -> start time
        self.lock = threading.Lock()

    def onStart(self, t, quiet=False):
        with self.lock:
            self.running[t['spec']['runId']] = time.time()
            self.study.status[t['spec']['line']]['status'] = 'submitted' if quiet else 'running'
        if not quiet and self.study.verbose:
            self.study.say('start  %s (line %d)' % (t['spec']['runId'], t['spec']['line']))

    def onDone(self, t, res):
        st = self.study
        if not res.get('finalized'):
            if res.get('files') is not None:
                finalizeShipped(st.out, st.packings, res)
            elif res.get('log'):
                # the machinery failed before the run had output: what is known goes to its log
                writeAtomic(os.path.join(st.out, 'logs', res['runId'] + '.log'), res['log'])
        n = t['spec']['line']
        with self.lock:
            self.running.pop(res['runId'], None)
            ok = res['status'] == 'ok'
            if res['status'] != 'stopped':  # neither: redone next time
                self.counts['ok' if ok else 'failed'] += 1
            if ok and res.get('wall'):
                self.walls.append(res['wall'])
            if ok:
                try:
                    st.keepRecord(n)
                except (OSError, ValueError) as e:  # the run itself is finished and kept in runs/
                    st.say('warning: no record of %s in %s: %s' % (res['runId'], st.records, e))
            st.status[n] = {'status': 'finished' if ok else res['status'], 'rc': res.get('rc'), 'wall': res.get('wall'),
                            'host': res.get('host', ''), 'error': res.get('error', '')}
            rec = {k: res.get(k) for k in ('runId', 'line', 'status', 'rc', 'host', 'started', 'wall', 'error', 'command')}
            rec['executor'] = self.executor.name
            self.journal.write(json.dumps(rec) + '\n')
            self.journal.flush()
            st.writeStatus()
            done = self.counts['ok'] + self.counts['failed']
            left = self.nTodo - done
            eta = ''
            if self.walls and left:
                # remaining runs spread over the slots, at the mean duration so far
                eta = ', ETA %s' % fmtTime(sum(self.walls) / len(self.walls) * -(-left // max(1, min(self.executor.slots, left))))
            tally = '[%d/%d, %d failed%s]' % (done, self.nTodo, self.counts['failed'], eta)
            if ok:
                s = res['summary'] or {}
                st.say('ok     %s (line %d) %s on %s: %s  %s' % (res['runId'], n, fmtTime(res.get('wall')), res.get('host'),
                                                               st.declaration.brief(s), tally))
            else:
                st.say('%-6s %s (line %d) %s: %s; log %s  %s' % (
                    res['status'].upper(), res['runId'], n, fmtTime(res.get('wall')), res.get('error'),
                    os.path.join(st.out, 'logs', res['runId'] + '.log'), tally))

    def heartbeat(self, stop):
        while not stop.wait(self.study.progress):
            with self.lock:
                now = time.time()
                run = sorted(self.running.items(), key=lambda kv: kv[1])
                done = self.counts['ok'] + self.counts['failed']
            if self.executor.name == 'local':
                work = os.path.join(self.study.out, 'work')
                what = ', '.join('%s %s%s' % (k, fmtTime(now - v), ' (%s)' % p if (p := runProgress(work, k)) else '')
                                 for k, v in run[:6]) + (' ...' if len(run) > 6 else '')
                self.study.say('%d/%d done, running: %s' % (done, self.nTodo, what or '-'))
                continue
            held = self.executor.processing()
            if held is None:
                self.study.say('%d/%d done, %d queued or running on the cluster' % (done, self.nTodo, len(run)))
            else:
                self.study.say('%d/%d done, %d on the workers (%s%s), %d waiting' % (
                    done, self.nTodo, len(held), ', '.join(sorted(held)[:6]), ' ...' if len(held) > 6 else '', len(run) - len(held)))

    def run(self, tasks):
        st = self.study
        t0 = time.time()
        stop = threading.Event()
        threading.Thread(target=self.heartbeat, args=(stop,), daemon=True).start()
        self.journal = open(os.path.join(st.out, 'journal.jsonl'), 'a')
        try:
            self.executor.run(tasks, self.onDone, self.onStart)
        except KeyboardInterrupt:
            for n in st.lines:
                if st.status[n]['status'] in ('running', 'submitted'):
                    st.status[n]['status'] = 'todo'
            st.writeStatus()
            st.say('interrupted: %d ok, %d failed; the same command carries on where this stopped' % (
                self.counts['ok'], self.counts['failed']))
            return 130
        finally:
            stop.set()
            self.journal.close()
        st.writeStatus()
        st.say('done in %s: %d ok, %d failed%s; status in %s' % (
            fmtTime(time.time() - t0), self.counts['ok'], self.counts['failed'],
            ' (their logs: %s/logs)' % st.out if self.counts['failed'] else '', os.path.join(st.out, 'status.csv')))
        return 0 if self.counts['failed'] == 0 else 1


def status(out):
    """Print what a study directory holds: finished, failed (with the line of the log that says
    why), still to run, and not selected (outside the --lines of its last start)."""
    out = os.path.abspath(out)
    path = os.path.join(out, 'study.json')
    if not os.path.exists(path):
        raise StudyError('OUT: %s is not a study directory (no study.json)' % out)
    with open(path) as fh:
        info = json.load(fh)
    counts = {}
    selected = set(info.get('lines', [r['line'] for r in info['rows']]))  # older folders: every row
    for r in info['rows']:
        rid = r['runId']
        if readSummary(os.path.join(out, 'runs', rid))[0] is not None:
            st = 'finished'
        elif os.path.isdir(os.path.join(out, 'failed', rid)) or failedLog(os.path.join(out, 'logs', rid + '.log')):
            st = 'failed'
        else:
            st = 'todo' if r['line'] in selected else 'not selected'
        counts.setdefault(st, []).append(rid)
    print('%s (%s): %d rows: %s' % (out, info['table'], len(info['rows']),
                                    ', '.join('%d %s' % (len(v), k) for k, v in sorted(counts.items()))))
    for rid in counts.get('failed', []):
        log = os.path.join(out, 'logs', rid + '.log')
        print('  failed: %s: %s (log %s)' % (rid, lastError(log), log))
    for rid in counts.get('todo', []):  # started and not ended: running, or its runner died (its lock says which)
        work = os.path.join(out, 'work')
        log = newestLog(work, rid)
        if log is not None:
            alive = rowHeld(work, rid)
            print('  %s: %s: %s, its log written %s ago (%s)' % (
                'running' if alive else 'killed', rid,
                (runProgress(work, rid) or 'no progress line yet') if alive else
                'its runner ended without an end recorded (killed, or its machine went down); the next start runs it '
                'again (from its kept state if it saved one)',
                fmtTime(max(0, time.time() - os.path.getmtime(log))), log))
        state = keptState(os.path.join(out, KEEP), rid)
        if state is not None:
            print('  kept: %s goes on from its %s at its next start (%s)' % (
                rid, os.path.basename(state), os.path.join(out, KEEP, rid)))
