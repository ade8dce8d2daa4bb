// Mirrored pairs (search/proposals.h).
#include <algorithm>
#include <cmath>
#include <limits>

#include "search/pose.h"
#include "search/proposals.h"

namespace opgraph {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Whether the target is its own mirror image across the plane through `centre` (local
// coordinates of `world_from_local`) normal to `axis`, with a gap around the plane: its samples
// reflected lie on it (RMS distance under 1% of the diagonal) and under 0.5% of them lie within
// 2% of the extent of the plane.
bool IsMirroredPair(const Target& target, const Eigen::Matrix3d& world_from_local, int axis, double centre,
                    double extent, double diagonal) {
  const Positions<double>& points = target.points();
  const size_t stride = std::max<size_t>(1, points.size() / 2000);
  const Vec3d normal = world_from_local.col(axis);
  double squared = 0;
  size_t count = 0, near_plane = 0;
  for (size_t i = 0; i < points.size(); i += stride, ++count) {
    const double signed_distance = normal.dot(points[i]) - centre;
    if (std::abs(signed_distance) < 0.02 * extent) ++near_plane;
    double distance2 = 0;
    target.tree().Nearest(points[i] - 2 * signed_distance * normal, &distance2);
    squared += distance2;
  }
  return std::sqrt(squared / count) < 0.01 * diagonal && near_plane < 0.005 * count;
}

}  // namespace

std::vector<Expansion> ProposeMirrors(const Target& target, const Layout& pose) {
  const Eigen::Matrix3d& world_from_local = pose.world_from_local;
  Vec3d lo = Vec3d::Constant(kInf), hi = Vec3d::Constant(-kInf);
  for (const Vec3d& p : target.points()) {
    const Vec3d q = world_from_local.transpose() * p;
    lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
  }
  const Vec3d centre = (lo + hi) / 2;
  const double diagonal = (hi - lo).norm();
  std::vector<int> axes;
  for (int axis = 0; axis < 3; ++axis) {
    if (IsMirroredPair(target, world_from_local, axis, centre[axis], hi[axis] - lo[axis], diagonal)) axes.push_back(axis);
  }
  if (axes.empty()) return {};
  // The part on the + side of every mirror plane, as the cage's box.
  Vec3d part_lo = Vec3d::Constant(kInf), part_hi = Vec3d::Constant(-kInf);
  for (const Vec3d& p : target.points()) {
    const Vec3d q = world_from_local.transpose() * p;
    bool on_part = true;
    for (int axis : axes) on_part = on_part && q[axis] > centre[axis];
    if (on_part) part_lo = part_lo.cwiseMin(q), part_hi = part_hi.cwiseMax(q);
  }
  if (!(part_hi.array() > part_lo.array()).all()) return {};
  Expansion pair{PoseLayoutOnBox(world_from_local, part_lo, part_hi), "a mirrored pair across"};
  // The part's cage is built about the cube's origin, moved to its place relative to the whole
  // target's centre, mirrored, then posed at that centre.
  pair.layout.mirror_axes = axes;
  pair.layout.mirror_offset = build::GlobalTranslate((part_lo + part_hi) / 2 - centre);
  pair.layout.translate = build::GlobalTranslate(world_from_local * centre);
  for (int axis : axes) pair.what += " " + build::AxisName(static_cast<build::Axis>(axis));
  return {pair};
}

}  // namespace opgraph
