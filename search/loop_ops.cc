#include "search/loop_ops.h"

namespace opgraph {

std::vector<Json> LoopCutWithScales(int axis, int cuts, int expect, std::vector<std::vector<int>> groups) {
  const build::Axis named = static_cast<build::Axis>(axis);
  std::vector<Json> ops = {build::LoopCut(named, cuts, Vec3d::Zero())};
  if (groups.empty()) {
    for (int i = 0; i < cuts; ++i) groups.push_back({i});
  }
  const double spacing = 2.0 / (cuts + 1);
  for (const std::vector<int>& group : groups) {
    build::VertexTarget verts;
    verts.box.lo[axis] = -1.0 + spacing * (group.front() + 1) - 0.3 * spacing;
    verts.box.hi[axis] = -1.0 + spacing * (group.back() + 1) + 0.3 * spacing;
    if (expect > 0) verts.expect = expect * static_cast<int>(group.size());
    ops.push_back(build::EdgeLoopScale(verts, Vec3d::Ones()));
  }
  return ops;
}

std::vector<Json> LoopCutGrid(int first_axis, int second_axis, int first_expect, const Eigen::Vector2d& spread) {
  std::vector<Json> grid = LoopCutWithScales(first_axis, 2, first_expect, {{0, 1}});
  std::vector<Json> second = LoopCutWithScales(second_axis, 2, -1, {{0, 1}});
  // Two cuts lie at +-1/3 of the cube's half extent: a loop scale of 3 * spread moves them.
  grid[1]["params"]["scale"][first_axis] = 3 * spread[0];
  second[1]["params"]["scale"][second_axis] = 3 * spread[1];
  grid.insert(grid.end(), second.begin(), second.end());
  return grid;
}

std::vector<Json> RaisedRidge(int cut_axis, int up_axis, int up_sign, const Vec3d& half_extent, double raise) {
  build::DisplaceGroup raised;
  raised.verts.box.lo[cut_axis] = -0.25 * half_extent[cut_axis];
  raised.verts.box.hi[cut_axis] = 0.25 * half_extent[cut_axis];
  (up_sign > 0 ? raised.verts.box.lo : raised.verts.box.hi)[up_axis] = up_sign * 0.5 * half_extent[up_axis];
  raised.offset = Vec3d::Zero();
  raised.offset[up_axis] = up_sign * raise;
  return {build::LoopCut(static_cast<build::Axis>(cut_axis), 1, Vec3d::Zero()), build::VertexDisplace({raised})};
}

}  // namespace opgraph
