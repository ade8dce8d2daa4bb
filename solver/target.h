// The shape a sequence is fitted to: a mesh or a point cloud (any format io/read_input reads),
// with seeded surface samples and normals and a kd-tree over them.
//
// Frames: everything stays in the input's frame and units (the sequence is fitted there, so
// outputs need no transform back); `centre` and `scale` map it to the unit box used by the
// metrics and by the residual weights: point_in_unit = (point_in_input - centre) * scale.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "core/cloud_surface.h"
#include "core/mesh.h"
#include "core/metrics.h"
#include "core/nearest.h"

namespace opgraph {

struct TargetOptions {
  int num_samples = 10000;     // surface samples of a mesh target (a cloud keeps its points)
  int max_cloud_points = 50000;  // larger clouds are subsampled (seeded)
  int normal_neighbours = 16;  // for estimating a cloud's normals (io/read_input)
  uint64_t seed = 1;
  // Empty when valid, else the problem.
  std::string Check() const;
};

class Target {
 public:
  // `shape` in the input frame; no faces means a point cloud (normals: given, or estimated).
  Target(Mesh shape, Positions<double> cloud_normals, const TargetOptions& options);
  Target(const Target&) = delete;
  Target& operator=(const Target&) = delete;

  const Mesh& shape() const { return shape_; }
  bool is_cloud() const { return shape_.faces.empty(); }
  const Vec3d& centre() const { return centre_; }
  double scale() const { return scale_; }
  // #N samples and unit normals (input frame), in random order (so a prefix is a fair sample);
  // for a mesh the normals are oriented outward as the faces' winding, for a cloud as given or
  // estimated (io/read_input).
  const Positions<double>& points() const { return points_; }
  const Positions<double>& normals() const { return normals_; }
  const PointTree& tree() const { return *tree_; }
  // For a cloud, the surface its points and normals sample (core/cloud_surface.h); else null.
  const CloudSurface* cloud_surface() const { return cloud_surface_.get(); }

 private:
  Mesh shape_;
  Vec3d centre_;
  double scale_;
  Positions<double> points_;
  Positions<double> normals_;
  std::unique_ptr<PointTree> tree_;
  std::unique_ptr<CloudSurface> cloud_surface_;  // over points_ and normals_, built once
};

// The metrics of `output` against the target: its mesh, or the surface its cloud samples (the
// cloud's points and normals: core/cloud_surface.h), so a fit to a cloud is judged without the
// cloud's sampling floor.
ShapeMetrics ComputeTargetMetrics(const Mesh& output, const Target& target, const MetricsOptions& options);

// Loads `path` with ReadInput. Throws std::runtime_error with a one-line message naming the
// problem.
std::unique_ptr<Target> LoadTarget(const std::string& path, const TargetOptions& options);

}  // namespace opgraph
