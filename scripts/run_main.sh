#!/usr/bin/env bash
# The main job (README): until the oedometer lands, the single-grain crushing demo.
set -euo pipefail
cd "$(dirname "$(readlink -f "$0")")/.."
exec yade -n -x scripts/single_grain.py "$@"
