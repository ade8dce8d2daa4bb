// Free-form detail last (the paper's VertexDisplace as a final stage): per-vertex displacements
// of the finished sequence's cage, before its final Subdivision and pose, with every earlier op
// held. It lets scans and characters reach the target where no structured op explains the
// detail; priced so that structured ops win wherever they explain the shape.
#pragma once

#include "ops/params.h"
#include "search/evaluator.h"

namespace opgraph {

struct FreeformOutcome {
  Json document;         // the document with the displacements, or the input when not kept
  bool used = false;     // whether the displacements were kept
  double loss = 0;       // the free-form fit's data loss when used
};

// Fits displacements of the cage of `document` (the step before its trailing Subdivision and
// global affine ops), on the cage as it is and refined by one Subdivision level first, and
// keeps the better when it lowers the Chamfer distance by more than the price of a free-form
// stage and the result replays. The decision is logged.
FreeformOutcome AddFreeformDetail(Evaluator* evaluator, const Json& document);

}  // namespace opgraph
