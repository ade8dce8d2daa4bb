// The search's access to the fitter: fits a layout to the target (each document fitted once,
// later requests answered from a cache keyed by the document), keeps the time budget, counts
// fits and records the decision log.
#pragma once

#include <chrono>
#include <map>
#include <string>
#include <vector>

#include "search/layout.h"
#include "search/zero_shot.h"
#include "solver/fitter.h"
#include "solver/target.h"

namespace opgraph {

enum class FitPrecision { kSearch, kFinal };

class Evaluator {
 public:
  Evaluator(const Target& target, const ZeroShotOptions& options);

  // `layout` fitted to the target. Not ok when the layout has more ops than allowed, the fit
  // fails with an engine error (logged), or the fitted sequence would not replay (its
  // selectors re-resolve at the fitted parameters, ops/replay_guards.h).
  Trial Fit(const Layout& layout, FitPrecision precision = FitPrecision::kSearch);
  // The finishing gate fit of `sequence` (parsed from `document`): op gates fitted with the
  // sparsity stage, ops below the threshold pruned. Throws the fitter's errors.
  FitSummary FitGates(Sequence* sequence, const Json& document, double min_half_extent);
  // The fitter options of `precision`, with the domain rules of `document`.
  FitterOptions FitOptions(FitPrecision precision, const Json& document, double min_half_extent) const;

  // Proposals stop at this share of the budget; the finishing fits (gate pruning, polishing,
  // simplification: 20-40 s on a 20-op sequence) take the rest.
  static constexpr double kSearchShare = 0.65;
  bool InBudget() const;
  double Seconds() const;
  bool budget_ended_search() const { return budget_ended_search_; }

  // A decision line: "[zero-shot] stage: what: loss a -> b accepted (n ops, k fits, t s)".
  void Log(const std::string& stage, const Trial& before, const Trial& after, bool accepted, const std::string& what);
  void Note(const std::string& line);  // a line as given, prefixed with "[zero-shot] "

  const Target& target() const { return target_; }
  const ZeroShotOptions& options() const { return options_; }
  int num_fits() const { return num_fits_; }
  const std::vector<std::string>& decisions() const { return decisions_; }

 private:
  const Target& target_;
  ZeroShotOptions options_;
  FitterOptions search_options_, final_options_;
  std::chrono::steady_clock::time_point start_;
  std::map<std::string, Trial> cache_;
  mutable bool budget_ended_search_ = false;  // a proposal was skipped for lack of time
  int num_fits_ = 0;
  std::vector<std::string> decisions_;
};

}  // namespace opgraph
