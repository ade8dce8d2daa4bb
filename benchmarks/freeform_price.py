#!/usr/bin/env python3
"""What the free-form stage's price does to a tuning run, without rerunning it.

Each model's fit log (OUT/SET/MODEL/log.txt) records the free-form candidates' Chamfer distances
("freeform: ...: Chamfer A -> B") and which was kept. For a grid of (minimum Chamfer, required
gain) this replays the stage's decision (search/freeform.cc) and reports the median Chamfer and
the mean normalised LCS against the truth: a dropped stage scales the model's Chamfer by A/B
and removes the VertexDisplace (and the refining Subdivision) from its sequence. The Chamfer is
an estimate (the log's Chamfer uses 3000 samples); rerun the set to confirm a choice.

    python3 benchmarks/freeform_price.py --records out/results_X/records/synth-tune.json \
        --out out/results_X --truth out/synth

Tuning splits only: held-out runs are measured, not used to choose.
"""
import argparse
import json
import os
import re
import statistics

LINE = re.compile(r"freeform: (\d+) vertices displaced(?: on a cage refined by Subdivision\((\d)\))?: Chamfer (\S+) -> (\S+)")
GATE_PRICE = 0.08  # ZeroShotOptions::min_relative_gain: a refining Subdivision's price


def lcs(a, b):
    longer = max(len(a), len(b))
    if longer == 0:
        return 1.0
    prev = [0] * (len(b) + 1)
    for x in a:
        cur = [0] * (len(b) + 1)
        for j, y in enumerate(b, 1):
            cur[j] = prev[j - 1] + 1 if x == y else max(prev[j], cur[j - 1])
        prev = cur
    return prev[-1] / longer


def candidates(log_path):
    """[(refine, before, after)] from a model's log, or [] when the stage did not run."""
    found = []
    if not os.path.exists(log_path):
        return found
    with open(log_path, errors="replace") as log:
        for line in log:
            m = LINE.search(line)
            if m:
                found.append((int(m.group(2) or 0), float(m.group(3)), float(m.group(4))))
    return found


def without_freeform(ops, refine):
    """The sequence with its VertexDisplace (and the Subdivision before it when refined) removed."""
    k = ops.index("VertexDisplace")
    drop = {k, k - 1} if refine > 0 and k > 0 and ops[k - 1] == "Subdivision" else {k}
    return [op for i, op in enumerate(ops) if i not in drop]


def kept_choice(found, min_chamfer, gain):
    """The candidate search/freeform.cc keeps under this price, or None."""
    if not found or found[0][1] < min_chamfer:
        return None
    best, best_score = None, found[0][1] * (1 - gain)
    for refine, before, after in found:
        score = after / ((1 - GATE_PRICE) if refine > 0 else 1)
        if score < best_score:
            best, best_score = (refine, before, after), score
    return best


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--records", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--truth", default="out/synth")
    args = parser.parse_args()
    record = json.load(open(args.records))
    rows = [r for r in record["rows"] if r["ok"]]
    models = []
    for r in rows:
        truth_path = os.path.join(args.truth, r["name"], "sequence.json")
        truth = [op["op"] for op in json.load(open(truth_path))["operations"]] if os.path.exists(truth_path) else None
        found = candidates(os.path.join(args.out, r["set"], r["name"], "log.txt"))
        ops = r["sequence"].split()
        kept = kept_choice(found, 2e-3, 0.25) if "VertexDisplace" in ops else None
        if "VertexDisplace" in ops and kept is None:
            kept = min(found, key=lambda c: c[2]) if found else None
        models.append((r, truth, found, ops, kept))
    print(f"{len(models)} models from {args.records}")
    print("| min Chamfer | gain | free-form kept | median Chamfer (est.) | mean LCS | mean ops |")
    print("|---|---|---|---|---|---|")
    for min_chamfer in (2e-3, 3e-3, 4e-3, 6e-3):
        for gain in (0.25, 0.35, 0.5, 0.65, 1.01):
            chamfers, lcss, lengths, used = [], [], [], 0
            for r, truth, found, ops, kept in models:
                choice = kept_choice(found, min_chamfer, gain) if found else None
                chamfer, sequence = r["chamfer"], ops
                if kept is not None and choice != kept:
                    sequence = without_freeform(ops, kept[0])
                    chamfer = r["chamfer"] * kept[1] / max(kept[2], 1e-12)
                    if choice is not None:  # another candidate: its ratio and its Subdivision
                        chamfer *= choice[2] / choice[1]
                        k = sequence.index("Subdivision") if choice[0] > 0 and "Subdivision" in sequence else len(sequence)
                        sequence = sequence[:k] + (["Subdivision"] if choice[0] > 0 else []) + ["VertexDisplace"] + sequence[k:]
                used += choice is not None
                chamfers.append(chamfer)
                lengths.append(len(sequence))
                if truth is not None:
                    lcss.append(lcs(sequence, truth))
            print(f"| {min_chamfer:g} | {gain:g} | {used} | {statistics.median(chamfers):.4f} | "
                  f"{statistics.mean(lcss) if lcss else float('nan'):.3f} | {statistics.mean(lengths):.2f} |")


if __name__ == "__main__":
    main()
