"""pytest set-up: Debian's python3 finds YADE only under yade-double/py (the dist-packages link
shipped by python3-yade is broken), so the engine tests add that path themselves."""
import os
import sys

# One OpenMP thread, as `yade` runs by default: YADE's threads spin-wait, and on a loaded 2-core
# machine a test would crawl. Must be set before YADE's libraries load.
os.environ.setdefault('OMP_NUM_THREADS', '1')

YADE_PY = '/usr/lib/x86_64-linux-gnu/yade-double/py'
if YADE_PY not in sys.path:
    sys.path.append(YADE_PY)
