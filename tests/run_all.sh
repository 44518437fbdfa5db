#!/usr/bin/env bash
# Runs every test: the C++ core with ctest, then the Python binding and the YADE engines with pytest
# under Debian's /usr/bin/python3 against the installed package. Exit code non-zero if any fails.
set -uo pipefail
cd "$(dirname "$(readlink -f "$0")")/.."
status=0
echo "== C++ core (GoogleTest through ctest)"
(cd build && ctest --output-on-failure) || status=1
echo "== Python binding and YADE engines (pytest)"
# Run from outside the tree so the installed package is what is imported.
(cd /tmp && /usr/bin/python3 -m pytest -q -p no:cacheprovider "$OLDPWD/tests/python") || status=1
exit $status
