#include "search/section_changes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "search/pose.h"

namespace opgraph {
namespace {

// The half-widths of a bin's samples from the centre: +u, -u, +v, -v (u, v: the other axes).
using Sides = std::array<double, 4>;

double Median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

double AxisChange(const std::vector<Vec3d>& local, int axis, const Vec3d& lo, const Vec3d& hi) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const Vec3d centre = (lo + hi) / 2;
  std::vector<Sides> sides(kSectionBins, Sides{0, 0, 0, 0});
  std::vector<int> count(kSectionBins, 0);
  for (const Vec3d& q : local) {
    const int b = BinOf(q[axis], lo[axis], hi[axis], kSectionBins);
    Sides& s = sides[b];
    const double du = q[u] - centre[u], dv = q[v] - centre[v];
    s[0] = std::max(s[0], du), s[1] = std::max(s[1], -du), s[2] = std::max(s[2], dv), s[3] = std::max(s[3], -dv);
    ++count[b];
  }
  std::vector<int> used;
  for (int b = 1; b + 1 < kSectionBins; ++b) {
    if (count[b] > 0) used.push_back(b);
  }
  if (used.empty()) return 0;
  Sides usual;
  for (int k = 0; k < 4; ++k) {
    std::vector<double> widths;
    for (int b : used) widths.push_back(sides[b][k]);
    usual[k] = Median(widths);
    if (!(usual[k] > 1e-9 * (hi - lo).maxCoeff())) return 0;  // a side on the centre: no section to scale
  }
  double largest = 0;
  for (int b : used) {
    double grow = std::numeric_limits<double>::infinity(), shrink = grow;
    for (int k = 0; k < 4; ++k) {
      const double change = sides[b][k] / usual[k] - 1;
      grow = std::min(grow, change), shrink = std::min(shrink, -change);
    }
    largest = std::max({largest, grow, shrink});
  }
  return largest;
}

}  // namespace

Vec3d SectionChanges(const std::vector<Vec3d>& local) {
  Vec3d lo = Vec3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Vec3d& q : local) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
  Vec3d changes = Vec3d::Zero();
  if (local.empty() || !((hi - lo).minCoeff() > 0)) return changes;
  for (int axis = 0; axis < 3; ++axis) changes[axis] = AxisChange(local, axis, lo, hi);
  return changes;
}

}  // namespace opgraph
