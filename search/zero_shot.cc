#include "search/zero_shot.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "search/evaluator.h"
#include "search/finish.h"
#include "search/pose.h"
#include "search/proposals.h"

namespace opgraph {
namespace {

// The staged search: the order in which proposal families are asked, the main-form choice and
// the lookahead of structures that only pay through the extrusions they enable.
class StagedSearch {
 public:
  StagedSearch(const Target& target, const ZeroShotOptions& options) : target_(target), evaluator_(target, options) {}

  ZeroShotResult Run() {
    Trial best = FitGlobalAffine();
    if (!best.ok) throw std::runtime_error("the global affine fit failed");
    best = Smoothing(best);
    best = ChooseMainForm(best);
    // Stages feed each other (a bend lets a profile help, a profile gives extrusions faces), so
    // they repeat until a whole pass changes nothing.
    // Rounding comes after the extrusions, as a modeller would bevel: a bevel first would round
    // the cage toward a protrusion and split its faces below the extrusions' support.
    const Stage passes[] = {&StagedSearch::Slab,     &StagedSearch::Profiles, &StagedSearch::LoopMoves,
                            &StagedSearch::Deforms,  &StagedSearch::Ridges,   &StagedSearch::Holes,
                            &StagedSearch::RepeatDetails, &StagedSearch::Booleans, &StagedSearch::Facets,
                            &StagedSearch::Grids,    &StagedSearch::Bevels,   &StagedSearch::Smoothing};
    for (int pass = 0; pass < 3 && evaluator_.InBudget(); ++pass) {
      const double before = best.loss;
      for (const Stage stage : passes) best = (this->*stage)(best);
      if (!(best.loss < before)) break;
    }
    // Last, once the structure has taken what it explains.
    best = ConsiderRounds(&evaluator_, "pose", best, ProposePoseDrops(best.layout));
    return Finish(&evaluator_, best);
  }

 private:
  using Stage = Trial (StagedSearch::*)(Trial);

  Trial Smoothing(Trial best) { return ConsiderRounds(&evaluator_, "smooth", best, ProposeSmoothing(best.layout)); }
  Trial Profiles(Trial best) { return ConsiderRounds(&evaluator_, "profile", best, ProposeProfiles(best.layout)); }
  Trial LoopMoves(Trial best) {
    if (best.layout.profile.empty()) return best;
    const FaceResiduals residuals = ComputeFaceResiduals(target_, best.layout);
    return ConsiderRounds(&evaluator_, "loop", best, ProposeLoopMoves(best.layout, residuals));
  }
  Trial Deforms(Trial best) { return ConsiderRounds(&evaluator_, "deform", best, ProposeDeforms(best.layout)); }
  Trial Ridges(Trial best) { return ConsiderRounds(&evaluator_, "ridge", best, ProposeRidges(best.layout)); }
  Trial Holes(Trial best) { return ConsiderRounds(&evaluator_, "hole", best, ProposeHoles(best.layout)); }
  Trial Booleans(Trial best) {
    const std::vector<ResidualCluster> clusters = FindResidualClusters(target_, best.layout);
    return ConsiderRounds(&evaluator_, "boolean", best, ProposeBooleans(best.layout, clusters));
  }
  Trial Facets(Trial best) {
    const FaceResiduals residuals = ComputeFaceResiduals(target_, best.layout);
    return ConsiderRounds(&evaluator_, "facet", best, ProposeFacets(best.layout, residuals));
  }
  Trial Bevels(Trial best) { return ConsiderRounds(&evaluator_, "bevel", best, ProposeBevels(best.layout)); }
  Trial Details(Trial best) {
    const FaceResiduals residuals = ComputeFaceResiduals(target_, best.layout);
    return ConsiderRounds(&evaluator_, "detail", best, ProposeExtrusions(best.layout, residuals));
  }
  Trial RepeatDetails(Trial best) {
    for (int round = 0; round < 6 && evaluator_.InBudget(); ++round) {
      const double before = best.loss;
      best = Details(best);
      if (!(best.loss < before)) break;
    }
    return best;
  }

  // The cube on the target's box, along the coordinate axes (models are often built
  // axis-aligned: kept unless clearly worse) or the principal axes.
  Trial FitGlobalAffine() {
    const std::vector<Trial> poses = evaluator_.FitAll(
        {PoseLayout(target_, Eigen::Matrix3d::Identity()), PoseLayout(target_, PrincipalFrame(target_))});
    const Trial& aligned = poses[0];
    const Trial& rotated = poses[1];
    if (aligned.ok && !(rotated.loss < 0.7 * aligned.loss)) {
      evaluator_.Log("affine", aligned, aligned, true, "Scale, Rotate, Translate (coordinate axes)");
      return aligned;
    }
    evaluator_.Log("affine", rotated, rotated, true, "Scale, Rotate, Translate (principal axes)");
    return rotated;
  }

  // The first decision shapes the rest of a greedy search (a profile accepted for a small gain
  // blocks the extrusion that explains a boss; a small bend blocks a profile), so it is made
  // best-first: every stage runs from the pose (a rounded box is a Bevel of it), and the one
  // with the lowest loss after the price of its ops wins. The passes then add to it in a fixed
  // order.
  Trial ChooseMainForm(const Trial& start) {
    const std::pair<const char*, Stage> stages[] = {
        {"slab", &StagedSearch::Slab},   {"profile", &StagedSearch::Profiles}, {"deform", &StagedSearch::Deforms},
        {"ridge", &StagedSearch::Ridges}, {"hole", &StagedSearch::Holes},       {"detail", &StagedSearch::RepeatDetails},
        {"bevel", &StagedSearch::Bevels},  {"mirror", &StagedSearch::Mirror}};
    Trial chosen = start;
    double chosen_score = start.loss;
    std::string chosen_stage;
    for (const auto& [name, stage] : stages) {
      if (!evaluator_.InBudget()) break;
      const Trial trial = (this->*stage)(start);
      const int added = trial.layout.NumOps() - start.layout.NumOps();
      const double score = trial.ok ? trial.loss / Price(evaluator_.options(), added) : kInfinity;
      if (score < chosen_score) chosen = trial, chosen_score = score, chosen_stage = name;
    }
    if (!chosen_stage.empty()) evaluator_.Log("main form", start, chosen, true, "the " + chosen_stage + " stage's result");
    return chosen;
  }

  // Loop-cut grids give faces where extrusions can start. Cuts alone do not change the surface,
  // so each grid is judged with the extrusions it enables (one step of lookahead); without any,
  // its loop scales would only be a second profile.
  Trial Grids(Trial best) {
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

  // A slab as the body with the extrusions that grow the rest (a table's legs), judged against
  // the best sequence as a whole. Tried once. The slab is not fitted alone: the rest of the
  // target would pull it back to the bounding box.
  Trial Slab(Trial best) {
    if (slab_tried_ || !evaluator_.InBudget()) return best;
    slab_tried_ = true;
    return Grow("slab", best, ProposeSlabs(target_, best.layout), false);
  }

  // A mirrored pair: the part fitted, then its extrusions, judged against the best sequence as
  // a whole. Tried once.
  Trial Mirror(Trial best) {
    if (mirror_tried_ || !evaluator_.InBudget()) return best;
    mirror_tried_ = true;
    return Grow("mirror", best, ProposeMirrors(target_, best.layout), true);
  }

  // Each new start (fitted and smoothed first, or else with an unknown loss so that its first
  // extrusions are taken) with the extrusions it grows, kept when it pays for its ops.
  Trial Grow(const std::string& stage, const Trial& best, const std::vector<Expansion>& starts, bool fit_first) {
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

  static std::vector<Layout> Layouts(const std::vector<Expansion>& expansions) {
    std::vector<Layout> layouts;
    for (const Expansion& expansion : expansions) layouts.push_back(expansion.layout);
    return layouts;
  }

  static constexpr double kInfinity = std::numeric_limits<double>::infinity();
  const Target& target_;
  Evaluator evaluator_;
  bool slab_tried_ = false, mirror_tried_ = false;
};

}  // namespace

FitCostSummary SummariseFitCosts(const std::vector<FitCost>& costs) {
  FitCostSummary summary;
  double work = 0, seconds = 0;
  std::vector<double> per_unit;
  for (const FitCost& cost : costs) {
    if (cost.work <= 0 || cost.seconds < 1e-3) continue;
    work += static_cast<double>(cost.work), seconds += cost.seconds;
    per_unit.push_back(cost.seconds / static_cast<double>(cost.work));
  }
  summary.fits = static_cast<int>(per_unit.size());
  if (per_unit.empty()) return summary;
  const double mean = seconds / work;
  summary.microseconds_per_unit = 1e6 * mean;
  std::sort(per_unit.begin(), per_unit.end());
  auto percentile = [&](double q) { return per_unit[static_cast<size_t>(q * (per_unit.size() - 1))] / mean; };
  summary.ratio_p10 = percentile(0.1), summary.ratio_p90 = percentile(0.9);
  return summary;
}

const char* SearchEndName(SearchEnd end) {
  switch (end) {
    case SearchEnd::kComplete: return "complete";
    case SearchEnd::kWorkBudget: return "work budget";
    case SearchEnd::kTimeBudget: return "time budget";
    case SearchEnd::kCancelled: return "cancelled";
  }
  return "unknown";
}

std::string ZeroShotOptions::Check() const {
  if (work_budget < 1) return "work budget must be positive";
  if (!(time_budget_seconds >= 0)) return "time budget must be positive, or 0 for none";
  if (max_ops < 3) return "max ops must be at least 3";
  if (max_faces < 1 || max_faces > kMaxFacesCeiling) return "max faces must be in [1, " + std::to_string(kMaxFacesCeiling) + "]";
  if (!(min_relative_gain >= 0 && min_relative_gain < 1)) return "min relative gain must be in [0, 1)";
  if (num_threads < 1) return "threads must be at least 1";
  return "";
}

ZeroShotResult RecoverSequence(const Target& target, const ZeroShotOptions& options) {
  const std::string problem = options.Check();
  if (!problem.empty()) throw std::invalid_argument(problem);
  return StagedSearch(target, options).Run();
}

}  // namespace opgraph
