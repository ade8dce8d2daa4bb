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

#include <chrono>
#include <cstdint>
#include <optional>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "ops/limits.h"
#include "ops/params.h"
#include "residuals/correspondence_cost.h"
#include "solver/fitter.h"
#include "solver/target.h"

namespace opgraph {

// Where a search stands, for a progress display (and a caller's cancel).
struct SearchProgress {
  std::string stage;    // "search" while proposals are fitted, then "finish: <step>"
  double fraction = 0;  // of the run done, in [0, 1]: the search's work budget, then steps
  double seconds = 0;   // wall time so far
  int ops = 0;          // of the best sequence so far
  double loss = 0;      // its data loss (unit box, mean squared, both directions)
  std::string line;     // the decision just taken (as in `decisions`), or empty
};
// Called after every batch of fits and every decision; returning false cancels the search
// (the best sequence so far is finished and returned).
using ProgressCallback = std::function<bool(const SearchProgress&)>;

// How the search ended.
enum class SearchEnd { kComplete, kWorkBudget, kTimeBudget, kCancelled };
const char* SearchEndName(SearchEnd end);

struct ZeroShotOptions {
  // The budget in work: Jacobian evaluations of the fitted programs times the parameters they
  // differentiate and a size factor, summed over every fit (about 140 us a unit here with the dense LM;
  // docs/zero-shot.md). Proposals stop at 65% of it; the finishing steps follow. Work does not
  // depend on the machine, its load or the thread count, so a seed gives the same result
  // everywhere.
  int64_t work_budget = 500000;
  // A cap on wall time, in seconds (0: none). When the cap ends the search before the work
  // budget, the result depends on the machine's speed and load (metrics.json says which ended it).
  double time_budget_seconds = 0;
  // When the cap's clock started (unset: when the search starts). A tool passes its own start,
  // so reading the target counts too and the whole run ends within the cap.
  std::optional<std::chrono::steady_clock::time_point> time_budget_start;
  int max_ops = 24;
  // The most faces a step may have (Sequence::max_faces): a layout beyond it is not fitted.
  int64_t max_faces = kDefaultMaxFaces;
  // A proposal must lower the loss by this fraction per op it adds (fit_sequence --op-price;
  // chosen on the tuning splits among 0.08 to 0.35: docs/zero-shot.md, "The op price").
  double min_relative_gain = 0.2;
  // Main forms (the first decision) the passes run from; the best result wins (1: greedy).
  int beam_width = 3;
  uint64_t seed = 1;
  // Independent candidate fits run on this many threads; each fit runs on one (so the result
  // is the same for every thread count).
  int num_threads = 1;
  Optimizer optimizer = Optimizer::kLm;
  // The fits' residuals. Point-to-plane alone lets a cage leave parts of the target uncovered
  // (house: Chamfer 0.039 vs 0.014 with both; docs/zero-shot.md).
  ChamferMetric metric = ChamferMetric::kPlaneAndPoint;
  // Free-form detail last (search/freeform.h): per-vertex displacements of the cage when they
  // lower the Chamfer distance by more than their price.
  bool freeform = true;
  std::ostream* progress = nullptr;  // one line per decision when set
  ProgressCallback on_progress;      // structured progress, may cancel; optional
  // Empty when valid, else the problem.
  std::string Check() const;
};

// One fit's work (ZeroShotOptions::work_budget's unit) and the wall time it took.
struct FitCost {
  int64_t work = 0;
  double seconds = 0;
};

struct ZeroShotResult {
  Json sequence;         // the recovered sequence document (sequence.json)
  double loss = 0;       // final data loss (unit box, mean squared, both directions)
  int num_fits = 0;      // Ceres (or Adam) fits run
  // Of them, those fitted ahead on idle threads (prefetched rounds, speculated lines of search)
  // and taken when the search asked for them; 0 with one thread.
  int num_fits_ahead = 0;
  int64_t work = 0;      // the work of all fits (the work budget's unit)
  std::vector<FitCost> fit_costs;  // per fit, in the order the search used them
  double seconds = 0;
  std::vector<std::string> decisions;  // one line per accepted or rejected proposal
  SearchEnd end = SearchEnd::kComplete;
  bool search_complete = true;         // every proposal was tried (end == kComplete)
  bool freeform = false;               // whether free-form displacements were kept
  // The finishing steps the time cap cut or skipped ("gate fit", "polish", "simplify",
  // "freeform"), in order; empty without a cap.
  std::vector<std::string> cut_by_time;
};

// How well work tracks wall time over `costs` (fits of at least 1 ms): the mean time of a work
// unit, and the 10th and 90th percentiles of each fit's time per unit over that mean.
struct FitCostSummary {
  int fits = 0;
  double microseconds_per_unit = 0;
  double ratio_p10 = 0, ratio_p90 = 0;
};
FitCostSummary SummariseFitCosts(const std::vector<FitCost>& costs);

// Recovers a sequence for `target`. Deterministic for a given seed and work budget, whatever
// the thread count and the machine's load, unless the time cap or a cancel ends the search.
ZeroShotResult RecoverSequence(const Target& target, const ZeroShotOptions& options);

}  // namespace opgraph
