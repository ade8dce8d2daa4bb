#!/usr/bin/env python3
"""Where a results record's sequences differ from the truth, op by op.

For each op type: in how many models the truth has it, in how many ours has it, and the op
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
