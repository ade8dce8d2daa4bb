#!/usr/bin/env python3
"""How many models of a results run have a search log (`log.txt`) line matching a pattern:
how often a proposal family was offered, accepted or won, counted from the run's own logs.

    python3 benchmarks/log_counts.py out/results synth-tune --pattern 'profile: LoopCut ([XYZ]) x' --distinct 2

With --distinct N, a model counts when its matches give at least N distinct values of the
pattern's first group (above: profiles along two axes). Prints "k of n" and, with --names,
the models counted.
"""
import argparse
import os
import re
import sys


def matches(log_path, pattern, distinct):
    values = set()
    with open(log_path, errors="replace") as log:
        for line in log:
            found = pattern.search(line)
            if found:
                values.add(found.group(1) if pattern.groups else found.group(0))
    return len(values) >= distinct


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run", help="a results run's --out folder")
    parser.add_argument("set")
    parser.add_argument("--pattern", required=True, help="a Python regular expression")
    parser.add_argument("--distinct", type=int, default=1)
    parser.add_argument("--names", action="store_true")
    args = parser.parse_args()
    pattern = re.compile(args.pattern)
    folder = os.path.join(args.run, args.set)
    models = sorted(m for m in os.listdir(folder) if os.path.isfile(os.path.join(folder, m, "log.txt")))
    if not models:
        sys.exit(f"{folder}: no model folder with a log.txt")
    counted = [m for m in models if matches(os.path.join(folder, m, "log.txt"), pattern, args.distinct)]
    print(f"{len(counted)} of {len(models)}")
    if args.names:
        print("\n".join(counted))


if __name__ == "__main__":
    main()
