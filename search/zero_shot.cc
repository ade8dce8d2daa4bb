#include "search/zero_shot.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "core/parallel_for.h"

#include "search/evaluator.h"
#include "search/finish.h"
#include "search/pose.h"
#include "search/proposals.h"
#include "search/section_changes.h"

namespace opgraph {
namespace {

// The staged search: the order in which proposal families are asked, the main-form choice and
// the lookahead of structures that only pay through the extrusions they enable.
class StagedSearch {
 public:
  StagedSearch(const Target& target, const ZeroShotOptions& options) : target_(target), evaluator_(target, options) {}

  ZeroShotResult Run() {
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

 private:
  using Stage = Trial (StagedSearch::*)(Trial);
  using Task = std::function<void(StagedSearch*)>;

  // A copy of `other` that fits with `evaluator` (a speculator of other's).
  StagedSearch(const StagedSearch& other, Evaluator evaluator)
      : target_(other.target_),
        evaluator_(std::move(evaluator)),
        slab_tried_(other.slab_tried_),
        mirror_tried_(other.mirror_tried_) {}

  // Speculation for idle threads on whole lines of search, which one thread each keeps busy
  // better than the few alternatives of a decision do: each task runs on a copy of the search
  // (the first on the calling thread, reporting progress), and their fits are kept aside; the
  // caller then runs the same tasks for real, one after another, and takes those fits as if it
  // made them then (Evaluator::Adopt). So the result, the log and the work count are a serial
  // search's, for any thread count; only the wall time changes. A line the real run takes
  // further than its copy did (the budget ends elsewhere) fits the rest itself.
  // Lines that reach the same layouts fit them once (Evaluator::FitOnce), so a line often waits
  // on another's fit: each may batch on all the threads, since a waiting thread takes no core.
  void Speculate(const std::vector<Task>& tasks) {
    const int threads = evaluator_.options().num_threads;
    const int count = static_cast<int>(tasks.size());
    if (threads < 2 || count < 2 || !evaluator_.InBudget()) return;
    std::vector<Evaluator> speculators = evaluator_.Speculators(count, threads);
    std::vector<StagedSearch> copies;
    copies.reserve(tasks.size());
    for (Evaluator& speculator : speculators) copies.push_back(StagedSearch(*this, std::move(speculator)));
    // Once no line is left to start, a thread whose line ends helps the lines still running.
    const int workers = std::min(threads, count);
    std::atomic<int> ended{0};
    ParallelFor(count, threads, [&](int i) {
      tasks[i](&copies[i]);
      if (++ended > count - workers) copies[i].evaluator_.LendThreads();
    });
    for (StagedSearch& copy : copies) evaluator_.Adopt(&copy.evaluator_);
  }

  // A beam branch: the passes from its main form, then the pose's ops that it does not need,
  // last, once the structure has taken what it explains.
  Trial Follow(const Trial& main_form) {
    const Trial trial = Passes(main_form);
    return ConsiderRounds(&evaluator_, "pose", trial, ProposePoseDrops(trial.layout));
  }

  Trial Smoothing(Trial best) { return ConsiderRounds(&evaluator_, "smooth", best, ProposeSmoothing(best.layout)); }
  Trial Profiles(Trial best) {
    const Vec3d changes = SectionChanges(LocalSamples(target_, best.layout.world_from_local));
    return Resolution(ConsiderRounds(&evaluator_, "profile", best, ProposeProfiles(best.layout, changes)));
  }
  // The profile's loop count, once a profile or a deformation has made it matter.
  Trial Resolution(Trial best) { return ConsiderRounds(&evaluator_, "resolution", best, ProposeLoopCounts(best.layout)); }
  Trial LoopMoves(Trial best) {
    if (best.layout.profile.empty()) return best;
    const FaceResiduals residuals = ComputeFaceResiduals(target_, best.layout);
    return ConsiderRounds(&evaluator_, "loop", best, ProposeLoopMoves(best.layout, residuals));
  }
  Trial Deforms(Trial best) {
    return Resolution(ConsiderRounds(&evaluator_, "deform", best, ProposeDeforms(best.layout)));
  }
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
  // A cavity is explained by an extrusion in or by a cut through the shape, and whichever is
  // asked first takes the residual the other needs: when a cut pays, both lines (the
  // extrusions; the cut, then the extrusions) are followed and the better after the price of
  // its ops is kept.
  Trial Details(Trial best) {
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
  Trial Extrusions(Trial best) {
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

  // Stages feed each other (a bend lets a profile help, a profile gives extrusions faces), so
  // they repeat until a whole pass changes nothing.
  // Rounding comes after the extrusions, as a modeller would bevel: a bevel first would round
  // the cage toward a protrusion and split its faces below the extrusions' support.
  Trial Passes(Trial best) {
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

  // A trial's loss after the price of the ops it adds to `start` (lower is better).
  double Score(const Trial& start, const Trial& trial) const {
    if (!trial.ok) return kInfinity;
    return trial.loss / Price(evaluator_.options(), trial.layout.NumOps() - start.layout.NumOps());
  }

  struct Branch {
    Trial trial;
    std::string name;
    double score = 0;
  };

  // The first decision shapes the rest of a staged search (a profile accepted for a small gain
  // blocks the extrusion that explains a boss; a small bend blocks a profile), so it is made
  // best-first: every stage runs from the pose (a rounded box is a Bevel of it), each result
  // scored by its loss after the price of its ops. Returns the best `beam_width` of them,
  // best first (the pose itself among them when it scores so).
  std::vector<Branch> ChooseMainForms(const Trial& start) {
    const std::pair<const char*, Stage> stages[] = {
        {"slab", &StagedSearch::Slab},     {"body", &StagedSearch::Bodies}, {"roof", &StagedSearch::Roofs},
        {"profile", &StagedSearch::Profiles},
        {"deform", &StagedSearch::Deforms}, {"ridge", &StagedSearch::Ridges}, {"hole", &StagedSearch::Holes},
        {"detail", &StagedSearch::RepeatDetails}, {"bevel", &StagedSearch::Bevels}, {"mirror", &StagedSearch::Mirror}};
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

  // A box body (a limb's trunk, the block of an L): the cube on it, not fitted alone (the rest
  // would pull it back to the box), with the extrusions that grow the rest, judged against the
  // best sequence as a whole. A main form only.
  Trial Bodies(Trial best) {
    if (!evaluator_.InBudget()) return best;
    return Grow("body", best, ProposeBoxBodies(target_, best.layout), false);
  }

  // A roof on walls: the walls' box with its ridge, fitted first (the roof explains the rest but
  // for what grows from it), then its extrusions, judged against the best sequence as a whole.
  // A main form only.
  Trial Roofs(Trial best) {
    if (!evaluator_.InBudget()) return best;
    return Grow("roof", best, ProposeRoofs(target_, best.layout), true);
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

ZeroShotResult RecoverSequence(const Target& target, const ZeroShotOptions& options) {
  const std::string problem = options.Check();
  if (!problem.empty()) throw std::invalid_argument(problem);
  return StagedSearch(target, options).Run();
}

}  // namespace opgraph
