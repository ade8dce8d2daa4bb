// Slab bodies (search/proposals.h).
#include <algorithm>
#include <limits>
#include <tuple>

#include "search/loop_ops.h"
#include "search/pose.h"
#include "search/proposals.h"

namespace opgraph {
namespace {

struct Slab {
  int axis = -1;
  double lo = 0, hi = 0;  // along the axis, in world units
};

// The densest layer (three bins, so a layer on a bin boundary counts whole) of a histogram.
std::pair<int, double> DensestLayer(const std::vector<double>& count) {
  int best = 0;
  double weight = 0;
  const int bins = static_cast<int>(count.size());
  for (int b = 0; b < bins; ++b) {
    const double w = count[b] + (b > 0 ? count[b - 1] : 0) + (b + 1 < bins ? count[b + 1] : 0);
    if (w > weight) weight = w, best = b;
  }
  return {best, weight};
}

// Along some axis of `world_from_local`, the largest layer of the target's surface facing +
// and the largest facing - bound a slab thinner than 60% of the box, both holding 5% of the
// samples; the heaviest such pair.
Slab FindSlab(const Target& target, const Eigen::Matrix3d& world_from_local) {
  const Positions<double>& points = target.points();
  const Positions<double>& normals = target.normals();
  constexpr int kBins = 100;
  Slab slab;
  double best_weight = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3d direction = world_from_local.col(axis);
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const Vec3d& p : points) lo = std::min(lo, direction.dot(p)), hi = std::max(hi, direction.dot(p));
    if (!(hi - lo > 0)) continue;
    std::vector<double> plus(kBins, 0), minus(kBins, 0);
    for (size_t i = 0; i < points.size(); ++i) {
      const int bin = std::clamp(static_cast<int>((direction.dot(points[i]) - lo) / (hi - lo) * kBins), 0, kBins - 1);
      const double facing = direction.dot(normals[i]);
      if (facing > 0.9) plus[bin] += 1;
      if (facing < -0.9) minus[bin] += 1;
    }
    const auto [top, top_weight] = DensestLayer(plus);
    const auto [bottom, bottom_weight] = DensestLayer(minus);
    const double n = static_cast<double>(points.size());
    if (bottom >= top || top - bottom > 0.6 * kBins || std::min(top_weight, bottom_weight) < 0.05 * n) continue;
    if (top_weight + bottom_weight > best_weight) {
      best_weight = top_weight + bottom_weight;
      slab = {axis, lo + (bottom + 0.5) / kBins * (hi - lo), lo + (top + 0.5) / kBins * (hi - lo)};
    }
  }
  return slab;
}

}  // namespace

std::vector<Expansion> ProposeSlabs(const Target& target, const Layout& pose) {
  const Slab slab = FindSlab(target, pose.world_from_local);
  if (slab.axis < 0) return {};
  // The slab is not fitted alone: the rest of the target would pull it back to the bounding
  // box. Its extrusions are proposed from the placed slab and fitted with it; with a loop-cut
  // grid across it (legs at the corners) and without (a boss on the whole face).
  const std::string across = "slab across " + build::AxisName(static_cast<build::Axis>(slab.axis));
  Expansion plain{PoseLayout(target, pose.world_from_local, slab.axis, slab.lo, slab.hi), across};
  Expansion gridded = plain;
  const int a = (slab.axis + 1) % 3, b = (slab.axis + 2) % 3;
  gridded.layout.grid = LoopCutGrid(std::min(a, b), std::max(a, b), 4);
  gridded.what += " with a LoopCut grid";
  return {plain, gridded};
}

}  // namespace opgraph
