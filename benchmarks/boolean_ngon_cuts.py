#!/usr/bin/env python3
"""Counts the synthetic ground-truth sequences in which a Boolean cuts a polygon of more than
four corners left by the op before it (docs/zero-shot.md, Known limits).

    python3 benchmarks/boolean_ngon_cuts.py [--synth out/synth] [--split tune]

Each sequence with a Boolean is rebuilt up to each Boolean and the op before it with the
Python binding (build/python); a polygon of the step before a Boolean counts as cut when no
polygon of the Boolean's output has the same corners.
"""
import argparse
import collections
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'build', 'python'))
import opgraph  # noqa: E402


def polygons(document, num_ops):
    """The polygons of the mesh after the first `num_ops` ops, each as its set of corners."""
    mesh = opgraph.apply(dict(document, operations=document['operations'][:num_ops]))
    corners = [tuple(round(float(x), 6) for x in v) for v in mesh['vertices']]
    return [frozenset(corners[i] for i in face) for face in mesh['faces']]


def cuts_ngon(document):
    for k, op in enumerate(document['operations']):
        if op['op'] != 'Boolean':
            continue
        kept = set(polygons(document, k + 1))
        if any(len(face) > 4 and face not in kept for face in polygons(document, k)):
            return True
    return False


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument('--synth', default='out/synth')
    parser.add_argument('--split', default='tune')
    args = parser.parse_args()
    models = json.load(open(os.path.join(args.synth, 'index.json')))['models']
    counts = collections.Counter()
    for model in models:
        if model['split'] != args.split or 'Boolean' not in model['ops']:
            continue
        cut = cuts_ngon(json.load(open(os.path.join(args.synth, model['name'], 'sequence.json'))))
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
