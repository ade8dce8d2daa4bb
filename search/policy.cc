#include "search/policy.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace opgraph {

double Price(const ZeroShotOptions& options, int added, double gain_per_op) {
  return std::pow(1.0 - std::max(gain_per_op, options.min_relative_gain), added);
}

void Alternatives(const Layout& best, const Round& round, std::vector<Layout>* layouts, std::vector<std::string>* whats) {
  for (const Edit& edit : round.alternatives) {
    Layout layout = best;
    std::string what = edit(&layout);
    if (what.empty()) continue;
    layouts->push_back(std::move(layout));
    if (whats != nullptr) whats->push_back(std::move(what));
  }
}

namespace {

// Rounds are judged one after another, each on the best so far, and most change nothing; so
// while a round has fewer alternatives than there are threads, the next rounds' alternatives on
// the same best are fitted beside them (wasted only when a round is accepted).
void PrefetchAhead(Evaluator* evaluator, const Layout& best, const std::vector<Round>& rounds, size_t first) {
  const int threads = evaluator->Threads();
  if (threads < 2 || !evaluator->InBudget()) return;
  constexpr size_t kMaxRoundsAhead = 8;
  std::vector<Layout> layouts, round_layouts;
  int pending = 0;
  for (size_t r = first; r < rounds.size() && r < first + kMaxRoundsAhead && pending < threads; ++r) {
    round_layouts.clear();
    Alternatives(best, rounds[r], &round_layouts, nullptr);
    for (Layout& layout : round_layouts) {
      if (!evaluator->NeedsFit(layout)) continue;
      layouts.push_back(std::move(layout));
      ++pending;
    }
  }
  if (pending > 1) evaluator->Prefetch(layouts);
}

}  // namespace

Trial ConsiderRound(Evaluator* evaluator, const std::string& stage, const Trial& best, const Round& round) {
  if (!evaluator->InBudget() && (!round.finishing || evaluator->search_end() == SearchEnd::kCancelled)) return best;
  std::vector<Layout> layouts;
  std::vector<std::string> whats;
  Alternatives(best.layout, round, &layouts, &whats);
  // The alternatives are fitted together, then judged in their order.
  const std::vector<Trial> trials = evaluator->FitAll(layouts);
  Trial chosen = best;
  double chosen_score = best.loss;
  std::string chosen_what;
  for (size_t i = 0; i < trials.size(); ++i) {
    const Trial& trial = trials[i];
    const int added = trial.layout.NumOps() - best.layout.NumOps();
    const double score =
        trial.ok ? trial.loss / Price(evaluator->options(), added, round.gain_per_op) : std::numeric_limits<double>::infinity();
    if (score < chosen_score) {
      chosen = trial, chosen_score = score, chosen_what = whats[i];
    } else {
      evaluator->Log(stage, best, trial, false, whats[i]);
    }
  }
  if (!chosen_what.empty()) evaluator->Log(stage, best, chosen, true, chosen_what);
  return chosen;
}

Trial ConsiderRounds(Evaluator* evaluator, const std::string& stage, Trial best, const std::vector<Round>& rounds) {
  for (size_t r = 0; r < rounds.size(); ++r) {
    PrefetchAhead(evaluator, best.layout, rounds, r);
    best = ConsiderRound(evaluator, stage, best, rounds[r]);
  }
  return best;
}

}  // namespace opgraph
