#!/usr/bin/env python3
"""Where a results record's sequences differ from the truth, by kind of truth and op by op.

First, by the truth's kind (its ops after the first scale: "LoopCut EdgeLoopAffineScale",
"Boolean ...") the models' mean LCS and how much of the split's mean LCS their shortfall costs.
Then for each op type: in how many models the truth has it, in how many ours has it, and the op
counts ours adds beyond the truth (extra) and misses (missing), summed over the models. With two
records of the same models it also prints the paired change of each model's LCS in a summary.

    python3 benchmarks/op_balance.py out/results_X/records/synth-tune.json [--truth out/synth]
    python3 benchmarks/op_balance.py BASE.json NEW.json

Tuning splits only: held-out runs are measured, not used to choose.
"""
import argparse
import collections
import json
import os
import statistics


def ops_of(path):
    return [op["op"] for op in json.load(open(path))["operations"]]


def truth_class(ops):
    """A truth's kind, from its ops after the first scale: a CSG, extrusion, inset or knife start
    by that op, a loop cut by the op that shapes it (LoopCut EdgeLoopAffineScale, ...)."""
    rest = ops[1:] if ops and ops[0] == "GlobalAffineScale" else ops
    if not rest:
        return "(scale only)"
    if rest[0] == "LoopCut" and len(rest) > 1:
        return "LoopCut " + rest[1]
    return rest[0] + " ..."


def print_classes(rows, truth_dir, models):
    """Where the mean LCS is lost: by the truth's kind, its models' mean LCS and the share of the
    split's mean LCS their shortfall costs (1 - LCS summed over the class, over all models)."""
    count, lost = collections.Counter(), collections.Counter()
    recall = []
    for name, row in rows.items():
        truth_path = os.path.join(truth_dir, name, "sequence.json")
        if not os.path.exists(truth_path) or row.get("lcs") is None:
            continue
        truth = ops_of(truth_path)
        kind = truth_class(truth)
        count[kind] += 1
        lost[kind] += 1 - row["lcs"]
        # The common subsequence over the truth's length: the LCS ours would have without the
        # ops it adds beyond the truth's.
        common = row["lcs"] * max(len(truth), len(row["sequence"].split()))
        recall.append(common / len(truth))
    if recall:
        print(f"mean LCS without our extra ops (the truth's ops we find, in order): {statistics.mean(recall):.3f}")
    print("| truth starts with | models | their mean LCS | mean LCS lost to them |")
    print("|---|---|---|---|")
    for kind in sorted(count, key=lambda k: -lost[k]):
        print(f"| {kind} | {count[kind]} | {1 - lost[kind] / count[kind]:.2f} | {lost[kind] / models:.3f} |")
    print()


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("records", nargs="+")
    parser.add_argument("--truth", default="out/synth")
    args = parser.parse_args()
    base = {r["name"]: r for r in json.load(open(args.records[0]))["rows"] if r["ok"]}
    truth_has, ours_has, extra, missing = (collections.Counter() for _ in range(4))
    models = 0
    for name, row in sorted(base.items()):
        truth_path = os.path.join(args.truth, name, "sequence.json")
        if not os.path.exists(truth_path):
            continue
        truth = collections.Counter(ops_of(truth_path))
        ours = collections.Counter(row["sequence"].split())
        models += 1
        for op in truth:
            truth_has[op] += 1
        for op in ours:
            ours_has[op] += 1
        for op, n in (ours - truth).items():
            extra[op] += n
        for op, n in (truth - ours).items():
            missing[op] += n
    print(f"{models} models with a truth in {args.records[0]}")
    print_classes(base, args.truth, models)
    print("| op | truth has it | ours has it | extra ops | missing ops |")
    print("|---|---|---|---|---|")
    for op in sorted(set(truth_has) | set(ours_has), key=lambda o: -(extra[o] + missing[o])):
        print(f"| {op} | {truth_has[op]} | {ours_has[op]} | {extra[op]} | {missing[op]} |")
    if len(args.records) > 1:
        new = {r["name"]: r for r in json.load(open(args.records[1]))["rows"] if r["ok"]}
        common = sorted(set(base) & set(new))
        for key in ("chamfer", "lcs", "ops", "seconds"):
            a = [base[n][key] for n in common if base[n][key] is not None and base[n][key] >= 0]
            b = [new[n][key] for n in common if new[n][key] is not None and new[n][key] >= 0]
            if a and b:
                print(f"{key}: median {statistics.median(a):.4g} -> {statistics.median(b):.4g}, "
                      f"mean {statistics.mean(a):.4g} -> {statistics.mean(b):.4g}")
        better = sum(new[n]["lcs"] > base[n]["lcs"] + 1e-9 for n in common)
        worse = sum(new[n]["lcs"] < base[n]["lcs"] - 1e-9 for n in common)
        print(f"LCS better on {better}, worse on {worse} of {len(common)}")


if __name__ == "__main__":
    main()
