#!/usr/bin/env bash
# Builds and runs every test (GoogleTest under ctest; the Blender parity tests need `blender`).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j 2
