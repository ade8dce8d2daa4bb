#!/usr/bin/env bash
# Renders the synthetic corpus' contact sheets (Blender Workbench, 50 models a sheet) and copies
# its index next to them:  bash benchmarks/synth/make_contact_sheets.sh [SYNTH_DIR] [DOC_DIR]
# (defaults: out/synth, docs/corpus).
set -euo pipefail
cd "$(dirname "$0")/../.."
synth="${1:-out/synth}"
doc="${2:-docs/corpus}"
mkdir -p "$doc"
mapfile -t models < <(ls -d "$synth"/synth_* | sort)
for ((start = 0; start < ${#models[@]}; start += 50)); do
  sheet="$doc/sheet_$((start / 50 + 1)).png"
  blender -b --factory-startup --python-exit-code 1 -P benchmarks/synth/contact_sheet.py -- \
    "$sheet" 10 "${models[@]:start:50}" > /dev/null
  echo "wrote $sheet"
done
cp "$synth/index.md" "$doc/index.md"
