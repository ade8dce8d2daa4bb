#include "search/box_body.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "search/pose.h"

namespace opgraph {
namespace {

constexpr int kBodyBins = 50;

// A bin's section is constant when the bins kReach either side of it differ by under this
// fraction of the box across (a box's sides are planes; an Extrude's narrowed cap makes its
// sides taper).
constexpr double kFlat = 0.005;
constexpr int kReach = 2;
// The body spans at least this fraction of the box along the axis, and leaves at least
// kMinBeyond of it to grow.
constexpr double kMinBody = 0.2, kMinBeyond = 0.05;
// A box's section: this fraction of its samples within kOnSide of the box across from a side.
constexpr double kMinOnSides = 0.95, kOnSide = 0.01;

// The box of a set of samples across `axis` (the other two coordinates).
struct Section {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  size_t count = 0;
  void Add(const Vec3d& q, int axis) {
    const Eigen::Vector2d across(q[(axis + 1) % 3], q[(axis + 2) % 3]);
    lo = lo.cwiseMin(across), hi = hi.cwiseMax(across), ++count;
  }
};

// Whether the samples of bins [first, last] along `axis`, but for kReach bins at either end (a
// body's end faces and the rims where parts grow from it), lie on the sides of `section`'s
// rectangle: a box's, not an L's or a T's.
bool OnRectangle(const std::vector<Vec3d>& local, int axis, const Vec3d& lo, const Vec3d& hi, int first, int last,
                 const Section& section, const Eigen::Vector2d& across_size) {
  const double tolerance = kOnSide * across_size.maxCoeff();
  size_t on = 0, all = 0;
  for (const Vec3d& q : local) {
    const int b = BinOf(q[axis], lo[axis], hi[axis], kBodyBins);
    if (b < first + kReach || b > last - kReach) continue;
    const Eigen::Vector2d across(q[(axis + 1) % 3], q[(axis + 2) % 3]);
    const double to_side = std::min((across - section.lo).minCoeff(), (section.hi - across).minCoeff());
    ++all, on += to_side < tolerance;
  }
  return all > 0 && on >= kMinOnSides * all;
}

// Along `axis`, binned in kBodyBins over the samples' box [lo, hi]: of the runs of bins whose
// section is one constant rectangle (the samples on its sides), spanning at least a fifth of
// the box and leaving at least a twentieth, the one with the largest box. False when there is
// none or a bin is empty (parts apart along the axis are not grown from one another).
bool FindBoxBody(const std::vector<Vec3d>& local, int axis, const Vec3d& lo, const Vec3d& hi, BoxBody* body) {
  const double length = hi[axis] - lo[axis];
  const Eigen::Vector2d across_size(hi[(axis + 1) % 3] - lo[(axis + 1) % 3], hi[(axis + 2) % 3] - lo[(axis + 2) % 3]);
  if (!(length > 0) || !(across_size.minCoeff() > 0)) return false;
  std::vector<Section> bins(kBodyBins);
  for (const Vec3d& q : local) bins[BinOf(q[axis], lo[axis], hi[axis], kBodyBins)].Add(q, axis);
  for (const Section& bin : bins) {
    if (bin.count == 0) return false;
  }
  auto flat = [&](int b) {
    const Section& before = bins[b - kReach];
    const Section& after = bins[b + kReach];
    return std::max((before.lo - after.lo).cwiseAbs().cwiseQuotient(across_size).maxCoeff(),
                    (before.hi - after.hi).cwiseAbs().cwiseQuotient(across_size).maxCoeff()) < kFlat;
  };
  bool found = false;
  for (int b = kReach; b + kReach < kBodyBins;) {
    if (!flat(b)) {
      ++b;
      continue;
    }
    int last = b;
    while (last + 1 + kReach < kBodyBins && flat(last + 1)) ++last;
    // Bins b - kReach to last + kReach share the section.
    const int first_bin = b - kReach, last_bin = last + kReach, count = last_bin - first_bin + 1;
    b = last + 1;
    if (count < kMinBody * kBodyBins || count > (1 - kMinBeyond) * kBodyBins) continue;
    Section section;
    for (int k = first_bin; k <= last_bin; ++k) {
      section.lo = section.lo.cwiseMin(bins[k].lo), section.hi = section.hi.cwiseMax(bins[k].hi);
    }
    if (!OnRectangle(local, axis, lo, hi, first_bin, last_bin, section, across_size)) continue;
    const int a = (axis + 1) % 3, c = (axis + 2) % 3;
    BoxBody run;
    run.lo[axis] = lo[axis] + length * first_bin / kBodyBins, run.hi[axis] = lo[axis] + length * (last_bin + 1) / kBodyBins;
    run.lo[a] = section.lo[0], run.hi[a] = section.hi[0];
    run.lo[c] = section.lo[1], run.hi[c] = section.hi[1];
    run.volume = (run.hi - run.lo).prod();
    if (!found || run.volume > body->volume) *body = run, found = true;
  }
  return found;
}

}  // namespace

std::vector<std::pair<int, BoxBody>> FindBoxBodies(const std::vector<Vec3d>& local, const Vec3d& lo, const Vec3d& hi) {
  std::vector<std::pair<int, BoxBody>> bodies;
  for (int axis = 0; axis < 3; ++axis) {
    BoxBody body;
    if (FindBoxBody(local, axis, lo, hi, &body)) bodies.push_back({axis, body});
  }
  std::stable_sort(bodies.begin(), bodies.end(),
                   [](const auto& a, const auto& b) { return a.second.volume > b.second.volume; });
  return bodies;
}

}  // namespace opgraph
