#!/usr/bin/env python3
"""Counts the synthetic ground-truth sequences in which a Boolean cuts a polygon of more than
four corners left by the op before it (docs/zero-shot.md, Known limits).

    python3 benchmarks/boolean_ngon_cuts.py [--synth out/synth] [--split tune]

Each sequence with a Boolean is rebuilt step by step with build/apply_sequence (into
out/boolean_ngon_cuts/); a polygon of the step before a Boolean counts as cut when no polygon
of the Boolean's output has the same corners.
"""
import argparse
import collections
import json
import os
import subprocess


def load_obj(path):
    vertices, faces = [], []
    for line in open(path):
        fields = line.split()
        if fields and fields[0] == 'v':
            vertices.append(tuple(round(float(x), 6) for x in fields[1:4]))
        elif fields and fields[0] == 'f':
            faces.append([int(x.split('/')[0]) - 1 for x in fields[1:]])
    return vertices, faces


def cuts_ngon(steps_dir):
    steps = sorted(os.listdir(steps_dir))
    for k in range(1, len(steps)):
        if 'Boolean' not in steps[k]:
            continue
        before_v, before_f = load_obj(os.path.join(steps_dir, steps[k - 1]))
        after_v, after_f = load_obj(os.path.join(steps_dir, steps[k]))
        kept = {frozenset(after_v[i] for i in f) for f in after_f}
        if any(len(f) > 4 and frozenset(before_v[i] for i in f) not in kept for f in before_f):
            return True
    return False


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument('--synth', default='out/synth')
    parser.add_argument('--split', default='tune')
    parser.add_argument('--work', default='out/boolean_ngon_cuts')
    args = parser.parse_args()
    models = json.load(open(os.path.join(args.synth, 'index.json')))['models']
    counts = collections.Counter()
    for model in models:
        if model['split'] != args.split or 'Boolean' not in model['ops']:
            continue
        out = os.path.join(args.work, model['name'])
        if not os.path.isdir(os.path.join(out, 'steps')):
            subprocess.run(['build/apply_sequence', os.path.join(args.synth, model['name'], 'sequence.json'), '--out', out],
                           check=True, capture_output=True)
        cut = cuts_ngon(os.path.join(out, 'steps'))
        replays = model['blender_counts_equal'] and 0 <= model['blender_distance'] <= 1e-6
        counts[(cut, replays)] += 1
        if cut:
            print(f"{model['name']}: {' '.join(model['ops'])} (Blender {'replays' if replays else 'does not replay'} it)")
    total = sum(counts.values())
    cut = counts[(True, True)] + counts[(True, False)]
    print(f"{cut} of {total} {args.split} sequences with a Boolean cut an earlier polygon of more than four corners; "
          f"{counts[(True, True)]} of those replay in Blender within 1e-6 with equal counts")


if __name__ == '__main__':
    main()
