"""The yade process of one run of a study: started in a session of its own with a parent-death signal, watched
by a watchdog that kills what is left of its process group whenever the runner ends (a SIGKILL from the OOM killer or
Slurm too), killed past its deadline or when the study is stopped (Ctrl-C here, or the study's Dask event)."""
import ctypes
import functools
import os
import signal
import subprocess
import sys
import threading
import time

# Set on Ctrl-C by the local executor: every running run kills its yade and returns.
STOP = threading.Event()
POLL = 0.2        # [s] how often a run checks its yade, the --timeout and STOP
ASK_DASK = 5.0    # [s] how often a run on a Dask worker asks whether the study was stopped
KILL_WAIT = 10.0  # [s] after SIGTERM, before SIGKILL
PR_SET_PDEATHSIG = 1  # prctl option of Linux: the signal a process gets when its parent dies
PRCTL = ctypes.CDLL(None, use_errno=True).prctl  # looked up here, not between fork and exec

# The watchdog of one run (see runYade), in a session of its own: reads the process group of the
# run's yade, then waits for its stdin to close, which happens when the run is over or when the
# runner died, however it died, and kills what is left of the group: yade's children have no
# parent-death signal of their own. A zombie counts as gone: an orphan's waits for init to reap it.
WATCHDOG = r'''
import os, signal, sys, time

def alive(group):
    for pid in filter(str.isdigit, os.listdir('/proc')):
        try:
            with open('/proc/%s/stat' % pid) as fh:
                state, _, pgrp = fh.read().rsplit(')', 1)[1].split()[:3]
        except (OSError, ValueError):
            continue
        if int(pgrp) == group and state != 'Z':
            return True
    return False

line = sys.stdin.readline()
sys.stdin.read()
group = int(line) if line else None  # None: yade did not start
for sig in (signal.SIGTERM, signal.SIGKILL):
    if group is None or not alive(group):
        break
    try:
        os.killpg(group, sig)
    except ProcessLookupError:  # gone meanwhile
        break
    end = time.time() + float(sys.argv[1])
    while alive(group) and time.time() < end:
        time.sleep(0.05)
'''


def stopRequested(spec):
    """A function telling whether the study was stopped: Ctrl-C here, or the Dask event of the study."""
    if not spec.get('stopEvent'):
        return STOP.is_set
    try:
        from distributed import Event
        event = Event(spec['stopEvent'])
    except Exception:
        return STOP.is_set
    asked = [0.0]  # the first call asks: a run does not start once the study is stopped

    def stopped():
        if time.time() - asked[0] < ASK_DASK:
            return False
        asked[0] = time.time()
        try:
            return event.is_set()
        except Exception:
            return False
    return stopped


def dieWithParent(parent):
    """preexec_fn of a run's yade: SIGTERM when the runner's thread that started it ends, killed
    too; at once if the runner (pid `parent`) died before this was set."""
    if PRCTL(PR_SET_PDEATHSIG, int(signal.SIGTERM), 0, 0, 0) != 0:
        raise OSError(ctypes.get_errno(), 'prctl(PR_SET_PDEATHSIG, SIGTERM)')
    if os.getppid() != parent:
        os.kill(os.getpid(), signal.SIGTERM)


def niceGroup(nice):
    """preexec_fn part: nice the scheduling group (autogroup) of the session the run has just made. Under a kernel
    that groups by session (Debian 12's default) the run's own nice value ranks it only within that session, so a
    niced study would still take a full share of the machine beside a test suite or an interactive session. A kernel
    without autogroup has no such file: the nice value alone then does it."""
    try:
        with open('/proc/self/autogroup', 'w') as fh:
            fh.write(str(nice))
    except OSError:
        pass


def startRun(parent, nice):
    """preexec_fn of a run's yade (after its setsid): it dies with the runner, and its group is niced."""
    dieWithParent(parent)
    if nice is not None and nice > 0:
        niceGroup(nice)


def runYade(cmd, env, cwd, logPath, deadline, stopped, keepFds=(), nice=None):
    """Run cmd with its output in logPath; kill it (and its children: its own process group) past
    the deadline or when stopped(). keepFds: descriptors it inherits (the run's lock); nice: the run's
    nice value, given to the scheduling group of its session as well (niceGroup). Should this
    process die first, the run dies with it: yade by its parent-death signal, what it started by the
    watchdog. Returns (exit code, None or 'timeout' or 'stopped')."""
    watchdog = subprocess.Popen([sys.executable, '-I', '-S', '-c', WATCHDOG, str(KILL_WAIT)], stdin=subprocess.PIPE,
                                stdout=subprocess.DEVNULL, start_new_session=True)
    try:
        with open(logPath, 'w') as log:
            proc = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL, env=env, cwd=cwd,
                                    start_new_session=True, pass_fds=keepFds,
                                    preexec_fn=functools.partial(startRun, os.getpid(), nice))
        watchdog.stdin.write(b'%d\n' % proc.pid)
        watchdog.stdin.flush()
        while True:
            try:
                return proc.wait(timeout=POLL), None
            except subprocess.TimeoutExpired:
                pass
            why = 'timeout' if deadline and time.time() > deadline else ('stopped' if stopped() else None)
            if why:
                for sig in (signal.SIGTERM, signal.SIGKILL):
                    try:
                        os.killpg(proc.pid, sig)
                    except ProcessLookupError:
                        break
                    try:
                        proc.wait(timeout=KILL_WAIT)
                        break
                    except subprocess.TimeoutExpired:
                        continue
                return proc.wait(), why
    finally:
        watchdog.stdin.close()  # the run is over: the watchdog kills what is left of its group, if anything
        watchdog.wait()
