#!/usr/bin/env bash
# The default case of `./setup.sh demo`: the fluidized test column, coupled, on 2 MPI ranks, then its plots.
set -euo pipefail
build=${1:?usage: run_demo.sh BUILD_DIR}
here=$(cd "$(dirname "$0")" && pwd)
case_dir="$here/fluidized_column"
out="$(cd "$here/.." && pwd)/runs/fluidized_column"
ranks=$(( $(nproc) >= 2 ? 2 : 1 ))
echo "== running cases/fluidized_column on $ranks rank(s); output in runs/fluidized_column"
mpirun -np "$ranks" "$build/bin/parcelflow" run "$case_dir" --output "$out"
/usr/bin/python3 "$case_dir/plot.py" "$out"
