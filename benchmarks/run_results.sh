#!/usr/bin/env bash
# Runs fit_sequence on an evaluation set (default: all of them) and writes docs/results.md.
# Generates the synthetic corpus first when it is missing. Arguments go to build/run_results:
#   bash benchmarks/run_results.sh --set all|gt-dev|synth-tune|synth-heldout|real-dev|real-tune|real-heldout
#        [--work_budget N] [--time_budget S] [--threads N] [--jobs N]
# All 259 models took 91 min at the old --time_budget 60 on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
# The default synthetic set (docs/corpus.md), made once (about 4 minutes with the Blender check).
if [ ! -f out/synth/index.json ]; then build/make_synth --out out/synth --verify_blender; fi
build/run_results "$@"
