#!/usr/bin/env python3
"""Two results records of one set compared model by model: which sequences changed (better or
worse in Chamfer) and the summary numbers of both (median and mean Chamfer, median F1@0.01 and
NC, mean normalised LCS, replays within 1e-6, complete searches, free-form kept, median time).
A record is a file or a git revision and path, so a past record needs no checkout:

    python3 benchmarks/compare_records.py 8f746f8:docs/results/synth-tune.json docs/results/synth-tune.json

Add --sequences to print both sequences of each changed model (tuning splits only: held-out
records are measured, not read model by model to choose a change).
"""
import argparse
import json
import os
import statistics
import subprocess


def load(spec):
    if os.path.exists(spec):
        text = open(spec).read()
    else:
        text = subprocess.run(["git", "show", spec], check=True, capture_output=True, text=True).stdout
    return {row["name"]: row for row in json.loads(text)["rows"]}


def summary(rows):
    ok = [r for r in rows if r["ok"]]
    with_truth = [r["lcs"] for r in ok if r["lcs"] >= 0]
    return [
        ("median Chamfer", statistics.median(r["chamfer"] for r in ok), 4),
        ("mean Chamfer", statistics.mean(r["chamfer"] for r in ok), 4),
        ("median F1@0.01", statistics.median(r["f1_0.01"] for r in ok), 4),
        ("median NC", statistics.median(r["normal_consistency"] for r in ok), 4),
        ("mean LCS", statistics.mean(with_truth) if with_truth else float("nan"), 3),
        ("replays", sum(r["replay_distance"] <= 1e-6 and r["replay_counts_equal"] for r in ok), 0),
        ("complete searches", sum(r["search_complete"] for r in ok), 0),
        ("free-form kept", sum(r["freeform"] for r in ok), 0),
        ("median time s", statistics.median(r["seconds"] for r in ok), 1),
    ]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("base")
    parser.add_argument("new")
    parser.add_argument("--sequences", action="store_true")
    args = parser.parse_args()
    base, new = load(args.base), load(args.new)
    common = sorted(set(base) & set(new))
    changed = [n for n in common if base[n]["sequence"] != new[n]["sequence"] or base[n]["chamfer"] != new[n]["chamfer"]]
    better = sum(new[n]["chamfer"] < base[n]["chamfer"] for n in changed)
    print(f"{len(common)} models in both; {len(changed)} changed ({better} better in Chamfer, {len(changed) - better} not)")
    for n in changed:
        print(f"  {n}: Chamfer {base[n]['chamfer']:.4f} -> {new[n]['chamfer']:.4f}, LCS {base[n]['lcs']:.2f} -> {new[n]['lcs']:.2f}")
        if args.sequences:
            print(f"    {base[n]['sequence']}\n    {new[n]['sequence']}")
    for (name, a, digits), (_, b, _) in zip(summary([base[n] for n in common]), summary([new[n] for n in common])):
        print(f"  {name}: {a:.{digits}f} -> {b:.{digits}f}")


if __name__ == "__main__":
    main()
