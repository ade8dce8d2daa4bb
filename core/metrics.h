// Shape and wiring metrics, all on the target's unit bounding box (both shapes translated by the
// target box's centre and scaled so its longest side is 1), so numbers compare across models.
//
// Point-to-surface Chamfer: mean distance (and mean squared distance) from seeded area-weighted
// samples of one shape to the other's exact surface, each direction and summed.
// Sample-to-sample Chamfer (as in the paper): both shapes sampled, mean squared distance from
// each sample to the nearest sample of the other set, both directions summed.
// Normal consistency: mean |n_sample . n_closest triangle| over both directions.
// F1 at tau: precision = fraction of output samples within tau of the target surface, recall =
// fraction of target samples within tau of the output surface, F1 = 2PR / (P + R).
// A target without faces (a point cloud) is its own sample set; distances to it are to its
// nearest point (or, given its normals, to the surface it samples: core/cloud_surface.h), and
// its normal consistency is NaN.
#pragma once

#include <cstdint>
#include <string>

#include "core/mesh.h"

namespace opgraph {

class CloudSurface;

struct ChamferDistance {
  double output_to_target = 0;
  double target_to_output = 0;
  double Sum() const { return output_to_target + target_to_output; }
};

struct ShapeMetrics {
  ChamferDistance chamfer;          // point-to-surface, mean distance
  ChamferDistance chamfer_squared;  // point-to-surface, mean squared distance
  double sample_chamfer = 0;        // sample-to-sample, mean squared, summed
  double normal_consistency = 0;    // in [0, 1]; NaN for a point-cloud target
  double f1_001 = 0;                // F1 at 0.01
  double f1_002 = 0;                // F1 at 0.02
};

struct WiringMetrics {
  double valence4_fraction = 0;  // vertices with exactly 4 incident edges / all vertices
  double quad_fraction = 0;      // 4-sided faces / all faces
  double face_area_cv = 0;       // standard deviation / mean of face areas (population)
};

struct MetricsOptions {
  int num_samples = 10000;  // per shape
  uint64_t seed = 1;
  // Empty when valid, else the problem.
  std::string Check() const;
};

// `output` must have faces; `target` may be a point cloud (no faces). Throws
// std::invalid_argument on invalid options.
ShapeMetrics ComputeShapeMetrics(const Mesh& output, const Mesh& target, const MetricsOptions& options = {});
// A point-cloud `target` (no faces) with #V by 3 unit normals: distances to it are to the surface
// it samples (core/cloud_surface.h), so the output-to-target terms have no sampling floor.
ShapeMetrics ComputeShapeMetrics(const Mesh& output, const Mesh& target, const Positions<double>& target_normals,
                                 const MetricsOptions& options = {});
// The same with the surface of the cloud `target` built once by the caller (over target.vertices
// in target's own frame), for callers that measure many outputs against one cloud.
ShapeMetrics ComputeShapeMetrics(const Mesh& output, const Mesh& target, const CloudSurface& target_surface,
                                 const MetricsOptions& options = {});

// The sampling noise floor: the target against an independent resampling of itself
// (sample-to-sample distances; point-to-surface distances of a surface to itself are 0).
// Returns the mean nearest-sample distance, both directions summed (compare with
// ShapeMetrics::chamfer.Sum()).
double SamplingNoiseFloor(const Mesh& target, const MetricsOptions& options = {});

WiringMetrics ComputeWiringMetrics(const Mesh& mesh);

// Centre of the axis-aligned box of `mesh`'s vertices and 1 / its longest side.
void UnitBoxTransform(const Mesh& mesh, Vec3d* centre, double* scale);

}  // namespace opgraph
