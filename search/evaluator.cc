#include "search/evaluator.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ostream>
#include <sstream>

#include "core/parallel_for.h"
#include "ops/replay_guards.h"
#include "ops/sequence.h"
#include "search/domain_rules.h"

namespace opgraph {
namespace {

// A fit's work: its Jacobian evaluations, each weighted by the parameters it differentiates
// (forward-mode passes carry one derivative per parameter) and by the output's vertices beyond
// the sampled residuals' share, so that it tracks a fit's time (metrics.json: fit.work_per_time;
// docs/zero-shot.md).
int64_t Work(const FitSummary& summary) {
  const double size = std::max(1, summary.num_parameters) * (1.0 + summary.num_vertices / 2000.0);
  return static_cast<int64_t>(std::ceil(summary.jacobian_evaluations * size));
}

}  // namespace

Evaluator::Evaluator(const Target& target, const ZeroShotOptions& options)
    : target_(target),
      options_(options),
      start_(options.time_budget_start.value_or(std::chrono::steady_clock::now())) {
  search_options_.seed = options.seed;
  // One thread per fit: Ceres' threads sum a cost in an order that depends on scheduling,
  // which would make a fit (and so the search) differ between runs.
  search_options_.num_threads = 1;
  search_options_.optimizer = options.optimizer;
  search_options_.metric = options.metric;
  search_options_.num_output_samples = 1500;
  search_options_.num_target_samples = 1500;
  search_options_.max_outer_iterations = 8;
  search_options_.max_inner_iterations = 20;
  // A search's fits are probes compared at a fixed cost (and its outputs are recorded in
  // docs/results/): they stop at the first stalled update, as before the fitter's default
  // carried on through two.
  search_options_.max_stalled_updates = 0;
  final_options_ = search_options_;
  final_options_.num_output_samples = 4000;
  final_options_.num_target_samples = 4000;
  final_options_.max_outer_iterations = 15;
  final_options_.max_inner_iterations = 30;
}

FitterOptions Evaluator::FitOptions(FitPrecision precision, const Json& document, const Vec3d& half_extent) const {
  FitterOptions options = WithDomainRules(precision == FitPrecision::kSearch ? search_options_ : final_options_,
                                          document, half_extent);
  options.max_seconds = FitMaxSeconds(kFitsShare);
  return options;
}

Sequence Evaluator::Parse(const Json& document) const {
  Sequence sequence = ParseSequence(document);
  sequence.max_faces = options_.max_faces;
  return sequence;
}

// Runs on a worker thread: touches no member that changes during a batch.
Evaluator::Outcome Evaluator::FitUncached(const Layout& layout, FitPrecision precision) const {
  Outcome outcome;
  outcome.trial.layout = layout;
  if (layout.NumOps() > options_.max_ops) return outcome;
  const Json document = layout.Document();
  try {
    Sequence sequence = Parse(document);
    outcome.fitted = true;
    const FitSummary summary =
        FitSequence(target_, &sequence, FitOptions(precision, document, layout.half_extent));
    outcome.work = Work(summary);
    outcome.seconds = summary.seconds;
    outcome.trial.layout = layout.WithParameters(SequenceToJson(sequence));
    Sequence replay = Parse(outcome.trial.layout.Document());
    outcome.trial.loss = summary.final_loss;
    const std::vector<Mesh> steps = EvaluateSequence(&replay);
    outcome.trial.ok = std::isfinite(outcome.trial.loss) && !BreaksReplay(replay, steps);
  } catch (const std::runtime_error& error) {
    // The engine's errors: a proposal whose targets vanish or whose fit fails is rejected.
    outcome.error = error.what();
    outcome.trial.ok = false;
  }
  return outcome;
}

Trial Evaluator::Fit(const Layout& layout, FitPrecision precision) { return FitAll({layout}, precision).front(); }

std::string Evaluator::Key(const Layout& layout, FitPrecision precision) {
  return (precision == FitPrecision::kSearch ? "s" : "f") + layout.Document().dump();
}

bool Evaluator::NeedsFit(const Layout& layout) const {
  const std::string key = Key(layout, FitPrecision::kSearch);
  return cache_.count(key) == 0 && prefetched_.count(key) == 0;
}

std::vector<Trial> Evaluator::FitAll(const std::vector<Layout>& layouts, FitPrecision precision) {
  std::vector<Trial> trials(layouts.size());
  std::vector<std::string> keys(layouts.size());
  std::vector<int> job_of(layouts.size(), -1);
  std::vector<int> jobs;  // indices into `layouts` of the distinct uncached documents
  std::map<std::string, int> job_of_key;
  for (size_t i = 0; i < layouts.size(); ++i) {
    keys[i] = Key(layouts[i], precision);
    if (const auto cached = cache_.find(keys[i]); cached != cache_.end()) {
      trials[i] = cached->second;
    } else if (const auto job = job_of_key.find(keys[i]); job != job_of_key.end()) {
      job_of[i] = job->second;
    } else {
      job_of[i] = job_of_key[keys[i]] = static_cast<int>(jobs.size());
      jobs.push_back(static_cast<int>(i));
    }
  }
  std::vector<Outcome> outcomes(jobs.size());
  std::vector<int> to_fit;
  for (size_t j = 0; j < jobs.size(); ++j) {
    const auto prefetched = prefetched_.find(keys[jobs[j]]);
    if (prefetched == prefetched_.end()) {
      to_fit.push_back(static_cast<int>(j));
    } else {
      outcomes[j] = std::move(prefetched->second);
      prefetched_.erase(prefetched);
      num_fits_ahead_ += outcomes[j].fitted ? 1 : 0;
    }
  }
  const int borrowed = BorrowThreads(static_cast<int>(to_fit.size()) - options_.num_threads);
  ParallelFor(static_cast<int>(to_fit.size()), options_.num_threads + borrowed,
              [&](int f) { outcomes[to_fit[f]] = FitOnce(keys[jobs[to_fit[f]]], layouts[jobs[to_fit[f]]], precision); });
  ReturnThreads(borrowed);
  for (size_t j = 0; j < jobs.size(); ++j) {
    const Outcome& outcome = outcomes[j];
    cache_.emplace(keys[jobs[j]], outcome.trial);
    if (outcome.from_earlier_line) continue;  // the serial run's cache hit: no work, no log
    num_fits_ += outcome.fitted ? 1 : 0;
    work_ += outcome.work;
    if (outcome.fitted) fit_costs_.push_back({outcome.work, outcome.seconds});
    if (!outcome.error.empty()) Note("fit failed: " + outcome.error);
    if (speculative_) speculated_.emplace_back(keys[jobs[j]], outcome);
  }
  if (speculative_) (*line_work_)[line_] = work_ - work_at_start_;
  for (size_t i = 0; i < layouts.size(); ++i) {
    if (job_of[i] >= 0) trials[i] = outcomes[job_of[i]].trial;
  }
  if (!jobs.empty()) Report();
  return trials;
}

FitSummary Evaluator::FitGates(Sequence* sequence, const Json& document, const Vec3d& half_extent) {
  FitterOptions options = FitOptions(FitPrecision::kFinal, document, half_extent);
  options.fit_gates = true;
  const FitSummary summary = FitSequence(target_, sequence, options);
  ++num_fits_;
  work_ += Work(summary);
  fit_costs_.push_back({Work(summary), summary.seconds});
  Report();
  return summary;
}

bool Evaluator::InBudget() const {
  if (search_end_ != SearchEnd::kComplete) return false;
  if (speculative_ && *speculation_cancelled_) cancelled_ = true;
  // A speculator's line runs for real after the lines before it: their work counts too.
  int64_t work = work_;
  for (int line = 0; speculative_ && line < line_; ++line) work += (*line_work_)[line];
  if (cancelled_) {
    search_end_ = SearchEnd::kCancelled;
  } else if (!(static_cast<double>(work) < kSearchShare * static_cast<double>(options_.work_budget))) {
    search_end_ = SearchEnd::kWorkBudget;
  } else if (options_.time_budget_seconds > 0 && !(Seconds() < kSearchShare * options_.time_budget_seconds)) {
    search_end_ = SearchEnd::kTimeBudget;
  }
  return search_end_ == SearchEnd::kComplete;
}

double Evaluator::SecondsLeft(double share) const {
  if (!(options_.time_budget_seconds > 0)) return std::numeric_limits<double>::infinity();
  return std::max(0.0, share * options_.time_budget_seconds - Seconds());
}

double Evaluator::FitMaxSeconds(double share) const {
  return options_.time_budget_seconds > 0 ? std::max(1e-6, SecondsLeft(share)) : 0.0;
}

void Evaluator::NoteCutByTime(const std::string& step, const std::string& line) {
  cut_by_time_.push_back(step);
  Note(line);
}

double Evaluator::Seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Evaluator::Report(const std::string& line) const {
  if (!options_.on_progress) return;
  SearchProgress progress;
  progress.stage = stage_;
  const double search_share = static_cast<double>(work_) / (kSearchShare * static_cast<double>(options_.work_budget));
  progress.fraction = stage_ == "search" ? kSearchProgress * std::min(1.0, search_share) : stage_fraction_;
  progress.seconds = Seconds();
  progress.ops = best_ops_;
  progress.loss = best_loss_;
  progress.line = line;
  if (!options_.on_progress(progress)) {
    cancelled_ = true;
    if (speculative_) *speculation_cancelled_ = true;
  }
}

void Evaluator::Log(const std::string& stage, const Trial& before, const Trial& after, bool accepted,
                    const std::string& what) {
  std::ostringstream line;
  line.precision(3);
  if (accepted && after.ok) best_ops_ = after.layout.NumOps(), best_loss_ = after.loss;
  line << stage << ": " << what << ": loss " << before.loss << " -> "
       << (after.ok ? after.loss : std::numeric_limits<double>::infinity()) << (accepted ? " accepted" : " rejected")
       << " (" << (accepted ? after : before).layout.NumOps() << " ops, " << num_fits_ << " fits, " << work_ << " work)";
  Note(line.str());
}

void Evaluator::Note(const std::string& line) {
  if (speculative_) return Report();
  decisions_.push_back("[zero-shot] " + line);
  if (options_.progress != nullptr) *options_.progress << decisions_.back() << std::endl;
  Report(decisions_.back());
}

}  // namespace opgraph
