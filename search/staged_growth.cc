// The stages that grow a new start and the repeated details (search/staged_search.h).
#include <algorithm>
#include <cmath>

#include "search/staged_search.h"

namespace opgraph {

Trial StagedSearch::Details(Trial best) {
  const Trial extruded = Extrusions(best);
  std::vector<ResidualCluster> interior;
  FindResidualClusters(target_, best.layout, &interior);
  Trial cut = ConsiderRounds(&evaluator_, "cut", best, ProposeThroughHoles(best.layout, interior));
  if (cut.layout.NumOps() == best.layout.NumOps()) return extruded;
  cut = Extrusions(cut);
  const bool keep_cut = Score(best, cut) < Score(best, extruded);
  evaluator_.Note(std::string("cut: kept the line ") + (keep_cut ? "with" : "without") + " the cut");
  return keep_cut ? cut : extruded;
}

Trial StagedSearch::RepeatDetails(Trial best) {
  for (int round = 0; round < 6 && evaluator_.InBudget(); ++round) {
    const double before = best.loss;
    best = Details(best);
    if (!(best.loss < before)) break;
  }
  return best;
}

Trial StagedSearch::Grids(Trial best) {
  if (!evaluator_.InBudget()) return best;
  const std::vector<Expansion> grids = ProposeGrids(best.layout);
  const std::vector<Trial> fitted = evaluator_.FitAll(Layouts(grids));
  for (size_t i = 0; i < grids.size(); ++i) {
    const Expansion& grid = grids[i];
    if (!evaluator_.InBudget()) break;
    Trial trial = fitted[i];
    if (!trial.ok) continue;
    evaluator_.Log("grid", best, trial, false, grid.what + " (before its extrusions)");
    const size_t details_before = trial.layout.details.size();
    trial = RepeatDetails(trial);
    const int added = trial.layout.NumOps() - best.layout.NumOps();
    const bool accept = trial.layout.details.size() > details_before &&
                        trial.loss < best.loss * Price(evaluator_.options(), added);
    evaluator_.Log("grid", best, trial, accept, grid.what + " with its extrusions");
    if (accept) best = trial;
  }
  return best;
}

Trial StagedSearch::WithExtrusions(const std::string& stage, const Trial& best, const std::vector<Round>& rounds,
                                   size_t followed) {
  if (!evaluator_.InBudget()) return best;
  std::vector<Layout> structures;
  std::vector<std::string> whats;
  std::vector<double> gains_per_op;
  for (const Round& round : rounds) {
    Alternatives(best.layout, round, &structures, &whats);
    gains_per_op.resize(structures.size(), round.gain_per_op);
  }
  const std::vector<Trial> fitted = evaluator_.FitAll(structures);
  // The structures that explain at least one op's worth of the loss, the lowest loss after
  // the price of their ops first.
  std::vector<size_t> order;
  std::vector<double> scores(fitted.size(), kInfinity);
  for (size_t i = 0; i < fitted.size(); ++i) {
    evaluator_.Log(stage, best, fitted[i], false, whats[i] + " (before its extrusions)");
    if (!fitted[i].ok || !(fitted[i].loss < best.loss * Price(evaluator_.options(), 1))) continue;
    const int ops = fitted[i].layout.NumOps() - best.layout.NumOps();
    scores[i] = fitted[i].loss / Price(evaluator_.options(), ops, gains_per_op[i]);
    order.push_back(i);
  }
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return scores[a] < scores[b]; });
  if (order.size() > followed) order.resize(followed);
  Trial chosen = best;
  double chosen_score = best.loss;
  for (const size_t i : order) {
    if (!evaluator_.InBudget()) break;
    const Trial& structure = fitted[i];
    const int structure_ops = structure.layout.NumOps() - best.layout.NumOps();
    const Trial trial = RepeatDetails(structure);
    const int extrusion_ops = trial.layout.NumOps() - structure.layout.NumOps();
    const double price = Price(evaluator_.options(), structure_ops, gains_per_op[i]) *
                         Price(evaluator_.options(), extrusion_ops);
    const double score = trial.ok ? trial.loss / price : kInfinity;
    const bool accept = score < chosen_score;
    evaluator_.Log(stage, best, trial, accept, whats[i] + " and its extrusions");
    if (accept) chosen = trial, chosen_score = score;
  }
  return chosen;
}

Trial StagedSearch::Slab(Trial best) {
  if (slab_tried_ || !evaluator_.InBudget()) return best;
  slab_tried_ = true;
  return Grow("slab", best, ProposeSlabs(target_, best.layout), false);
}

Trial StagedSearch::Bodies(Trial best) {
  if (!evaluator_.InBudget()) return best;
  return Grow("body", best, ProposeBoxBodies(target_, best.layout), false);
}

Trial StagedSearch::Mirror(Trial best) {
  if (mirror_tried_ || !evaluator_.InBudget()) return best;
  mirror_tried_ = true;
  return Grow("mirror", best, ProposeMirrors(target_, best.layout), true);
}

Trial StagedSearch::Grow(const std::string& stage, const Trial& best, const std::vector<Expansion>& starts, bool fit_first) {
  Trial chosen = best;
  const std::vector<Trial> fitted = fit_first ? evaluator_.FitAll(Layouts(starts)) : std::vector<Trial>();
  for (size_t i = 0; i < starts.size(); ++i) {
    const Expansion& start = starts[i];
    if (!evaluator_.InBudget()) break;
    Trial trial;
    trial.layout = start.layout;
    trial.ok = true;
    if (fit_first) {
      trial = fitted[i];
      if (!trial.ok) continue;
      trial = Smoothing(trial);
    }
    trial = RepeatDetails(trial);
    trial.ok = std::isfinite(trial.loss);
    const int added = trial.layout.NumOps() - chosen.layout.NumOps();
    const bool accept = trial.ok && trial.loss < chosen.loss * Price(evaluator_.options(), added);
    evaluator_.Log(stage, chosen, trial, accept, start.what + " and its extrusions");
    if (accept) chosen = trial;
  }
  return chosen;
}

}  // namespace opgraph
