#!/usr/bin/env python3
"""Two results runs on the same models, compared model by model from their output folders
(finished models only, so a stopped run can be compared too): median and mean Chamfer, F1@0.01,
normalised LCS against the truth and op count, and on how many models the LCS rose or fell.

    python3 benchmarks/paired_runs.py out/results_base out/results_b synth-tune [--truth out/synth]

Tuning splits only: held-out runs are measured, not used to choose.
"""
import argparse
import json
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from freeform_price import lcs  # noqa: E402


def summary(folder, truth):
    ops = [o["op"] for o in json.load(open(os.path.join(folder, "sequence.json")))["operations"]]
    shape = json.load(open(os.path.join(folder, "metrics.json")))["shape"]
    return shape["chamfer"]["sum"], shape["f1_0.01"], lcs(ops, truth), len(ops)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("base")
    parser.add_argument("new")
    parser.add_argument("set")
    parser.add_argument("--truth", default="out/synth")
    args = parser.parse_args()
    pairs = []
    for name in sorted(os.listdir(os.path.join(args.new, args.set))):
        folders = [os.path.join(run, args.set, name) for run in (args.base, args.new)]
        truth_path = os.path.join(args.truth, name, "sequence.json")
        if not all(os.path.exists(os.path.join(f, "metrics.json")) for f in folders) or not os.path.exists(truth_path):
            continue
        truth = [o["op"] for o in json.load(open(truth_path))["operations"]]
        pairs.append([summary(f, truth) for f in folders])
    print(f"{len(pairs)} models finished in both runs")
    for i, key in enumerate(("chamfer", "f1_0.01", "lcs", "ops")):
        a, b = [p[0][i] for p in pairs], [p[1][i] for p in pairs]
        print(f"{key}: median {statistics.median(a):.4f} -> {statistics.median(b):.4f}, "
              f"mean {statistics.mean(a):.4f} -> {statistics.mean(b):.4f}")
    print(f"LCS higher on {sum(p[1][2] > p[0][2] + 1e-9 for p in pairs)}, "
          f"lower on {sum(p[1][2] < p[0][2] - 1e-9 for p in pairs)}")


if __name__ == "__main__":
    main()
