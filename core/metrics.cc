#include "core/metrics.h"

#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <memory>

#include <Eigen/Geometry>

#include "core/cloud_surface.h"
#include "core/geometry.h"
#include "core/nearest.h"

namespace opgraph {

std::string MetricsOptions::Check() const {
  return num_samples > 0 && num_samples <= 100000000 ? "" : "num_samples must be in [1, 1e8]";
}

void UnitBoxTransform(const Mesh& mesh, Vec3d* centre, double* scale) {
  Eigen::AlignedBox3d box;
  for (const Vec3d& v : mesh.vertices) box.extend(v);
  *centre = box.center();
  const double longest = box.sizes().maxCoeff();
  *scale = longest > 0 ? 1.0 / longest : 1.0;
}

namespace {

Positions<double> Normalised(const Positions<double>& points, const Vec3d& centre, double scale) {
  Positions<double> out(points.size());
  for (size_t i = 0; i < points.size(); ++i) out[i] = (points[i] - centre) * scale;
  return out;
}

// Where distances to a cloud's surface are measured: `surface`, built in the cloud's own frame,
// which is the unit box's scaled by 1 / scale about centre.
struct SurfaceInFrame {
  const CloudSurface* surface = nullptr;
  Vec3d centre = Vec3d::Zero();
  double scale = 1;
  double Distance(const Vec3d& unit_point) const { return scale * surface->Distance(unit_point / scale + centre); }
};

// Distances from `samples` to a shape: its surface when it has triangles, else the surface its
// points sample when `cloud.surface` is given, else its points.
struct DistanceStats {
  double mean = 0, mean_squared = 0, normal_dot = 0;
  int within_001 = 0, within_002 = 0;
};

DistanceStats DistancesToShape(const SurfaceSamples& samples, const Positions<double>& positions,
                               const std::vector<MeshTriangle>& triangles, const SurfaceInFrame& cloud) {
  DistanceStats stats;
  const int n = static_cast<int>(samples.points.size());
  if (n == 0) return stats;
  std::unique_ptr<TriangleTree> surface;
  std::unique_ptr<PointTree> points;
  if (!triangles.empty()) {
    surface.reset(new TriangleTree(positions, triangles));
  } else if (cloud.surface == nullptr) {
    points.reset(new PointTree(positions));
  }
  for (int i = 0; i < n; ++i) {
    double squared;
    if (surface) {
      const ClosestPoint c = surface->Closest(samples.points[i]);
      squared = c.squared_distance;
      if (!samples.normals.empty()) stats.normal_dot += std::abs(samples.normals[i].dot(surface->Normal(c.triangle)));
    } else if (cloud.surface) {
      const double d = cloud.Distance(samples.points[i]);
      squared = d * d;
    } else {
      points->Nearest(samples.points[i], &squared);
    }
    const double d = std::sqrt(squared);
    stats.mean += d;
    stats.mean_squared += squared;
    stats.within_001 += d <= 0.01;
    stats.within_002 += d <= 0.02;
  }
  stats.mean /= n;
  stats.mean_squared /= n;
  stats.normal_dot /= n;
  return stats;
}

double MeanSquaredNearest(const Positions<double>& from, const PointTree& to) {
  double sum = 0;
  for (const Vec3d& p : from) {
    double squared;
    to.Nearest(p, &squared);
    sum += squared;
  }
  return from.empty() ? 0 : sum / from.size();
}

double MeanNearest(const Positions<double>& from, const PointTree& to) {
  double sum = 0;
  for (const Vec3d& p : from) {
    double squared;
    to.Nearest(p, &squared);
    sum += std::sqrt(squared);
  }
  return from.empty() ? 0 : sum / from.size();
}

double F1(double precision, double recall) {
  return precision + recall > 0 ? 2 * precision * recall / (precision + recall) : 0;
}

// The metrics with distances to a cloud target measured to `cloud_surface` when given.
ShapeMetrics MetricsAgainst(const Mesh& output, const Mesh& target, const CloudSurface* cloud_surface,
                            const MetricsOptions& options) {
  const std::string problem = options.Check();
  if (!problem.empty()) throw std::invalid_argument("metrics options: " + problem);
  Vec3d centre;
  double scale;
  UnitBoxTransform(target, &centre, &scale);
  const Positions<double> output_positions = Normalised(output.vertices, centre, scale);
  const Positions<double> target_positions = Normalised(target.vertices, centre, scale);
  const std::vector<MeshTriangle> output_triangles = FanTriangulate(output.faces);
  const std::vector<MeshTriangle> target_triangles = FanTriangulate(target.faces);

  const SurfaceSamples output_samples = SampleSurface(output_positions, output_triangles, options.num_samples, options.seed);
  SurfaceSamples target_samples;
  if (!target_triangles.empty()) {
    target_samples = SampleSurface(target_positions, target_triangles, options.num_samples, options.seed + 1);
  } else {
    target_samples.points = target_positions;
  }

  SurfaceInFrame cloud;
  if (target_triangles.empty() && cloud_surface != nullptr) cloud = {cloud_surface, centre, scale};
  const DistanceStats forward = DistancesToShape(output_samples, target_positions, target_triangles, cloud);
  const DistanceStats backward = DistancesToShape(target_samples, output_positions, output_triangles, {});
  ShapeMetrics metrics;
  metrics.chamfer = {forward.mean, backward.mean};
  metrics.chamfer_squared = {forward.mean_squared, backward.mean_squared};
  metrics.normal_consistency = target_triangles.empty() ? std::numeric_limits<double>::quiet_NaN()
                                                        : 0.5 * (forward.normal_dot + backward.normal_dot);
  const double n_out = std::max<size_t>(output_samples.points.size(), 1);
  const double n_target = std::max<size_t>(target_samples.points.size(), 1);
  metrics.f1_001 = F1(forward.within_001 / n_out, backward.within_001 / n_target);
  metrics.f1_002 = F1(forward.within_002 / n_out, backward.within_002 / n_target);

  const PointTree output_tree(output_samples.points), target_tree(target_samples.points);
  metrics.sample_chamfer = MeanSquaredNearest(output_samples.points, target_tree) +
                           MeanSquaredNearest(target_samples.points, output_tree);
  return metrics;
}

}  // namespace

ShapeMetrics ComputeShapeMetrics(const Mesh& output, const Mesh& target, const MetricsOptions& options) {
  return MetricsAgainst(output, target, nullptr, options);
}

ShapeMetrics ComputeShapeMetrics(const Mesh& output, const Mesh& target, const Positions<double>& target_normals,
                                 const MetricsOptions& options) {
  if (!target.faces.empty() || target_normals.empty()) return MetricsAgainst(output, target, nullptr, options);
  if (target_normals.size() != target.vertices.size()) {
    throw std::invalid_argument("metrics: a cloud's normals must be one per point");
  }
  const CloudSurface surface(target.vertices, target_normals);
  return MetricsAgainst(output, target, &surface, options);
}

ShapeMetrics ComputeShapeMetrics(const Mesh& output, const Mesh& target, const CloudSurface& target_surface,
                                 const MetricsOptions& options) {
  return MetricsAgainst(output, target, &target_surface, options);
}

double SamplingNoiseFloor(const Mesh& target, const MetricsOptions& options) {
  Vec3d centre;
  double scale;
  UnitBoxTransform(target, &centre, &scale);
  const Positions<double> positions = Normalised(target.vertices, centre, scale);
  const std::vector<MeshTriangle> triangles = FanTriangulate(target.faces);
  const SurfaceSamples a = SampleSurface(positions, triangles, options.num_samples, options.seed + 1);
  const SurfaceSamples b = SampleSurface(positions, triangles, options.num_samples, options.seed + 1000003);
  const PointTree tree_a(a.points), tree_b(b.points);
  return MeanNearest(a.points, tree_b) + MeanNearest(b.points, tree_a);
}

WiringMetrics ComputeWiringMetrics(const Mesh& mesh) {
  WiringMetrics wiring;
  if (mesh.faces.empty()) return wiring;
  std::map<long long, bool> edges;
  for (const Polygon& f : mesh.faces) {
    for (size_t i = 0; i < f.size(); ++i) edges[EdgeKey(f[i], f[(i + 1) % f.size()])] = true;
  }
  std::vector<int> valence(mesh.NumVertices(), 0);
  for (const auto& edge : edges) {
    ++valence[edge.first >> 32];
    ++valence[edge.first & 0xffffffffLL];
  }
  int valence4 = 0;
  for (int v : valence) valence4 += v == 4;
  wiring.valence4_fraction = mesh.NumVertices() > 0 ? static_cast<double>(valence4) / mesh.NumVertices() : 0;
  int quads = 0;
  double sum = 0, sum_squared = 0;
  for (const Polygon& f : mesh.faces) {
    quads += f.size() == 4;
    const double area = 0.5 * Norm(FaceAreaNormal(mesh.vertices, f));
    sum += area;
    sum_squared += area * area;
  }
  const double n = mesh.NumFaces();
  wiring.quad_fraction = quads / n;
  const double mean = sum / n;
  const double variance = std::max(0.0, sum_squared / n - mean * mean);
  wiring.face_area_cv = mean > 0 ? std::sqrt(variance) / mean : 0;
  return wiring;
}

}  // namespace opgraph
