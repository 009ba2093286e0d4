#!/usr/bin/env bash
# parcelflow setup: installs the Debian packages it needs (only the missing ones), builds, and then
#   ./setup.sh demo    runs the default case and writes its plots
#   ./setup.sh test    runs the test suite (unit + regression + validation smoke tests)
#   ./setup.sh build   only installs and builds
#   ./setup.sh bench   runs the benchmarks (not part of the tests; they print numbers)
#   (long verification runs, not in `test`: cd build && ctest -L long)
set -euo pipefail

action=${1:-build}
case "$action" in demo|test|build|bench) ;; *)
  echo "usage: ./setup.sh demo|test|build|bench  (got '$action')" >&2; exit 2;;
esac
root=$(cd "$(dirname "$0")" && pwd)
build=${PARCELFLOW_BUILD_DIR:-$root/build}

packages=(cmake g++ make pkg-config
          libliggghts-dev liggghts liggghts-doc libopenmpi-dev openmpi-bin
          libeigen3-dev libhdf5-openmpi-dev libmetis-dev libyaml-cpp-dev libgtest-dev libhypre-dev libcgal-dev
          python3 python3-numpy python3-scipy python3-matplotlib python3-h5py python3-yaml)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "== installing Debian packages: ${missing[*]}"
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo=sudo
  $sudo apt-get update
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y --no-install-recommends "${missing[@]}"
fi

# Open MPI refuses to start as root unless told; containers and CI run as root.
if [ "$(id -u)" -eq 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
export OMPI_MCA_rmaps_base_oversubscribe=1

echo "== building parcelflow in $build"
mkdir -p "$build"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release > "$build/configure.log" 2>&1 ||
  { cat "$build/configure.log"; exit 1; }
cmake --build "$build" -j "$(nproc)"

case "$action" in
  demo)  exec "$root/cases/run_demo.sh" "$build" ;;
  test)  cd "$build" && exec ctest -LE "benchmark|long" --output-on-failure --timeout 1200 -j "$(nproc)" ;;
  bench) cd "$build" && exec ctest -L benchmark --verbose ;;
  build) echo "== built: $build/bin/parcelflow" ;;
esac
