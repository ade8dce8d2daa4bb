#include "search/pose.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>

#include "ops/builders.h"

namespace opgraph {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Turns the pair of axes other than `distinct` about it to the smallest bounding rectangle of
// the samples.
void TurnToSmallestRectangle(const Positions<double>& points, const Vec3d& mean, int distinct,
                             Eigen::Matrix3d* frame) {
  const Vec3d e1 = frame->col((distinct + 1) % 3), e2 = frame->col((distinct + 2) % 3);
  const size_t stride = std::max<size_t>(1, points.size() / 5000);
  double best_area = kInf;
  for (int step = 0; step < 180; ++step) {
    const double angle = DegToRad(0.5 * step);
    const Vec3d a = std::cos(angle) * e1 + std::sin(angle) * e2, b = -std::sin(angle) * e1 + std::cos(angle) * e2;
    double a_lo = kInf, a_hi = -kInf, b_lo = kInf, b_hi = -kInf;
    for (size_t i = 0; i < points.size(); i += stride) {
      const double x = a.dot(points[i] - mean), y = b.dot(points[i] - mean);
      a_lo = std::min(a_lo, x), a_hi = std::max(a_hi, x), b_lo = std::min(b_lo, y), b_hi = std::max(b_hi, y);
    }
    const double area = (a_hi - a_lo) * (b_hi - b_lo);
    if (area < best_area) best_area = area, frame->col((distinct + 1) % 3) = a, frame->col((distinct + 2) % 3) = b;
  }
}

}  // namespace

void LocalBox(const Target& target, const Eigen::Matrix3d& world_from_local, Vec3d* lo, Vec3d* hi) {
  *lo = Vec3d::Constant(kInf), *hi = Vec3d::Constant(-kInf);
  for (const Vec3d& p : target.points()) {
    const Vec3d q = world_from_local.transpose() * p;
    *lo = lo->cwiseMin(q), *hi = hi->cwiseMax(q);
  }
}

std::vector<Vec3d> LocalSamples(const Target& target, const Eigen::Matrix3d& world_from_local) {
  const Positions<double>& points = target.points();
  const size_t stride = std::max<size_t>(1, points.size() / 20000);
  std::vector<Vec3d> local;
  for (size_t i = 0; i < points.size(); i += stride) local.push_back(world_from_local.transpose() * points[i]);
  return local;
}

int BinOf(double x, double lo, double hi, int bins) {
  return std::clamp(static_cast<int>((x - lo) / (hi - lo) * bins), 0, bins - 1);
}

Layout PoseLayout(const Target& target, const Eigen::Matrix3d& world_from_local, int slab_axis, double slab_lo,
                  double slab_hi) {
  Vec3d lo, hi;
  LocalBox(target, world_from_local, &lo, &hi);
  if (slab_axis >= 0) lo[slab_axis] = slab_lo, hi[slab_axis] = slab_hi;
  return PoseLayoutOnBox(world_from_local, lo, hi);
}

Layout PoseLayoutOnBox(const Eigen::Matrix3d& world_from_local, const Vec3d& lo, const Vec3d& hi) {
  const double extent = (hi - lo).maxCoeff();
  const Vec3d half = ((hi - lo) / 2).cwiseMax(Vec3d::Constant(1e-3 * extent));
  // R = Rz Ry Rx: Eigen's eulerAngles(2, 1, 0) returns (z, y, x).
  const Vec3d zyx = world_from_local.eulerAngles(2, 1, 0);
  Layout layout;
  layout.scale = build::GlobalScale(half);
  layout.rotate = build::GlobalRotate(Vec3d(RadToDeg(zyx[2]), RadToDeg(zyx[1]), RadToDeg(zyx[0])));
  layout.translate = build::GlobalTranslate(world_from_local * ((hi + lo) / 2));
  layout.half_extent = half;
  layout.world_from_local = world_from_local;
  return layout;
}

Eigen::Matrix3d PrincipalFrame(const Target& target) {
  const Positions<double>& points = target.points();
  Vec3d mean = Vec3d::Zero();
  for (const Vec3d& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Vec3d& p : points) covariance += (p - mean) * (p - mean).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
  const Vec3d& variances = eigen.eigenvalues();
  auto near_equal = [&](int a, int b) {
    return std::abs(variances[a] - variances[b]) < 0.15 * std::max(variances[a], variances[b]);
  };
  Eigen::Matrix3d frame = eigen.eigenvectors();
  if (near_equal(0, 1) && near_equal(1, 2)) return Eigen::Matrix3d::Identity();
  if (near_equal(0, 1) || near_equal(1, 2)) TurnToSmallestRectangle(points, mean, near_equal(0, 1) ? 2 : 0, &frame);
  if (frame.determinant() < 0) frame.col(2) *= -1;
  return frame;
}

int LongAxis(const Layout& layout) {
  int axis = 0;
  for (int a = 1; a < 3; ++a) {
    if (layout.half_extent[a] > layout.half_extent[axis]) axis = a;
  }
  return axis;
}

}  // namespace opgraph
