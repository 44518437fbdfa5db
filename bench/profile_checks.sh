#!/usr/bin/env bash
# Instruction counts of YADE steps with and without the ballast engines (valgrind's callgrind):
# repeatable on a busy machine, unlike wall time. Usage: bash bench/profile_checks.sh [GRAINS] [STEPS]
# Writes bench/profile/callgrind.<variant> and prints instructions per step and the ratio to plain,
# then the functions that cost most with both engines every step (callgrind_annotate).
set -euo pipefail
cd "$(dirname "$(readlink -f "$0")")/.."
GRAINS=${1:-200}
STEPS=${2:-50}
WARM=20  # steps bench_checks.hcpBox runs before the engines are added (counted for every variant)
command -v valgrind >/dev/null || { echo "profile_checks.sh: valgrind is not installed (apt-get install valgrind)" >&2; exit 1; }
mkdir -p bench/profile
for v in plain crush both bothFull; do
  OMP_NUM_THREADS=1 valgrind --tool=callgrind --toggle-collect='*moveToNextTimeStep*' \
    --callgrind-out-file="bench/profile/callgrind.$v" yade -n -x bench/profile_checks.py "$v" "$GRAINS" "$STEPS" \
    > "bench/profile/$v.log" 2>&1
  grep -h "profile_checks:" "bench/profile/$v.log"
done
/usr/bin/python3 - "$STEPS" "$WARM" <<'PY' | tee bench/profile/summary.txt
import re, sys
steps, warm = int(sys.argv[1]), int(sys.argv[2])
ir = {}
for v in ('plain', 'crush', 'both', 'bothFull'):
    with open('bench/profile/%s.log' % v) as fh:
        ir[v] = int(re.search(r'Collected : (\d+)', fh.read()).group(1))
perStep = ir['plain'] / (steps + warm)
print('%-9s %14s %14s %8s' % ('variant', 'instructions', 'extra/step', 'x plain'))
for v, n in ir.items():
    extra = (n - ir['plain']) / steps
    print('%-9s %14d %14.0f %8.3f' % (v, n, extra, (perStep + extra) / perStep))
PY
{ echo; echo "both engines every step: functions by own instruction count (callgrind_annotate)";
  callgrind_annotate bench/profile/callgrind.both 2>/dev/null | sed -n '25,50p' | cut -c1-140; } >> bench/profile/summary.txt || true
echo "profile_checks.sh: table and top functions in bench/profile/summary.txt"

