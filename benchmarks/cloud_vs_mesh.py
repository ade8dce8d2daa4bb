#!/usr/bin/env python3
"""Point-cloud input against mesh input, per split and for the done-when groups, paired model by
model: the median Chamfer of each, their ratio with a bootstrap 90% interval (models resampled
in pairs, fixed seed), the median of the per-model ratios, and how many models are worse or
better by more than 15% as clouds.

    python3 benchmarks/cloud_vs_mesh.py [--mesh docs/results] [--cloud docs/results-cloud]

A records folder may be given at a git revision (`--mesh 13cf458:docs/results`), so both sides
can come from one search.

A ratio of medians moves with the models next to the median, not only with the fits: on a
split of 21 models a gap between two neighbouring values moves it by half or more while the
per-model ratios stay near 1. The interval says how far resampling the models moves it.
"""
import argparse
import os
import random
import statistics
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from compare_records import load  # noqa: E402  (a records file, or a git revision and path)

GROUPS = [
    ("gt-dev", ["gt-dev"]),
    ("synth-tune", ["synth-tune"]),
    ("synth-heldout", ["synth-heldout"]),
    ("real-dev", ["real-dev"]),
    ("real-tune", ["real-tune"]),
    ("real-heldout", ["real-heldout"]),
    ("Blender-built (gt-dev + synth-heldout)", ["gt-dev", "synth-heldout"]),
    ("real (real-dev + real-tune + real-heldout)", ["real-dev", "real-tune", "real-heldout"]),
]


def load_split(directory, split):
    """The ok rows of DIRECTORY/SPLIT.json by name ({} when the split has no record there)."""
    try:
        rows = load(directory.rstrip("/") + "/" + split + ".json")
    except (OSError, subprocess.CalledProcessError):
        return {}
    return {name: row for name, row in rows.items() if row["ok"]}


def bootstrap_interval(pairs, rounds=2000, seed=1):
    rng = random.Random(seed)
    ratios = []
    for _ in range(rounds):
        sample = [pairs[rng.randrange(len(pairs))] for _ in pairs]
        ratios.append(statistics.median(c for _, c in sample) / statistics.median(m for m, _ in sample))
    ratios.sort()
    return ratios[int(0.05 * rounds)], ratios[int(0.95 * rounds) - 1]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--mesh", default="docs/results")
    parser.add_argument("--cloud", default="docs/results-cloud")
    args = parser.parse_args()
    print("| models | n | median Chamfer, mesh | median Chamfer, cloud | ratio of medians (90% interval) "
          "| median per-model ratio | worse by > 15% | better by > 15% |")
    print("|---|---|---|---|---|---|---|---|")
    for label, splits in GROUPS:
        pairs = []
        for split in splits:
            mesh, cloud = load_split(args.mesh, split), load_split(args.cloud, split)
            pairs += [(mesh[n]["chamfer"], cloud[n]["chamfer"]) for n in sorted(set(mesh) & set(cloud))]
        if not pairs:
            continue
        mesh_median = statistics.median(m for m, _ in pairs)
        cloud_median = statistics.median(c for _, c in pairs)
        low, high = bootstrap_interval(pairs)
        per_model = [c / m for m, c in pairs if m > 0]
        print(f"| {label} | {len(pairs)} | {mesh_median:.4f} | {cloud_median:.4f} | {cloud_median / mesh_median:.2f} "
              f"({low:.2f}-{high:.2f}) | {statistics.median(per_model):.2f} | {sum(r > 1.15 for r in per_model)} "
              f"| {sum(r < 1 / 1.15 for r in per_model)} |")


if __name__ == "__main__":
    main()
