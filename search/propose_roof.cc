// Roofs on box bodies (search/proposals.h).
#include <cmath>
#include <limits>

#include "search/box_body.h"
#include "search/loop_ops.h"
#include "search/pose.h"
#include "search/proposals.h"

namespace opgraph {
namespace {

// The body touches an end of the box when within this many bins of it (FindBoxBody's runs
// include the bins their flatness test reaches).
constexpr double kEndBins = 2.5;
// The section halfway up the rest: samples within this fraction of the box's length of it.
constexpr double kSliceHalfWidth = 0.02;

// Across which axis other than `up` the target narrows most at `level` along `up`, relative
// to the body: a ridge line runs along the axis the roof keeps whole. -1 when no sample is there.
int NarrowAxis(const std::vector<Vec3d>& local, int up, double level, double length, const BoxBody& body) {
  Vec3d lo = Vec3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Vec3d& q : local) {
    if (std::abs(q[up] - level) <= kSliceHalfWidth * length) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
  }
  const int a = (up + 1) % 3, b = (up + 2) % 3;
  if (!(hi[a] >= lo[a])) return -1;
  const double across_a = (hi[a] - lo[a]) / (body.hi[a] - body.lo[a]);
  const double across_b = (hi[b] - lo[b]) / (body.hi[b] - body.lo[b]);
  return across_a <= across_b ? a : b;
}

}  // namespace

std::vector<Expansion> ProposeRoofs(const Target& target, const Layout& pose) {
  Vec3d lo, hi;
  LocalBox(target, pose.world_from_local, &lo, &hi);
  const std::vector<Vec3d> local = LocalSamples(target, pose.world_from_local);
  std::vector<Expansion> expansions;
  for (const auto& [up, body] : FindBoxBodies(local, lo, hi)) {
    const double length = hi[up] - lo[up], reach = kEndBins * length / kBodyBins;
    const bool at_lo = body.lo[up] - lo[up] <= reach, at_hi = hi[up] - body.hi[up] <= reach;
    if (at_lo == at_hi) continue;  // walls stand on one end; the roof rises toward the other
    const int sign = at_lo ? 1 : -1;
    const double rise = at_lo ? hi[up] - body.hi[up] : body.lo[up] - lo[up];
    const double level = at_lo ? body.hi[up] + rise / 2 : body.lo[up] - rise / 2;
    const int cut = NarrowAxis(local, up, level, length, body);
    if (cut < 0) continue;
    Layout layout = PoseLayoutOnBox(pose.world_from_local, body.lo, body.hi);
    layout.ridge = RaisedRidge(cut, up, sign, layout.half_extent, rise);
    auto name = [](int axis) { return build::AxisName(static_cast<build::Axis>(axis)); };
    expansions.push_back({layout, "box body along " + name(up) + ", its ridge across " + name(cut) + " raised along " +
                                      (sign > 0 ? "+" : "-") + name(up)});
  }
  return expansions;
}

}  // namespace opgraph
