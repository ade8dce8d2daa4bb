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
  # runs the test binaries too (to list their tests). alloc_dealloc_mismatch is off: GCC 12's
  # std::stable_sort frees its temporary buffer (std::_Temporary_buffer, operator new) in a way
  # ASan reports as "operator new vs free"; opgraph's own code calls neither malloc nor free.
  export ASAN_OPTIONS=detect_leaks=1:alloc_dealloc_mismatch=0
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
