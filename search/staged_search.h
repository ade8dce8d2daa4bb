// The staged search behind RecoverSequence (search/zero_shot.h): the order in which proposal
// families are asked, the main-form choice and the lookahead of structures that only pay
// through the extrusions they enable. Its main line is in zero_shot.cc, the stages that grow a
// new start (a slab, a body, a mirrored part, a grid) in staged_growth.cc.
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "search/evaluator.h"
#include "search/pose.h"
#include "search/proposals.h"
#include "search/section_changes.h"
#include "search/zero_shot.h"

namespace opgraph {

class StagedSearch {
 public:
  StagedSearch(const Target& target, const ZeroShotOptions& options) : target_(target), evaluator_(target, options) {}

  ZeroShotResult Run();

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
  void Speculate(const std::vector<Task>& tasks);

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
  // A structure judged with the extrusions it enables (a roof with its bay): alone, the
  // best-fitting structure often bends the cage toward a protrusion, where another, followed by
  // the protrusion's extrusions, is the design. The `followed` alternatives of `rounds` (each
  // applied to `best`) with the lowest loss after their price are followed by their
  // extrusions, and the best line is kept when the extrusions pay for theirs at the usual price
  // and the structure for its at its round's.
  Trial WithExtrusions(const std::string& stage, const Trial& best, const std::vector<Round>& rounds, size_t followed);
  // The ridge main form. (Profiles followed alike, the two best after their price, did not
  // reach a tuning model's waist and boss: the boss pulls the single loop's fit away.)
  Trial RidgesWithExtrusions(Trial best) { return WithExtrusions("ridge", best, ProposeRidges(best.layout), 3); }
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
  Trial Details(Trial best);
  Trial Extrusions(Trial best) {
    const FaceResiduals residuals = ComputeFaceResiduals(target_, best.layout);
    return ConsiderRounds(&evaluator_, "detail", best, ProposeExtrusions(best.layout, residuals));
  }
  Trial RepeatDetails(Trial best);

  // The cube on the target's box, along the coordinate axes (models are often built
  // axis-aligned: kept unless clearly worse) or the principal axes.
  Trial FitGlobalAffine();

  // Stages feed each other (a bend lets a profile help, a profile gives extrusions faces), so
  // they repeat until a whole pass changes nothing.
  // Rounding comes after the extrusions, as a modeller would bevel: a bevel first would round
  // the cage toward a protrusion and split its faces below the extrusions' support.
  Trial Passes(Trial best);

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
  std::vector<Branch> ChooseMainForms(const Trial& start);

  // Loop-cut grids give faces where extrusions can start. Cuts alone do not change the surface,
  // so each grid is judged with the extrusions it enables (one step of lookahead); without any,
  // its loop scales would only be a second profile.
  Trial Grids(Trial best);

  // A slab as the body with the extrusions that grow the rest (a table's legs), judged against
  // the best sequence as a whole. Tried once. The slab is not fitted alone: the rest of the
  // target would pull it back to the bounding box.
  Trial Slab(Trial best);

  // A box body (a limb's trunk, the block of an L): the cube on it, not fitted alone (the rest
  // would pull it back to the box), with the extrusions that grow the rest, judged against the
  // best sequence as a whole. A main form only.
  Trial Bodies(Trial best);

  // A mirrored pair: the part fitted, then its extrusions, judged against the best sequence as
  // a whole. Tried once.
  Trial Mirror(Trial best);

  // Each new start (fitted and smoothed first, or else with an unknown loss so that its first
  // extrusions are taken) with the extrusions it grows, kept when it pays for its ops.
  Trial Grow(const std::string& stage, const Trial& best, const std::vector<Expansion>& starts, bool fit_first);

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

}  // namespace opgraph
