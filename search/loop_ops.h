// Loop cuts on the cube with scales of their new loops: the building block of profiles and grids.
#pragma once

#include <vector>

#include "ops/builders.h"

namespace opgraph {

// LoopCut along `axis` on the cube with one EdgeLoopAffineScale per group of neighbouring new
// loops (`groups`: loop indices, each group contiguous; empty = one per loop). `expect`: a
// loop's vertex count, < 0 when earlier cuts make it vary.
std::vector<Json> LoopCutWithScales(int axis, int cuts, int expect, std::vector<std::vector<int>> groups = {});

// Two loop cuts across each of the two axes other than `axis`, the two loops of each scaled
// together (a scale spaces them, so the new faces move to where extrusions belong: legs at a
// slab's corners). `first_expect`: the first cut's loop vertex count (< 0: varies). `spread`:
// where each pair of loops starts, as a fraction of the half extent along its axis (the
// default 1/3 spaces the cuts evenly).
std::vector<Json> LoopCutGrid(int first_axis, int second_axis, int first_expect,
                              const Eigen::Vector2d& spread = Eigen::Vector2d::Constant(1.0 / 3));

}  // namespace opgraph
