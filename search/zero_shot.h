// Zero-shot recovery of a design sequence: the outer combinatorial controller around the
// Ceres fits. It stages discrete decisions (propose, fit, accept or reject, expand), simplest
// first, as a modeller builds (docs/zero-shot.md has the details):
//   1. global affine: a cube scaled, rotated and translated onto the target;
//   2. smoothness: Subdivision (level 2) at the end of the structure, kept if it helps;
//   3. repeated passes of: profiles (LoopCut with loop scales), deformations (SimpleDeform), a
//      ridge (loop cut with raised vertices), holes (Boolean difference), protrusions and
//      cavities (Extrude, or Inset then Extrude, on faces found from the residuals), a
//      loop-cut grid or a slab body with the extrusions they enable, Bevel, Subdivision;
//   4. pruning: op gates fitted with the sparsity stage, ops below the threshold removed, a
//      polishing fit, ops the Chamfer distance does not need dropped, the scale written first.
// A proposal is accepted when the data loss falls by more than `min_relative_gain` per op it
// adds, the price of a longer sequence. During the search ops act in the cube's own frame
// (cube -> loop cuts -> Scale -> ridge -> deformations -> details -> Subdivision -> Rotate ->
// Translate), so element selectors stay valid while the fit moves the global pose
// (search/layout.h). The search's parts: proposal families one a file (search/proposals.h), the
// policy (search/policy.h), the fits (search/evaluator.h), the finishing steps (search/finish.h).
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "ops/params.h"
#include "residuals/correspondence_cost.h"
#include "solver/fitter.h"
#include "solver/target.h"

namespace opgraph {

struct ZeroShotOptions {
  // Total wall time aimed at: proposals stop at 65% of it, the finishing fits take the rest
  // (they are not cut short, so a run can end somewhat past it).
  double time_budget_seconds = 90;
  int max_ops = 24;
  double min_relative_gain = 0.08;  // a proposal must lower the loss by this fraction
  uint64_t seed = 1;
  int num_threads = 1;
  Optimizer optimizer = Optimizer::kCeres;
  // The fits' residuals. Point-to-plane alone lets a cage leave parts of the target uncovered
  // (house: Chamfer 0.039 vs 0.014 with both; docs/zero-shot.md).
  ChamferMetric metric = ChamferMetric::kPlaneAndPoint;
  // Free-form detail last (search/freeform.h): per-vertex displacements of the cage when they
  // lower the Chamfer distance by more than their price.
  bool freeform = true;
  std::ostream* progress = nullptr;  // one line per decision when set
  // Empty when valid, else the problem.
  std::string Check() const;
};

struct ZeroShotResult {
  Json sequence;         // the recovered sequence document (sequence.json)
  double loss = 0;       // final data loss (unit box, mean squared, both directions)
  int num_fits = 0;      // Ceres (or Adam) fits run
  double seconds = 0;
  std::vector<std::string> decisions;  // one line per accepted or rejected proposal
  bool search_complete = true;         // false when the time budget cut proposals short
  bool freeform = false;               // whether free-form displacements were kept
};

// Recovers a sequence for `target`. Deterministic for a given seed.
ZeroShotResult RecoverSequence(const Target& target, const ZeroShotOptions& options);

}  // namespace opgraph
