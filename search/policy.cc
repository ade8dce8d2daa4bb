#include "search/policy.h"

#include <algorithm>
#include <cmath>

namespace opgraph {

double Price(const ZeroShotOptions& options, int added, double gain_per_op) {
  return std::pow(1.0 - std::max(gain_per_op, options.min_relative_gain), added);
}

Trial ConsiderRound(Evaluator* evaluator, const std::string& stage, const Trial& best, const Round& round) {
  Trial chosen = best;
  double chosen_score = best.loss;
  std::string chosen_what;
  for (const Edit& edit : round.alternatives) {
    if (!evaluator->InBudget()) break;
    Layout layout = best.layout;
    const std::string what = edit(&layout);
    if (what.empty()) continue;
    const Trial trial = evaluator->Fit(layout);
    const int added = layout.NumOps() - best.layout.NumOps();
    const double score =
        trial.ok ? trial.loss / Price(evaluator->options(), added, round.gain_per_op) : std::numeric_limits<double>::infinity();
    if (score < chosen_score) {
      chosen = trial, chosen_score = score, chosen_what = what;
    } else {
      evaluator->Log(stage, best, trial, false, what);
    }
  }
  if (!chosen_what.empty()) evaluator->Log(stage, best, chosen, true, chosen_what);
  return chosen;
}

Trial ConsiderRounds(Evaluator* evaluator, const std::string& stage, Trial best, const std::vector<Round>& rounds) {
  for (const Round& round : rounds) best = ConsiderRound(evaluator, stage, best, round);
  return best;
}

}  // namespace opgraph
