#!/usr/bin/env bash
# Set up, build and install the ballast extension on Debian 12 (as root). Idempotent: a second run
# installs no package and rebuilds only what changed.
#   bash setup.sh            set up and build
#   bash setup.sh --main     ... then run the main job (the oedometer test)
#   bash setup.sh --test     ... then run every test (C++ and Python)
set -euo pipefail
cd "$(dirname "$(readlink -f "$0")")"

# Everything comes from Debian's packages.
PACKAGES=(yade libeigen3-dev libboost-python-dev libboost-numpy-dev python3-dev python3-numpy python3-scipy python3-pandas
          python3-pytest python3-pytest-xdist python3-matplotlib python3-distributed python3-vtk9 cmake g++ make libgtest-dev)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  if [ "$(id -u)" -ne 0 ]; then
    echo "setup: packages missing (${missing[*]}); run this script as root to install them" >&2
    exit 1
  fi
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q
  apt-get install -y -q --no-install-recommends "${missing[@]}"
else
  echo "setup: all ${#PACKAGES[@]} Debian packages present"
fi

# Build for Debian's /usr/bin/python3 (the interpreter yade runs), whatever python3 is first on PATH.
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3 >/dev/null
cmake --build build -j "$(nproc)"
# Installs under /usr/local, where Debian's python3 and yade look: `import ballast` needs no variable.
if [ -w /usr/local/lib ]; then
  cmake --install build | grep -v "Up-to-date" || true
else
  echo "setup: not root, not installing; use PYTHONPATH=$PWD/build/py" >&2
fi

case "${1:-}" in
  --main) shift; exec bash scripts/run_main.sh "$@" ;;
  --test) shift; exec bash tests/run_all.sh "$@" ;;
  "") ;;
  *) echo "setup: unknown option '$1' (expected --main or --test)" >&2; exit 2 ;;
esac
