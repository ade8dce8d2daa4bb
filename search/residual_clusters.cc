#include "search/residual_clusters.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "core/nearest.h"
#include "ops/sequence.h"

namespace opgraph {
namespace {

// A sample beyond the other surface, with the point of that surface it is nearest to.
struct Outlier {
  Vec3d point, foot;
};

using Cell = std::array<int, 3>;

// Connected groups of outliers over grid cells of side `cell` (26-neighbourhood).
std::vector<std::vector<Outlier>> Connect(const std::vector<Outlier>& outliers, double cell) {
  std::map<Cell, std::vector<int>> cells;
  for (int i = 0; i < static_cast<int>(outliers.size()); ++i) {
    const Vec3d& p = outliers[i].point;
    cells[{static_cast<int>(std::floor(p.x() / cell)), static_cast<int>(std::floor(p.y() / cell)),
           static_cast<int>(std::floor(p.z() / cell))}].push_back(i);
  }
  std::map<Cell, int> component;
  std::vector<std::vector<Outlier>> groups;
  for (const auto& [seed, members] : cells) {
    if (component.count(seed)) continue;
    const int id = static_cast<int>(groups.size());
    groups.emplace_back();
    std::vector<Cell> stack = {seed};
    component[seed] = id;
    while (!stack.empty()) {
      const Cell c = stack.back();
      stack.pop_back();
      for (int i : cells.at(c)) groups[id].push_back(outliers[i]);
      for (int dx = -1; dx <= 1; ++dx) {
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dz = -1; dz <= 1; ++dz) {
            const Cell n = {c[0] + dx, c[1] + dy, c[2] + dz};
            if (cells.count(n) && !component.count(n)) component[n] = id, stack.push_back(n);
          }
        }
      }
    }
  }
  return groups;
}

// The principal-axes box of a group's points and feet, grown by `margin` on every side.
ResidualCluster BoxOf(const std::vector<Outlier>& group, bool excess, double margin) {
  Vec3d mean = Vec3d::Zero();
  for (const Outlier& o : group) mean += o.point;
  mean /= static_cast<double>(group.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Outlier& o : group) covariance += (o.point - mean) * (o.point - mean).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
  ResidualCluster cluster;
  cluster.excess = excess;
  cluster.num_samples = static_cast<int>(group.size());
  cluster.axes = eigen.eigenvectors();
  if (cluster.axes.determinant() < 0) cluster.axes.col(2) *= -1;
  Vec3d lo = Vec3d::Constant(1e300), hi = Vec3d::Constant(-1e300);
  for (const Outlier& o : group) {
    for (const Vec3d& p : {o.point, o.foot}) {
      const Vec3d q = cluster.axes.transpose() * p;
      lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
    }
  }
  lo.array() -= margin, hi.array() += margin;
  cluster.centre = cluster.axes * ((lo + hi) / 2);
  cluster.extents = hi - lo;
  return cluster;
}

}  // namespace

std::vector<ResidualCluster> FindResidualClusters(const Target& target, const Layout& layout,
                                                  std::vector<ResidualCluster>* interior) {
  Sequence sequence = ParseSequence(layout.Document());
  const std::vector<Mesh> steps = EvaluateSequence(&sequence);
  const Mesh& cage = steps[layout.CageStep()];
  const Eigen::Matrix3d world_from_local = layout.PoseRotation();
  const Vec3d translation = layout.PoseTranslation();
  const double diagonal = 2.0 * layout.half_extent.norm();
  const double threshold = 0.03 * diagonal;
  const std::vector<MeshTriangle> triangles = FanTriangulate(cage.faces);
  const TriangleTree cage_tree(cage.vertices, triangles);
  // Target samples in the cage's frame, beyond the cage.
  const Positions<double>& points = target.points();
  const size_t stride = std::max<size_t>(1, points.size() / 3000);
  Positions<double> local;
  std::vector<Outlier> beyond_cage, inside_cage;
  for (size_t i = 0; i < points.size(); i += stride) {
    local.push_back(layout.LocalToCage(world_from_local.transpose() * (points[i] - translation)));
    const ClosestPoint closest = cage_tree.Closest(local.back());
    if (closest.triangle < 0 || closest.squared_distance < threshold * threshold) continue;
    if ((local.back() - closest.point).dot(cage_tree.Normal(closest.triangle)) > 0) {
      beyond_cage.push_back({local.back(), closest.point});
    } else {
      inside_cage.push_back({local.back(), local.back()});  // its box is the target's own surface
    }
  }
  // Cage samples beyond the target: far from it, and the target's nearest sample not clearly
  // outward (inward, or sideways: the rim of a pocket in the cage's own plane).
  const PointTree local_tree(local);
  const SurfaceSamples cage_samples = SampleSurface(cage.vertices, triangles, 3000, 1);
  std::vector<Outlier> beyond_target;
  for (size_t i = 0; i < cage_samples.points.size(); ++i) {
    double squared = 0;
    const int nearest = local_tree.Nearest(cage_samples.points[i], &squared);
    if (squared < threshold * threshold) continue;
    if ((local[nearest] - cage_samples.points[i]).dot(cage_samples.normals[i]) < 0.5 * std::sqrt(squared)) {
      beyond_target.push_back({cage_samples.points[i], local[nearest]});
    }
  }
  std::vector<ResidualCluster> clusters;
  const double margin = 0.03 * diagonal;
  for (bool excess : {false, true}) {
    const std::vector<Outlier>& outliers = excess ? beyond_target : beyond_cage;
    const size_t total = excess ? cage_samples.points.size() : local.size();
    for (const std::vector<Outlier>& group : Connect(outliers, 0.05 * diagonal)) {
      if (group.size() >= std::max<size_t>(5, total / 100)) clusters.push_back(BoxOf(group, excess, margin));
    }
  }
  const auto largest_first = [](const ResidualCluster& a, const ResidualCluster& b) {
    return a.num_samples > b.num_samples;
  };
  std::stable_sort(clusters.begin(), clusters.end(), largest_first);
  if (interior != nullptr) {
    interior->clear();
    for (const std::vector<Outlier>& group : Connect(inside_cage, 0.05 * diagonal)) {
      if (group.size() >= std::max<size_t>(5, local.size() / 100)) interior->push_back(BoxOf(group, true, 0));
    }
    std::stable_sort(interior->begin(), interior->end(), largest_first);
  }
  return clusters;
}

}  // namespace opgraph
