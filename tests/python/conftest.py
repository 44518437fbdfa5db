"""pytest set-up: Debian's python3 finds YADE only under yade-double/py (the dist-packages link
shipped by python3-yade is broken), so the engine tests add that path themselves."""
import sys

YADE_PY = '/usr/lib/x86_64-linux-gnu/yade-double/py'
if YADE_PY not in sys.path:
    sys.path.append(YADE_PY)
