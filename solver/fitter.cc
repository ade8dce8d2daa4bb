#include "solver/fitter.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <ostream>
#include <stdexcept>

#include "solver/build_fit_objective.h"
#include "solver/fit_correspondences.h"
#include "solver/fitter_solvers.h"
#include "solver/fresh_points.h"

namespace opgraph {

namespace {

double Now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

Fitter::Fitter(const Target& target, Sequence* sequence, const FitterOptions& options)
    : target_(target), sequence_(sequence), options_(options) {
  const std::string problem = options.Check();
  if (!problem.empty()) throw std::invalid_argument("fitter options: " + problem);
  free_gates_ = options.fit_gates;
  boolean_weight_ops_ = options.boolean_weight_ops;
  program_ = std::make_unique<Program>(sequence, free_gates_, options.branches, boolean_weight_ops_);
  scratch_ = std::make_unique<ObjectiveScratch>();
  fresh_points_ = std::make_unique<FreshPoints>();
  trust_region_radius_ = options.initial_trust_region_radius;
}

Fitter::~Fitter() = default;

void Fitter::BuildCorrespondences(uint64_t seed, FitCorrespondences* out) {
  BuildFitCorrespondences(program_.get(), *sequence_, target_, options_, seed, out);
}

void Fitter::MakeObjective(const FitCorrespondences& correspondences, Objective* objective) const {
  BuildFitObjective(*program_, options_, target_.scale(), correspondences, &sparsity_weight_, objective);
}

double Fitter::CurrentLoss() {
  std::vector<double> values = BlockValues();
  if (const FreshPoint* point = fresh_points_->Find(program_generation_, sparsity_weight_, values, sequence_->gates)) {
    return point->loss;
  }
  auto correspondences = std::make_unique<FitCorrespondences>();
  BuildCorrespondences(options_.seed, correspondences.get());
  Objective objective;
  MakeObjective(*correspondences, &objective);
  program_->PrepareForEvaluation(false, true);
  const double loss = EvaluateObjective(*program_, objective, nullptr, scratch_.get());
  fresh_points_->Add(
      {program_generation_, sparsity_weight_, std::move(values), sequence_->gates, loss, std::move(correspondences)});
  return loss;
}

std::vector<double> Fitter::BlockValues() const {
  std::vector<double> values;
  for (const ProgramBlock& b : program_->blocks()) values.insert(values.end(), b.data, b.data + b.size);
  return values;
}

bool Fitter::Held(const ProgramBlock& block) const {
  return static_cast<int>(block.constant.size()) == block.size || (block.is_gate ? hold_gates_ : hold_params_) ||
         sequence_->IsPinned(static_cast<size_t>(block.op));
}

FreeColumns Fitter::FindFreeColumns() const {
  FreeColumns columns;
  columns.index.assign(program_->num_columns(), -1);
  std::vector<double> lower, upper;
  for (const ProgramBlock& block : program_->blocks()) {
    for (int i = 0; i < block.size; ++i) {
      if (Held(block) || std::count(block.constant.begin(), block.constant.end(), i) > 0) continue;
      columns.index[block.column + i] = columns.size();
      columns.address.push_back(block.data + i);
      const bool bounded = block.holds_op_params();
      lower.push_back(bounded ? sequence_->ops[block.op]->specs()[i].lower : -std::numeric_limits<double>::infinity());
      upper.push_back(bounded ? sequence_->ops[block.op]->specs()[i].upper : std::numeric_limits<double>::infinity());
    }
  }
  columns.lower = Eigen::Map<const Eigen::VectorXd>(lower.data(), lower.size());
  columns.upper = Eigen::Map<const Eigen::VectorXd>(upper.data(), upper.size());
  return columns;
}

double Fitter::Solve(const FitCorrespondences& correspondences, double sparsity_weight, FitSummary* summary) {
  sparsity_weight_ = sparsity_weight;
  Objective objective;
  MakeObjective(correspondences, &objective);
  // The trust region carries over between correspondence updates: the first solve starts
  // cautious (large early steps tend to jump between near-equivalent configurations, such as
  // an inset's depth traded for an extrusion's height), later ones where the last ended.
  auto carry_over = [&](double radius) {
    trust_region_radius_ = std::max(options_.initial_trust_region_radius, std::min(1e16, radius));
  };
  switch (options_.optimizer) {
    case Optimizer::kLm: {
      DenseLmOptions lm;
      lm.max_iterations = options_.max_inner_iterations;
      lm.initial_radius = trust_region_radius_;
      lm.deadline = &deadline_;
      DenseLmSummary lm_summary;
      const double loss = SolveWithDenseLm(program_.get(), objective, FindFreeColumns(), lm, &lm_summary, scratch_.get());
      summary->inner_iterations += lm_summary.iterations;
      carry_over(lm_summary.radius);
      return loss;
    }
    case Optimizer::kCeres:
      return SolveWithCeres(objective, summary);
    case Optimizer::kAdam:
      break;
  }
  return SolveWithAdam(program_.get(), objective, FindFreeColumns(), options_.adam_iterations,
                       options_.adam_learning_rate, deadline_, &summary->inner_iterations, scratch_.get());
}

double Fitter::RunStage(double sparsity_weight, FitSummary* summary) {
  sparsity_weight_ = sparsity_weight;
  // The program may be rebuilt (ResolveTopology) with the same block layout, so blocks are
  // looked up afresh.
  auto restore = [&](const std::vector<double>& values) {
    size_t k = 0;
    for (const ProgramBlock& b : program_->blocks()) {
      for (int i = 0; i < b.size; ++i) b.data[i] = values[k++];
    }
  };
  // Start inside the bounds (Ceres needs a feasible start).
  for (const ProgramBlock& b : program_->blocks()) {
    if (!b.holds_op_params()) continue;
    const std::vector<ParamSpec>& specs = sequence_->ops[b.op]->specs();
    for (int i = 0; i < b.size; ++i) b.data[i] = std::min(specs[i].upper, std::max(specs[i].lower, b.data[i]));
  }
  double best = std::numeric_limits<double>::infinity(), best_reproducible = best;
  std::vector<double> best_values = BlockValues(), best_reproducible_values;
  int stalled = 0;
  for (int update = 0; update < options_.max_outer_iterations; ++update) {
    const double started = Now();
    // Discrete choices that depend on the parameters (a Boolean's intersection, the elements a
    // target selects) are re-resolved at each update; where the sequence no longer evaluates,
    // the last topology is kept and the point cannot be the result.
    const bool reproducible = ResolveTopology();
    std::vector<double> values = BlockValues();
    FreshPoint* known = fresh_points_->Find(program_generation_, sparsity_weight, values, sequence_->gates);
    FitCorrespondences correspondences;
    Objective objective;
    double fresh;
    if (known && known->correspondences) {  // CurrentLoss measured this point
      correspondences = std::move(*known->correspondences);
      known->correspondences.reset();
      MakeObjective(correspondences, &objective);
      program_->PrepareForEvaluation(false, true);
      fresh = known->loss;
    } else {
      // The same seed every update: samples move smoothly with the shape, so losses compare.
      BuildCorrespondences(options_.seed, &correspondences);
      MakeObjective(correspondences, &objective);
      program_->PrepareForEvaluation(false, true);
      fresh = EvaluateObjective(*program_, objective, nullptr, scratch_.get());
    }
    summary->history.push_back({Now() - start_time_, summary->inner_iterations, fresh, reproducible});
    stalled = fresh < best * (1 - options_.min_relative_improvement) ? 0 : stalled + 1;
    if (fresh < best) {
      if (!known) fresh_points_->Add({program_generation_, sparsity_weight, values, sequence_->gates, fresh, nullptr});
      best = fresh;
      best_values = std::move(values);
      // The result must be a sequence that, as written, rebuilds the fitted mesh (its
      // geometric targets resolve to the same elements); the path there may pass through
      // parameters where they do not (e.g. from a start where they do not).
      if (fresh < best_reproducible && reproducible) {
        best_reproducible = fresh;
        best_reproducible_values = best_values;
      }
    }
    if (stalled > options_.max_stalled_updates || deadline_.Passed()) break;
    const int iterations_before = summary->inner_iterations;
    const double solved = Solve(correspondences, sparsity_weight, summary);
    ++summary->outer_iterations;
    if (options_.progress) {
      char line[256];
      std::snprintf(line, sizeof(line), "fit: update %d: loss %.4e -> %.4e (%d %s, %.2f s)%s%s\n", update, fresh, solved,
                    summary->inner_iterations - iterations_before,
                    options_.optimizer != Optimizer::kAdam ? "LM iterations" : "Adam steps", Now() - started,
                    sparsity_weight > 0 ? " [gate sparsity]" : "",
                    reproducible ? "" : " [not reproducible: the sequence as written selects otherwise here]");
      *options_.progress << line << std::flush;
    }
  }
  if (best_reproducible > best && !best_reproducible_values.empty()) {
    if (options_.progress) {
      *options_.progress << "fit: the best parameters (loss " << best << ") would change what the sequence's targets "
                         << "select; keeping the best that do not (loss " << best_reproducible << ")\n";
    }
    best = best_reproducible;
    best_values = best_reproducible_values;
  }
  restore(best_values);
  stage_result_reproducible_ = ResolveTopology();
  program_->PrepareForEvaluation(false, true);
  return best;
}

FitSummary Fitter::Fit() {
  FitSummary summary;
  start_time_ = Now();
  deadline_ = Deadline(options_.max_seconds);
  fresh_points_->Clear();
  retired_jacobian_evaluations_ = -program_->num_jacobian_evaluations();  // count from here
  summary.initial_loss = CurrentLoss();
  if (options_.fit_gates) {
    // Stage 1: parameters with the gates held; stage 2: gates under the sparsity weight with
    // the parameters held (a gate and its op's parameters trade off exactly, so fitting both
    // under the penalty would shrink every gate and inflate the parameters to compensate).
    hold_gates_ = true;
    RunStage(0.0, &summary);
    if (CommitBranches(&summary)) RunStage(0.0, &summary);
    hold_gates_ = false;
    hold_params_ = true;
    RunStage(options_.gate_sparsity_weight, &summary);
    hold_params_ = false;
    for (int op : boolean_weight_ops_) summary.boolean_weights.push_back(program_->BooleanWeight(op));
    boolean_weight_ops_.clear();
    Finalise(&summary);
  } else {
    RunStage(0.0, &summary);
    if (CommitBranches(&summary)) RunStage(0.0, &summary);
    for (int op : boolean_weight_ops_) summary.boolean_weights.push_back(program_->BooleanWeight(op));
    program_->StoreGates();
  }
  sparsity_weight_ = 0;
  summary.final_loss = CurrentLoss();
  summary.history.push_back(
      {Now() - start_time_, summary.inner_iterations, summary.final_loss, stage_result_reproducible_});
  summary.jacobian_evaluations = retired_jacobian_evaluations_ + program_->num_jacobian_evaluations();
  summary.num_parameters = program_->num_columns();
  summary.num_vertices = static_cast<int>(program_->positions().size());
  summary.seconds = Now() - start_time_;
  summary.cut_by_time = deadline_.Passed();
  return summary;
}

FitSummary FitSequence(const Target& target, Sequence* sequence, const FitterOptions& options) {
  Fitter fitter(target, sequence, options);
  return fitter.Fit();
}

}  // namespace opgraph
