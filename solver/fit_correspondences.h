// The fitter's correspondences at one update: output-to-target samples and each target
// sample's closest point on the output, with the Boolean weight's and a mixed branch's own
// terms (solver/fitter.h describes them). Fixed within a solve, re-estimated between.
#pragma once

#include <cstdint>
#include <vector>

#include "program/program.h"
#include "residuals/correspondence_cost.h"
#include "solver/boolean_weight.h"
#include "solver/fitter.h"
#include "solver/target.h"

namespace opgraph {

// The Boolean weight's terms (solver/boolean_weight.h), when the last op has one: beta's
// block, whether each output-to-target sample lies on the extrusion's faces, and each target
// point's correspondence on the Boolean surface.
struct BooleanWeightTerms {
  int beta_block = -1;
  std::vector<char> on_extrusion;
  std::vector<SurfaceCorrespondence> boolean_to_target, target_to_boolean;
};

// A mixed branch's terms (program/program.h): per option, output-to-target samples of its own
// surface and each target point's closest point on it, every residual scaled by
// sqrt(w_option), so the loss mixes the options' Chamfer terms.
struct MixedBranchTerms {
  int block = -1;
  std::vector<SurfaceCorrespondence> forward, backward;
  std::vector<int> forward_option, backward_option;
  double forward_weight = 0, backward_weight = 0;  // residual multipliers (each option's own count)
};

struct FitCorrespondences {
  std::vector<SurfaceCorrespondence> output_to_target, target_to_output;
  double output_to_target_weight = 0, target_to_output_weight = 0;  // residual multipliers
  BooleanWeightTerms boolean;
  MixedBranchTerms mixed;
};

// Evaluates the program's values and samples `options.num_output_samples` points on its output
// (seeded by `seed`) and the first `options.num_target_samples` target points, pairing each
// with its closest point on the other surface.
void BuildFitCorrespondences(Program* program, const Sequence& sequence, const Target& target,
                             const FitterOptions& options, uint64_t seed, FitCorrespondences* out);

}  // namespace opgraph
