#!/usr/bin/env python3
"""Plots what benchmarks/time_to_quality.sh measured: median Chamfer, median F1@0.01 and the
median seconds used, of the Blender-built and of the real models, against the seconds cap, one
line per --threads count (axes from zero, so that a flat curve looks flat), and prints the same
numbers as a markdown table (with how many searches ended on their own before the cap).

    /usr/bin/python3 benchmarks/plot_time_to_quality.py out/time_to_quality docs/images/time_to_quality.png
"""
import argparse
import glob
import json
import os
import re
import statistics

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

GROUPS = {"Blender-built (gt-dev)": ("gt-dev",), "real (real-dev, real-tune first 4)": ("real-dev", "real-tune")}


def read_runs(root):
    """{(threads, budget): [row, ...]} from the records run_results wrote."""
    runs = {}
    for folder in glob.glob(os.path.join(root, "t*", "b*")):
        match = re.fullmatch(r"t(\d+)/b(\d+)", os.path.relpath(folder, root))
        if not match or not os.path.isdir(os.path.join(folder, "records")):
            continue
        rows = []
        for record in glob.glob(os.path.join(folder, "records", "*.json")):
            rows += json.load(open(record))["rows"]
        runs[(int(match.group(1)), int(match.group(2)))] = rows
    return runs


def group_rows(rows, sets):
    return [r for r in rows if r["set"] in sets and r["ok"]]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("root")
    parser.add_argument("png")
    args = parser.parse_args()
    runs = read_runs(args.root)
    if not runs:
        raise SystemExit(f"{args.root}: no runs")
    thread_counts = sorted({t for t, _ in runs})
    figure, axes = plt.subplots(3, len(GROUPS), figsize=(10, 9.5), sharex=True)
    print("| models | threads | cap s | models ok | median Chamfer | median F1@0.01 | median s used | ended before cap |")
    print("|---|---|---|---|---|---|---|---|")
    for column, (title, sets) in enumerate(GROUPS.items()):
        for threads in thread_counts:
            budgets = sorted(b for t, b in runs if t == threads)
            chamfers, f1s, seconds = [], [], []
            for budget in budgets:
                rows = group_rows(runs[(threads, budget)], sets)
                if not rows:
                    raise SystemExit(f"{args.root}: no finished model of {title} at threads {threads}, cap {budget} s")
                chamfers.append(statistics.median(r["chamfer"] for r in rows))
                f1s.append(statistics.median(r["f1_0.01"] for r in rows))
                seconds.append(statistics.median(r["seconds"] for r in rows))
                complete = sum(1 for r in rows if r["search_complete"])
                print(f"| {title} | {threads} | {budget} | {len(rows)} | {chamfers[-1]:.4f} | {f1s[-1]:.3f} | "
                      f"{seconds[-1]:.1f} | {complete} |")
            label = f"--threads {threads}"
            axes[0][column].plot(budgets, chamfers, marker="o", label=label)
            axes[1][column].plot(budgets, f1s, marker="o", label=label)
            axes[2][column].plot(budgets, seconds, marker="o", label=label)
        axes[0][column].set_title(title)
        axes[0][column].set_ylabel("median Chamfer (unit bounding box)")
        axes[1][column].set_ylabel("median F1@0.01")
        axes[1][column].set_ylim(0, 1.05)
        axes[2][column].set_ylabel("median seconds used")
        axes[2][column].plot(budgets, budgets, color="gray", linestyle=":", label="the cap")
        axes[2][column].set_xlabel("time cap per model (s), 2 cores")
        for row in axes:
            row[column].set_xscale("log", base=2)
            row[column].set_xticks(budgets, [str(b) for b in budgets])
            row[column].grid(True, alpha=0.3)
            row[column].set_ylim(bottom=0)
            row[column].legend()
    figure.suptitle("opgraph zero-shot search: quality against time (benchmarks/time_to_quality.sh)")
    figure.tight_layout()
    os.makedirs(os.path.dirname(args.png) or ".", exist_ok=True)
    figure.savefig(args.png, dpi=110)


if __name__ == "__main__":
    main()
