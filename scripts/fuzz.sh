#!/usr/bin/env bash
# Builds the libFuzzer harnesses (tests/fuzz) with clang, AddressSanitizer and UBSan into
# build-fuzz/, then runs each for SECONDS (default 600) from its seeds (tests/fuzz/seeds/<format>,
# tests/data/parity for sequences), two at a time. Inputs the fuzzer finds go to
# out/fuzz/corpus/<harness>/, a crashing input to out/fuzz/crashes/, each run's log to
# out/fuzz/logs/. Prints one line per harness with its executions; exits 1 on any finding (a
# crash, leak, sanitizer report, timeout, more than 2 GB of memory, or an exception the tools
# would report as their own failure).
#
#   bash scripts/fuzz.sh [--seconds N] [harness ...]     (harnesses: fuzz_read_obj ... fuzz_sequence)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=600
harnesses=()
while [ $# -gt 0 ]; do
  case "$1" in
    --seconds) seconds=$2; shift 2 ;;
    -*) echo "fuzz.sh: unknown option $1" >&2; exit 2 ;;
    *) harnesses+=("$1"); shift ;;
  esac
done
if [ ${#harnesses[@]} -eq 0 ]; then
  harnesses=(fuzz_read_obj fuzz_read_ply fuzz_read_stl fuzz_read_off fuzz_read_gltf fuzz_read_pcd fuzz_read_xyz
    fuzz_sequence)
fi

mkdir -p build-fuzz
if ! cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DOPGRAPH_BUILD_FUZZERS=ON -DOPGRAPH_BUILD_APPS=OFF -DOPGRAPH_BUILD_TESTS=OFF -DOPGRAPH_BUILD_PYTHON=OFF \
  >build-fuzz/configure.log 2>&1; then
  cat build-fuzz/configure.log
  exit 1
fi
if ! cmake --build build-fuzz -j 2 --target "${harnesses[@]}" >build-fuzz/build.log 2>&1; then
  tail -50 build-fuzz/build.log
  exit 1
fi

out=out/fuzz
mkdir -p "$out/crashes" "$out/logs"
# Leaks and UB are findings; the 2 GB memory promise is libFuzzer's -rss_limit_mb.
export ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=0
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1

run_one() {
  local harness=$1 seeds
  case "$harness" in
    fuzz_sequence) seeds=tests/data/parity ;;
    fuzz_read_*) seeds=tests/fuzz/seeds/${harness#fuzz_read_} ;;
    *) echo "fuzz.sh: unknown harness $harness" >&2; return 2 ;;
  esac
  mkdir -p "$out/corpus/$harness"
  local log=$out/logs/$harness.log status=0
  # -timeout: one input taking 30 s is a finding; -max_len: 64 KiB inputs reach every header
  # field and a few hundred elements.
  build-fuzz/tests/fuzz/"$harness" "$out/corpus/$harness" "$seeds" -max_total_time="$seconds" -timeout=30 \
    -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 \
    -artifact_prefix="$out/crashes/$harness-" >"$log" 2>&1 || status=$?
  local runs
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  if [ "$status" = 0 ]; then
    echo "$harness: ${runs:-?} executions in $seconds s, no finding"
  else
    echo "$harness: FINDING (exit $status) after ${runs:-?} executions; log $log:"
    grep -m 5 -E "ERROR|SUMMARY|threw|invalid|Test unit written" "$log" | sed 's/^/  /'
  fi
  return "$status"
}

# Two at a time (this machine's two cores); the exit status is the worst of all runs.
failed=0
pids=()
names=()
for harness in "${harnesses[@]}"; do
  run_one "$harness" &
  pids+=($!)
  names+=("$harness")
  if [ ${#pids[@]} -ge 2 ]; then
    wait "${pids[0]}" || failed=1
    pids=("${pids[@]:1}")
  fi
done
for pid in "${pids[@]}"; do wait "$pid" || failed=1; done
exit $failed
