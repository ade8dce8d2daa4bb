#include "search/zero_shot.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/priority_tasks.h"
#include "search/finish.h"
#include "search/staged_search.h"

namespace opgraph {

ZeroShotResult StagedSearch::Run() {
  Trial start = FitGlobalAffine();
  if (!start.ok) throw std::runtime_error("the global affine fit failed");
  start = Smoothing(start);
  // A beam over the first decision, which shapes the rest of a staged search most: the best
  // few main forms each get the passes, and the best result after the price of its ops wins.
  // The first branch is the best-scored main form, so a budget that ends early still leaves
  // the greedy search's result.
  const std::vector<Branch> branches = ChooseMainForms(start);
  std::vector<Task> lines;
  for (const Branch& branch : branches) lines.push_back([&branch](StagedSearch* search) { search->Follow(branch.trial); });
  Speculate(lines);
  Trial chosen;
  double chosen_score = kInfinity;
  for (size_t b = 0; b < branches.size(); ++b) {
    if (b > 0 && !evaluator_.InBudget()) break;
    if (branches.size() > 1) {
      evaluator_.Note("beam " + std::to_string(b + 1) + " of " + std::to_string(branches.size()) + ": " +
                      branches[b].name);
    }
    const Trial trial = Follow(branches[b].trial);
    const double score = Score(start, trial);
    if (score < chosen_score) chosen = trial, chosen_score = score;
  }
  if (branches.size() > 1) {
    evaluator_.Note("beam: kept the result with loss " + std::to_string(chosen.loss) + " and " +
                    std::to_string(chosen.layout.NumOps()) + " ops");
  }
  return Finish(&evaluator_, chosen);
}

void StagedSearch::Speculate(const std::vector<Task>& tasks) {
  const int threads = evaluator_.options().num_threads;
  const int count = static_cast<int>(tasks.size());
  if (threads < 2 || count < 2 || !evaluator_.InBudget()) return;
  std::vector<Evaluator> speculators = evaluator_.Speculators(count, threads);
  std::vector<StagedSearch> copies;
  copies.reserve(tasks.size());
  for (Evaluator& speculator : speculators) copies.push_back(StagedSearch(*this, std::move(speculator)));
  // The lines in the order the real run takes them, each at a lower priority than the one
  // before: a later line, whose fits are the likelier to be wasted (the budget may end before
  // it), takes a core mostly when the earlier ones leave it idle. Once no line is left to start,
  // a thread whose line ends helps the lines still running.
  RunInPriorityOrder(
      count, threads, [&](int i) { tasks[i](&copies[i]); }, [&](int i) { copies[i].evaluator_.LendThreads(); });
  for (StagedSearch& copy : copies) evaluator_.Adopt(&copy.evaluator_);
}

Trial StagedSearch::FitGlobalAffine() {
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

Trial StagedSearch::Passes(Trial best) {
  const Stage passes[] = {&StagedSearch::Slab,     &StagedSearch::Profiles, &StagedSearch::LoopMoves,
                          &StagedSearch::Deforms,  &StagedSearch::Ridges,   &StagedSearch::Holes,
                          &StagedSearch::RepeatDetails, &StagedSearch::Booleans, &StagedSearch::Facets,
                          &StagedSearch::Grids,    &StagedSearch::Bevels,   &StagedSearch::Smoothing};
  for (int pass = 0; pass < 3 && evaluator_.InBudget(); ++pass) {
    const double before = best.loss;
    for (const Stage stage : passes) best = (this->*stage)(best);
    if (!(best.loss < before)) break;
  }
  return best;
}

std::vector<StagedSearch::Branch> StagedSearch::ChooseMainForms(const Trial& start) {
  const std::pair<const char*, Stage> stages[] = {{"slab", &StagedSearch::Slab},
                                                  {"body", &StagedSearch::Bodies},
                                                  {"profile", &StagedSearch::Profiles},
                                                  {"deform", &StagedSearch::Deforms},
                                                  {"ridge", &StagedSearch::RidgesWithExtrusions},
                                                  {"hole", &StagedSearch::Holes},
                                                  {"detail", &StagedSearch::RepeatDetails},
                                                  {"bevel", &StagedSearch::Bevels},
                                                  {"mirror", &StagedSearch::Mirror}};
  std::vector<Task> tasks;
  for (const auto& entry : stages) {
    const Stage stage = entry.second;
    tasks.push_back([stage, &start](StagedSearch* search) { (search->*stage)(start); });
  }
  Speculate(tasks);
  std::vector<Branch> candidates = {{start, "the pose alone", start.loss}};
  for (const auto& [name, stage] : stages) {
    if (!evaluator_.InBudget()) break;
    const Trial trial = (this->*stage)(start);
    if (trial.layout.NumOps() == start.layout.NumOps()) continue;  // the stage added nothing
    candidates.push_back({trial, std::string("the ") + name + " stage's result", Score(start, trial)});
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Branch& a, const Branch& b) { return a.score < b.score; });
  candidates.resize(std::min<size_t>(candidates.size(), evaluator_.options().beam_width));
  if (candidates.front().trial.layout.NumOps() != start.layout.NumOps()) {
    evaluator_.Log("main form", start, candidates.front().trial, true, candidates.front().name);
  }
  return candidates;
}

ZeroShotResult RecoverSequence(const Target& target, const ZeroShotOptions& options) {
  const std::string problem = options.Check();
  if (!problem.empty()) throw std::invalid_argument(problem);
  return StagedSearch(target, options).Run();
}

}  // namespace opgraph
