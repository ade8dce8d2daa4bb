#!/usr/bin/env bash
# Builds and runs every test (GoogleTest under ctest; the Blender parity tests need `blender`),
# then a 60-second smoke run of each fuzz harness (scripts/fuzz.sh).
#
#   bash scripts/test.sh              the Release build in build/, the suite, the fuzz smoke runs
#   bash scripts/test.sh --sanitize   the whole suite built with AddressSanitizer and UBSan in
#                                     build-sanitize/ (no fuzzing: the harnesses are sanitized anyway)
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = --sanitize ]; then
  # Every report fails its test: leaks, and undefined behaviour too (halt_on_error); the build
  # runs the test binaries too (to list their tests).
  export ASAN_OPTIONS=detect_leaks=1
  export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
  cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=Release -DOPGRAPH_SANITIZE=ON >/dev/null
  cmake --build build-sanitize -j 2
  ctest --test-dir build-sanitize --output-on-failure -j 2
  exit 0
fi
if [ $# -gt 0 ]; then
  echo "usage: bash scripts/test.sh [--sanitize]" >&2
  exit 2
fi
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j 2
bash scripts/fuzz.sh --seconds 60
