#!/usr/bin/env bash
# Runs fit_sequence on all of ../shared/data and writes docs/results.md (about 16 x the time
# budget; the default budget is 90 s per model).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
build/run_results --data ../shared/data --out out/results --doc docs/results.md --time-budget "${1:-90}"
