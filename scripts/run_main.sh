#!/usr/bin/env bash
# The main job (README): one realization of the paper's oedometric test with the default parameters.
# Extra arguments go to the script (e.g. --f 2 --pattern 14); results in results/<run id>/.
set -euo pipefail
cd "$(dirname "$(readlink -f "$0")")/.."
export OMP_NUM_THREADS="${OMP_NUM_THREADS:-1}"
exec yade -n -x scripts/oedometer.py "$@"
