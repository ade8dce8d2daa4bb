#include "solver/target.h"

#include <cmath>
#include <random>
#include <stdexcept>

#include "core/metrics.h"
#include "io/read_input.h"

namespace opgraph {

std::string TargetOptions::Check() const {
  if (num_samples < 100 || num_samples > 10000000) return "num_samples must be in [100, 1e7]";
  if (max_cloud_points < 100) return "max_cloud_points must be >= 100";
  if (normal_neighbours < 3 || normal_neighbours > 100) return "normal_neighbours must be in [3, 100]";
  return "";
}

Target::Target(Mesh shape, Positions<double> cloud_normals, const TargetOptions& options) : shape_(std::move(shape)) {
  UnitBoxTransform(shape_, &centre_, &scale_);
  if (!is_cloud()) {
    const std::vector<MeshTriangle> triangles = FanTriangulate(shape_.faces);
    const SurfaceSamples samples = SampleSurface(shape_.vertices, triangles, options.num_samples, options.seed);
    if (samples.points.empty()) throw std::runtime_error("target: the mesh has no surface area");
    points_ = samples.points;
    normals_ = samples.normals;
    tree_.reset(new PointTree(points_));
    return;
  }
  // A seeded random order (and subsample of large clouds), so any prefix of the points is a
  // fair sample of the cloud (partial Fisher-Yates on the indices).
  std::vector<int> order(shape_.vertices.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::mt19937_64 rng(options.seed);
  const int kept = std::min<int>(options.max_cloud_points, static_cast<int>(order.size()));
  for (int i = 0; i < kept; ++i) std::swap(order[i], order[i + rng() % (order.size() - i)]);
  for (int i = 0; i < kept; ++i) {
    points_.push_back(shape_.vertices[order[i]]);
    if (cloud_normals.size() == shape_.vertices.size()) normals_.push_back(cloud_normals[order[i]]);
  }
  tree_.reset(new PointTree(points_));
  if (normals_.size() != points_.size()) normals_ = EstimatePointNormals(points_, options.normal_neighbours);
  cloud_surface_ = std::make_unique<CloudSurface>(points_, normals_);
}

ShapeMetrics ComputeTargetMetrics(const Mesh& output, const Target& target, const MetricsOptions& options) {
  if (!target.is_cloud()) return ComputeShapeMetrics(output, target.shape(), options);
  Mesh cloud;
  cloud.vertices = target.points();
  return ComputeShapeMetrics(output, cloud, *target.cloud_surface(), options);
}

std::unique_ptr<Target> LoadTarget(const std::string& path, const TargetOptions& options) {
  const std::string problem = options.Check();
  if (!problem.empty()) throw std::runtime_error("target options: " + problem);
  InputGeometry input = ReadInput(path);
  if (input.mesh.vertices.size() < 4) throw std::runtime_error(path + ": fewer than 4 points");
  return std::make_unique<Target>(std::move(input.mesh), std::move(input.normals), options);
}

}  // namespace opgraph
