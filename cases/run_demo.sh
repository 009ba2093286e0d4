#!/usr/bin/env bash
# The default case of `./setup.sh demo`: a short run of the Goldschmidt segregation bed (the paper's first
# validation), coupled on 2 MPI ranks, then its plots. PARCELFLOW_DEMO_END sets the simulated seconds.
set -euo pipefail
build=${1:?usage: run_demo.sh BUILD_DIR}
here=$(cd "$(dirname "$0")" && pwd)
case_dir="$here/goldschmidt_segregation"
out="$(cd "$here/.." && pwd)/runs/goldschmidt_segregation"
end=${PARCELFLOW_DEMO_END:-2.0}
ranks=$(( $(nproc) >= 2 ? 2 : 1 ))
echo "== running cases/goldschmidt_segregation for $end s of simulated time on $ranks rank(s);" \
     "output in runs/goldschmidt_segregation"
mpirun -np "$ranks" "$build/bin/parcelflow" run "$case_dir" --output "$out" --end "$end"
"$case_dir/plot.py" "$out"
