#!/usr/bin/env bash
# Time to quality (docs/benchmarks.md): the fixed subset of 10 Blender-built models (gt-dev) and 10
# real ones (real-dev, the first 4 of real-tune) searched with a seconds cap of 15, 30, 60 and 120
# and no work limit, once at --threads 1 (two models at once) and once at --threads 2 (one at a
# time), so both use the machine's two cores. Writes out/time_to_quality/tTHREADS/bBUDGET/ (the
# run_results outputs and records) and plots median Chamfer, F1@0.01 and seconds used against the
# cap: docs/images/time_to_quality.png, and its table on stdout (plot_time_to_quality.py).
# 49 minutes on 2 cores at 6205340; run it on an otherwise idle machine (the caps are wall time).
#   bash benchmarks/time_to_quality.sh [--budgets "15 30 60 120"] [--threads "1 2"]
set -euo pipefail
cd "$(dirname "$0")/.."
budgets="15 30 60 120"
thread_counts="1 2"
while [ $# -gt 0 ]; do
  case "$1" in
    --budgets) budgets=$2; shift 2 ;;
    --threads) thread_counts=$2; shift 2 ;;
    *) echo "time_to_quality.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
bash scripts/build.sh
out=out/time_to_quality
cores=$(nproc)
for threads in $thread_counts; do
  jobs=$(( cores / threads > 0 ? cores / threads : 1 ))
  for budget in $budgets; do
    run=$out/t$threads/b$budget
    mkdir -p "$run/records"
    for set_limit in "gt-dev 0" "real-dev 0" "real-tune 4"; do
      read -r set limit <<<"$set_limit"
      echo "== threads $threads, jobs $jobs, cap $budget s: $set" >&2
      build/run_results --set "$set" --limit "$limit" --threads "$threads" --jobs "$jobs" \
        --time_budget "$budget" --work_budget 1000000000 \
        --out "$run" --records "$run/records" --doc "$run/results.md" >"$run.$set.log" 2>&1 ||
        { tail -5 "$run.$set.log"; exit 1; }
    done
  done
done
/usr/bin/python3 benchmarks/plot_time_to_quality.py "$out" docs/images/time_to_quality.png
