#!/bin/bash
# The parallel ratio of issue 12 beside this machine's ceiling for it, measured side by side.
#
# The ratio: a results run of the first LIMIT gt-dev models, one model at a time, with
# `--threads 2` against `--threads 1`. The ceiling: the same models two at a time with one
# thread each (`--jobs 2 --threads 1`), whose fits are independent, so no search can use the
# two cores better than that (up to the order the models end in). The three runs are repeated
# ROUNDS times, interleaved, so a slower spell of the machine falls on all three; the outputs
# (sequence.json and result.obj) of every run are checked to be byte-identical.
#
#   bash benchmarks/parallel_ratio.sh [--limit 4] [--rounds 2] [--out out/parallel_ratio]
set -euo pipefail
cd "$(dirname "$0")/.."
limit=4 rounds=2 out=out/parallel_ratio
while [ $# -gt 0 ]; do
  case "$1" in
    --limit) limit=$2; shift 2 ;;
    --rounds) rounds=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    *) echo "parallel_ratio.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
bash scripts/build.sh
rm -rf "$out" && mkdir -p "$out"
modes=("1 1" "1 2" "2 1")  # jobs threads
for round in $(seq 1 "$rounds"); do
  for mode in "${modes[@]}"; do
    read -r jobs threads <<< "$mode"
    dir=$out/r${round}_jobs${jobs}_threads${threads}
    start=$(date +%s.%N)
    build/run_results --set gt-dev --limit "$limit" --jobs "$jobs" --threads "$threads" --out "$dir" \
      --records "$dir/records" --doc "$dir/results.md" > "$dir.log" 2>&1
    end=$(date +%s.%N)
    echo "$round $jobs $threads $(python3 -c "print(round($end - $start, 1))")" >> "$out/walls.txt"
    echo "round $round, --jobs $jobs --threads $threads: $(tail -n 1 "$out/walls.txt" | cut -d' ' -f4) s" >&2
  done
done
# Byte-identical outputs across every run.
reference=$out/r1_jobs1_threads1/gt-dev
for dir in "$out"/r*_jobs*_threads*/gt-dev; do
  for model in "$reference"/*/; do
    name=$(basename "$model")
    for file in sequence.json result.obj; do
      cmp -s "$model/$file" "$dir/$name/$file" || { echo "parallel_ratio.sh: $dir/$name/$file differs" >&2; exit 1; }
    done
  done
done
python3 - "$out/walls.txt" <<'EOF'
import collections, statistics, sys
walls = collections.defaultdict(list)
for line in open(sys.argv[1]):
    round_, jobs, threads, wall = line.split()
    walls[(jobs, threads)].append(float(wall))
serial, threads2, jobs2 = walls[("1", "1")], walls[("1", "2")], walls[("2", "1")]
print("| round | --threads 1 (s) | --threads 2 (s) | --jobs 2 --threads 1 (s) | ratio | ceiling |")
print("|---|---|---|---|---|---|")
for r, (a, b, c) in enumerate(zip(serial, threads2, jobs2), 1):
    print(f"| {r} | {a:.1f} | {b:.1f} | {c:.1f} | {b / a:.2f}x | {c / a:.2f}x |")
a, b, c = sum(serial), sum(threads2), sum(jobs2)
print(f"| all | {a:.1f} | {b:.1f} | {c:.1f} | {b / a:.2f}x | {c / a:.2f}x |")
print("\noutputs byte-identical across all runs")
EOF
