#include "search/finish.h"

#include <limits>
#include <ostream>
#include <sstream>

#include "core/metrics.h"
#include "ops/replay_guards.h"
#include "ops/sequence.h"
#include "search/freeform.h"
#include "search/scale_first.h"

namespace opgraph {
namespace {

// Drops ops the result does not need: each op in turn (last first) is removed when the sequence
// without it still evaluates and its Chamfer distance to the target grows by under 2%.
Json Simplify(Evaluator* evaluator, Json document) {
  MetricsOptions metrics_options;
  metrics_options.num_samples = 3000;
  metrics_options.seed = evaluator->options().seed;
  auto chamfer = [&](const Json& candidate) {
    try {
      Sequence sequence = evaluator->Parse(candidate);
      const Mesh result = EvaluateSequence(&sequence).back();
      return ComputeTargetMetrics(result, evaluator->target(), metrics_options).chamfer.Sum();
    } catch (const std::runtime_error&) {
      return std::numeric_limits<double>::infinity();  // the ops after it need the removed op
    }
  };
  double current = chamfer(document);
  for (int k = static_cast<int>(document["operations"].size()) - 1; k >= 0; --k) {
    if (document["operations"].size() == 1) break;
    if (evaluator->TimeIsUp(Evaluator::kSimplifyShare)) {
      evaluator->NoteCutByTime("simplify", "simplify: stopped by the time budget; ops 0 to " + std::to_string(k) +
                                               " not tried");
      break;
    }
    Json candidate = document;
    const std::string name = candidate["operations"][k]["op"];
    candidate["operations"].erase(static_cast<size_t>(k));
    const double without = chamfer(candidate);
    const bool remove = without <= current * 1.02 + 1e-7;
    // Kept ops are logged too, so a price can be studied from the logs (benchmarks/).
    std::ostringstream line;
    line << "simplify: " << (remove ? "removed" : "kept") << " op " << k << " (" << name << "): Chamfer " << current
         << " -> " << without;
    evaluator->Note(line.str());
    if (remove) {
      document = candidate;
      current = without;
    }
  }
  return document;
}

// The document with the scale moved first (as modellers order it) when it builds the same
// mesh: equal counts and every vertex on one of the original's. (A loop cut's seed edge can be
// another edge of the same ring after the scale, which only reorders the new vertices.)
Json ScaleFirstIfSame(const Json& document, double diagonal) {
  const Json reordered = ScaleFirst(document);
  if (reordered == document) return document;
  try {
    Sequence original_sequence = ParseSequence(document), reordered_sequence = ParseSequence(reordered);
    const Mesh original = EvaluateSequence(&original_sequence).back();
    const Mesh moved = EvaluateSequence(&reordered_sequence).back();
    if (moved.NumVertices() != original.NumVertices() || moved.NumFaces() != original.NumFaces()) return document;
    const double tolerance = 1e-9 * (diagonal + 1.0);
    for (const Vec3d& p : moved.vertices) {
      bool found = false;
      for (const Vec3d& q : original.vertices) {
        if ((p - q).squaredNorm() <= tolerance * tolerance) {
          found = true;
          break;
        }
      }
      if (!found) return document;
    }
    return reordered;
  } catch (const std::runtime_error&) {
    return document;
  }
}

// The searched sequence with its op gates fitted and the ops below the threshold pruned, or,
// when pruning does not pay, polished with more samples; `loss` is set to its loss.
Json PruneOrPolish(Evaluator* evaluator, const Trial& best, double* loss) {
  *loss = best.loss;
  const Json searched = best.layout.Document();
  if (evaluator->TimeIsUp(Evaluator::kFitsShare)) {
    evaluator->NoteCutByTime("gate fit", "prune: skipped with the polishing fit, the time budget is spent");
    return searched;
  }
  Json document = searched;
  try {
    Sequence sequence = evaluator->Parse(searched);
    // The polishing fit, needed when pruning does not pay, is made beside the gate fit.
    FitSummary summary;
    evaluator->Prefetch({best.layout}, FitPrecision::kFinal,
                        [&] { summary = evaluator->FitGates(&sequence, searched, best.layout.half_extent); });
    if (summary.cut_by_time) evaluator->NoteCutByTime("gate fit", "prune: the gate fit was cut by the time budget");
    Json fitted = SequenceToJson(sequence);
    Sequence replay = evaluator->Parse(fitted);
    const std::vector<Mesh> steps = EvaluateSequence(&replay);
    const bool breaks_replay = BreaksReplay(replay, steps);
    // Pruning must not undo what the search paid for.
    if (!breaks_replay && summary.final_loss <= best.loss * (1 + evaluator->options().min_relative_gain)) {
      document = fitted;
      *loss = summary.final_loss;
    }
    std::ostringstream line;
    line << "prune: " << summary.pruned_ops.size() << " op(s) below the gate threshold: loss " << best.loss
         << " -> " << summary.final_loss << (document == fitted ? " accepted" : " rejected");
    evaluator->Note(line.str());
  } catch (const std::runtime_error& e) {
    evaluator->Note(std::string("final gate fit failed, kept the searched sequence: ") + e.what());
  }
  if (document == searched && evaluator->TimeIsUp(Evaluator::kFitsShare)) {
    evaluator->NoteCutByTime("polish", "polish: skipped, the time budget is spent");
  } else if (document == searched) {
    const Trial polished = evaluator->Fit(best.layout, FitPrecision::kFinal);
    if (polished.ok) document = polished.layout.Document(), *loss = polished.loss;
  }
  return document;
}

}  // namespace

ZeroShotResult Finish(Evaluator* evaluator, const Trial& best) {
  evaluator->BeginStage("finish: pruning", Evaluator::kSearchProgress);
  double loss = best.loss;
  Json document = best.layout.Document();
  bool freeform = false;
  // A cancelled search returns its best sequence as it stands.
  if (evaluator->search_end() != SearchEnd::kCancelled) {
    document = PruneOrPolish(evaluator, best, &loss);
    evaluator->BeginStage("finish: simplifying", 0.92);
    document = Simplify(evaluator, document);
    document = ScaleFirstIfSame(document, 2.0 * best.layout.half_extent.norm());
    if (evaluator->options().freeform && evaluator->TimeIsUp(Evaluator::kFreeformShare)) {
      evaluator->NoteCutByTime("freeform", "freeform: skipped, the time budget is spent");
    } else if (evaluator->options().freeform) {
      evaluator->BeginStage("finish: free-form", 0.95);
      const FreeformOutcome outcome = AddFreeformDetail(evaluator, document);
      if (outcome.used) document = outcome.document, loss = outcome.loss, freeform = true;
    }
  }
  ZeroShotResult result;
  result.sequence = document;
  result.loss = loss;
  result.num_fits = evaluator->num_fits();
  result.num_fits_ahead = evaluator->num_fits_ahead();
  result.seconds = evaluator->Seconds();
  result.work = evaluator->work();
  result.fit_costs = evaluator->fit_costs();
  result.end = evaluator->search_end();
  result.search_complete = result.end == SearchEnd::kComplete;
  result.freeform = freeform;
  result.cut_by_time = evaluator->cut_by_time();
  if (!result.search_complete) {
    evaluator->Note(std::string("the ") + SearchEndName(result.end) + " ended the search before every proposal was tried");
  }
  result.decisions = evaluator->decisions();
  std::ostringstream line;
  line << "final: " << document["operations"].size() << " ops, loss " << loss << ", " << result.num_fits << " fits, "
       << result.work << " work";
  evaluator->Note(line.str());
  return result;
}

}  // namespace opgraph
