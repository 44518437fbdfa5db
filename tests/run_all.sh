#!/usr/bin/env bash
# Runs every test: the C++ core with ctest, then the Python binding and the YADE engines with pytest
# under Debian's /usr/bin/python3 against the installed package. Exit code non-zero if any fails.
set -uo pipefail
cd "$(dirname "$(readlink -f "$0")")/.."
status=0
echo "== C++ core (GoogleTest through ctest)"
(cd build && ctest --output-on-failure) || status=1
echo "== Python binding and YADE engines (pytest)"
# Run from outside the tree so the installed package is what is imported; a worker per core (pytest-xdist), each
# test file whole on one worker so its module fixtures (the small specimens, beds and runs) are built once; the 30
# slowest tests listed at the end (issue 48, item 9: where the suite's time goes).
(cd /tmp && /usr/bin/python3 -m pytest -q -p no:cacheprovider -n auto --dist loadfile --durations=30 "$OLDPWD/tests/python") || status=1
exit $status
