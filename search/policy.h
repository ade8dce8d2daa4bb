// The search's policy: what a change must gain to pay for its ops, and which of several
// alternative changes is kept.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "search/evaluator.h"
#include "search/layout.h"

namespace opgraph {

// A change to a layout; returns what it did ("+Extrude out x4 ..."), or "" when it does not
// apply to this layout (then the layout is not fitted).
using Edit = std::function<std::string(Layout*)>;

// Alternative changes for one decision, priced alike.
struct Round {
  std::vector<Edit> alternatives;
  double gain_per_op = 0;  // the price per added op, when larger than min_relative_gain
  // Fitted also when the search's share of the budget is spent (not when cancelled): a
  // finishing step, paid from the finishing share.
  bool finishing = false;
};

// The factor a loss must fall by to pay for `added` ops (below 1; above 1 when ops are
// removed): `min_relative_gain` per op, or `gain_per_op` when larger.
double Price(const ZeroShotOptions& options, int added, double gain_per_op = 0);

// Special-purpose structures (a hole, a ridge) can also lower the loss a little where the
// target has none, by bending the cage toward it; they must explain a quarter of the loss
// per op they add, and then the general proposals that follow are not blocked by them.
constexpr double kStructureGainPerOp = 0.25;

// Appends the alternatives of `round` that apply to `best` (as layouts), and what each does
// when `whats` is given.
void Alternatives(const Layout& best, const Round& round, std::vector<Layout>* layouts, std::vector<std::string>* whats);

// Fits each alternative of `round` applied to `best` and keeps the one whose loss, divided by
// the price of the ops it adds, is lowest, if that is below the loss of `best` (a change that
// shortens the sequence may cost some loss: the same price per op).
Trial ConsiderRound(Evaluator* evaluator, const std::string& stage, const Trial& best, const Round& round);

// The rounds in order, each on the best so far.
Trial ConsiderRounds(Evaluator* evaluator, const std::string& stage, Trial best, const std::vector<Round>& rounds);

}  // namespace opgraph
