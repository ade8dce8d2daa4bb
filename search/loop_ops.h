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

// A ridge on the scaled cube (half extents `half_extent`): a loop cut across `cut_axis`, and its
// two vertices on the `up_sign` side of `up_axis` moved along it by up_sign * `raise` (a gable
// roof's ridge line).
std::vector<Json> RaisedRidge(int cut_axis, int up_axis, int up_sign, const Vec3d& half_extent, double raise);

}  // namespace opgraph
