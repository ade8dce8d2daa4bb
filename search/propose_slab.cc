// Slab bodies (search/proposals.h).
#include <algorithm>
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
// samples; such pairs, one per axis at most, heaviest first (a chair's seat and backrest).
// [box_lo, box_hi]: the target's box in that frame (LocalBox).
std::vector<Slab> FindSlabs(const Target& target, const Eigen::Matrix3d& world_from_local, const Vec3d& box_lo,
                            const Vec3d& box_hi) {
  const Positions<double>& points = target.points();
  const Positions<double>& normals = target.normals();
  constexpr int kBins = 100;
  std::vector<std::pair<double, Slab>> slabs;
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3d direction = world_from_local.col(axis);
    const double lo = box_lo[axis], hi = box_hi[axis];
    if (!(hi - lo > 0)) continue;
    std::vector<double> plus(kBins, 0), minus(kBins, 0);
    for (size_t i = 0; i < points.size(); ++i) {
      const int bin = BinOf(direction.dot(points[i]), lo, hi, kBins);
      const double facing = direction.dot(normals[i]);
      if (facing > 0.9) plus[bin] += 1;
      if (facing < -0.9) minus[bin] += 1;
    }
    const auto [top, top_weight] = DensestLayer(plus);
    const auto [bottom, bottom_weight] = DensestLayer(minus);
    const double n = static_cast<double>(points.size());
    if (bottom >= top || top - bottom > 0.6 * kBins || std::min(top_weight, bottom_weight) < 0.05 * n) continue;
    slabs.push_back({top_weight + bottom_weight,
                     {axis, lo + (bottom + 0.5) / kBins * (hi - lo), lo + (top + 0.5) / kBins * (hi - lo)}});
  }
  std::stable_sort(slabs.begin(), slabs.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  std::vector<Slab> found;
  for (const auto& [weight, slab] : slabs) found.push_back(slab);
  return found;
}

// Where the parts beyond the slab on one side (`side` +1 above, -1 below) start across it: for
// each of the two other axes, the least |coordinate| (2nd percentile, in the box's half
// extents) of the target's samples there; a table's legs at the corners give about 0.8 on both
// axes, a pedestal under the middle about 0. Zero when the side holds under 5% of the samples.
// [lo, hi]: the target's box in the pose's frame (LocalBox).
Eigen::Vector2d PartsStart(const Target& target, const Layout& pose, const Vec3d& lo, const Vec3d& hi,
                           const Slab& slab, int side) {
  const int a = (slab.axis + 1) % 3, b = (slab.axis + 2) % 3;
  const Vec3d centre = (lo + hi) / 2, half = ((hi - lo) / 2).cwiseMax(Vec3d::Constant(1e-12));
  const double margin = 0.02 * (hi - lo).norm();
  std::vector<double> across_a, across_b;
  for (const Vec3d& p : target.points()) {
    const Vec3d q = pose.world_from_local.transpose() * p;
    const bool beyond = side > 0 ? q[slab.axis] > slab.hi + margin : q[slab.axis] < slab.lo - margin;
    if (!beyond) continue;
    across_a.push_back(std::abs(q[a] - centre[a]) / half[a]);
    across_b.push_back(std::abs(q[b] - centre[b]) / half[b]);
  }
  if (across_a.size() < 0.05 * target.points().size()) return Eigen::Vector2d::Zero();
  const size_t k = across_a.size() / 50;
  std::nth_element(across_a.begin(), across_a.begin() + k, across_a.end());
  std::nth_element(across_b.begin(), across_b.begin() + k, across_b.end());
  return Eigen::Vector2d(across_a[k], across_b[k]);
}

}  // namespace

std::vector<Expansion> ProposeSlabs(const Target& target, const Layout& pose) {
  std::vector<Expansion> expansions;
  Vec3d lo, hi;
  LocalBox(target, pose.world_from_local, &lo, &hi);
  const std::vector<Slab> slabs = FindSlabs(target, pose.world_from_local, lo, hi);
  for (size_t i = 0; i < slabs.size() && i < 2; ++i) {
    const Slab& slab = slabs[i];
    // The slab is not fitted alone: the rest of the target would pull it back to the bounding
    // box. Its extrusions are proposed from the placed slab and fitted with it; with a loop-cut
    // grid across it (legs at the corners) and without (a boss on the whole face); for the
    // heaviest slab only, unless the parts beyond it place the grid.
    const std::string across = "slab across " + build::AxisName(static_cast<build::Axis>(slab.axis));
    const Expansion plain{PoseLayout(target, pose.world_from_local, slab.axis, slab.lo, slab.hi), across};
    const int a = (slab.axis + 1) % 3, b = (slab.axis + 2) % 3;
    if (i == 0) {
      Expansion gridded = plain;
      gridded.layout.grid = LoopCutGrid(std::min(a, b), std::max(a, b), 4);
      gridded.what += " with a LoopCut grid";
      expansions.push_back(plain);
      expansions.push_back(gridded);
    }
    // The grid's loops where the parts beyond the slab start (a table's legs at the corners):
    // the new corner faces are then the legs' sections, and their extrusions fit at once.
    for (int side : {-1, 1}) {
      const Eigen::Vector2d start = PartsStart(target, pose, lo, hi, slab, side);
      if (!(start.minCoeff() > 0.2 && start.maxCoeff() < 0.95)) continue;
      Expansion placed = plain;
      placed.layout.grid = LoopCutGrid(std::min(a, b), std::max(a, b), 4, a < b ? start : start.reverse().eval());
      placed.what += std::string(" with a LoopCut grid where the parts ") + (side > 0 ? "above" : "below") + " start";
      expansions.push_back(placed);
    }
  }
  return expansions;
}

}  // namespace opgraph
