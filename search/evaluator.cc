#include "search/evaluator.h"

#include <cmath>
#include <ostream>
#include <sstream>

#include "ops/replay_guards.h"
#include "ops/sequence.h"
#include "search/domain_rules.h"

namespace opgraph {

Evaluator::Evaluator(const Target& target, const ZeroShotOptions& options)
    : target_(target), options_(options), start_(std::chrono::steady_clock::now()) {
  search_options_.seed = options.seed;
  search_options_.num_threads = options.num_threads;
  search_options_.optimizer = options.optimizer;
  search_options_.metric = options.metric;
  search_options_.num_output_samples = 1500;
  search_options_.num_target_samples = 1500;
  search_options_.max_outer_iterations = 8;
  search_options_.max_inner_iterations = 20;
  final_options_ = search_options_;
  final_options_.num_output_samples = 4000;
  final_options_.num_target_samples = 4000;
  final_options_.max_outer_iterations = 15;
  final_options_.max_inner_iterations = 30;
}

FitterOptions Evaluator::FitOptions(FitPrecision precision, const Json& document, double min_half_extent) const {
  return WithDomainRules(precision == FitPrecision::kSearch ? search_options_ : final_options_, document,
                         min_half_extent);
}

Trial Evaluator::Fit(const Layout& layout, FitPrecision precision) {
  Trial trial;
  trial.layout = layout;
  if (layout.NumOps() > options_.max_ops) return trial;
  const Json document = layout.Document();
  const std::string key = (precision == FitPrecision::kSearch ? "s" : "f") + document.dump();
  if (const auto cached = cache_.find(key); cached != cache_.end()) return cached->second;
  try {
    Sequence sequence = ParseSequence(document);
    const FitSummary summary =
        FitSequence(target_, &sequence, FitOptions(precision, document, layout.half_extent.minCoeff()));
    ++num_fits_;
    trial.layout = layout.WithParameters(SequenceToJson(sequence));
    Sequence replay = ParseSequence(trial.layout.Document());
    trial.loss = summary.final_loss;
    const std::vector<Mesh> steps = EvaluateSequence(&replay);
    trial.ok = std::isfinite(trial.loss) && !BreaksReplay(document, steps);
  } catch (const std::runtime_error& error) {
    // The engine's errors: a proposal whose targets vanish or whose fit fails is rejected.
    Note(std::string("fit failed: ") + error.what());
    trial.ok = false;
  }
  cache_.emplace(key, trial);
  return trial;
}

FitSummary Evaluator::FitGates(Sequence* sequence, const Json& document, double min_half_extent) {
  FitterOptions options = FitOptions(FitPrecision::kFinal, document, min_half_extent);
  options.fit_gates = true;
  const FitSummary summary = FitSequence(target_, sequence, options);
  ++num_fits_;
  return summary;
}

bool Evaluator::InBudget() const {
  const bool in_budget = Seconds() < kSearchShare * options_.time_budget_seconds;
  budget_ended_search_ = budget_ended_search_ || !in_budget;
  return in_budget;
}

double Evaluator::Seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Evaluator::Log(const std::string& stage, const Trial& before, const Trial& after, bool accepted,
                    const std::string& what) {
  std::ostringstream line;
  line.precision(3);
  line << stage << ": " << what << ": loss " << before.loss << " -> "
       << (after.ok ? after.loss : std::numeric_limits<double>::infinity()) << (accepted ? " accepted" : " rejected")
       << " (" << (accepted ? after : before).layout.NumOps() << " ops, " << num_fits_ << " fits, " << std::fixed
       << Seconds() << " s)";
  Note(line.str());
}

void Evaluator::Note(const std::string& line) {
  decisions_.push_back("[zero-shot] " + line);
  if (options_.progress != nullptr) *options_.progress << decisions_.back() << std::endl;
}

}  // namespace opgraph
