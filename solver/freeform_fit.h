// The free-form stage's fit: per-vertex displacements of a cage, seen through the affine ops
// after it (solver/affine_tail.h), fitted to the target by Chamfer terms (both directions, as
// the fitter's) plus a smoothness prior along the cage's edges. One parameter block of 3 per
// cage vertex and residual blocks that touch only the vertices under their point, so the
// problem stays sparse (SPARSE_NORMAL_CHOLESKY); correspondences re-estimated ICP-style.
#pragma once

#include <cstdint>
#include <string>

#include "core/mesh.h"
#include "residuals/correspondence_cost.h"
#include "solver/affine_tail.h"
#include "solver/target.h"

namespace opgraph {

struct FreeformOptions {
  int num_output_samples = 2000;
  int num_target_samples = 2000;
  int max_outer_iterations = 5;   // correspondence updates
  int max_inner_iterations = 5;   // Levenberg-Marquardt steps per update (the problem is linear in them)
  ChamferMetric metric = ChamferMetric::kPlaneAndPoint;
  // Weight of the mean squared difference of neighbouring displacements (unit box) against the
  // mean squared Chamfer distances: larger keeps the cage smoother.
  double smoothness_weight = 0.005;
  uint64_t seed = 1;
  int num_threads = 1;
  // A cap on the fit's wall time in seconds (0: none), as FitterOptions::max_seconds.
  double max_seconds = 0;
  // Empty when valid, else the problem.
  std::string Check() const;
};

struct FreeformResult {
  Positions<double> displacements;  // #V, in the cage's frame
  double initial_loss = 0;          // data loss at zero displacement
  double final_loss = 0;            // data loss at the displacements (same definition as the fitter's)
};

// Displacements of `cage` (#V) whose output through `tail` fits `target`.
FreeformResult FitDisplacements(const Target& target, const Mesh& cage, const AffineTail& tail,
                                const FreeformOptions& options);

}  // namespace opgraph
