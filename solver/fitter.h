// Fits every continuous parameter (and optionally the gates) of a sequence skeleton to a
// target: Chamfer residuals with correspondences fixed inside each solve (Levenberg-Marquardt,
// or Adam over exactly the same objective and gradients), re-estimated in an outer ICP loop
// until the loss stops improving. The loss: sum over residuals of rho(r^2), which without a
// robust loss is the mean squared distance (target's unit box) of each direction, weighted and
// summed, plus the gate and domain-rule penalties.
//
// With fit_gates the fit runs in stages: (1) the parameters with the gates held, (2) the gates
// under the gate sparsity weight with the parameters held, (3) finalisation: ops whose gate
// fell below prune_gate are removed, the other free gates are folded into their op's
// parameters (p <- identity + g (p - identity), which is each op's gate blend) and set to 1,
// and a last solve polishes the parameters with gates fixed, so the result is exportable to
// Blender.
//
// Branch choices (options.branches; program.h): a discrete field of an op fitted by softmax
// weights over its options, alongside the parameters in the first stage (while they are
// active the topology is not re-resolved: the blend is no single written sequence). After it
// the most weighted option is written into the op (CommitBranches) and the rest of the fit
// (gate stage, finalisation, or a polishing solve) runs on the sequence as written.
//
// Boolean weight (options.boolean_weight_ops; solver/boolean_weight.h): the last op, an
// Extrude, gets beta = sigmoid(logit), fitted with the parameters; its extrusion's residuals
// are scaled by sqrt(1 - beta) and each target point's term mixes its distances to the
// extruded and to the Boolean surface. FitSummary::boolean_weights reports beta; the Extrude
// stays in the sequence (ExtrudeToBoolean converts it, for a controller to apply once).
//
// Discrete choices are made by the topology passes at the start parameters and re-made at each
// correspondence update when the parameters have moved them (a Boolean's intersection, the
// elements a geometric target selects); the result is the best parameter set at which the
// written sequence evaluates, when there is one.
//
// Deterministic for a given seed (single-threaded residual evaluation by default).
#pragma once

#include <cstdint>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <ceres/problem.h>

#include "core/deadline.h"
#include "residuals/correspondence_cost.h"
#include "program/program.h"
#include "solver/target.h"

namespace opgraph {

enum class RobustLoss { kNone, kHuber, kCauchy };
// kLm: Levenberg-Marquardt on dense normal equations (solver/dense_lm.h); kCeres: Ceres'
// Levenberg-Marquardt (dense QR) on the same residual blocks; kAdam: Adam on their gradient.
enum class Optimizer { kLm, kCeres, kAdam };

struct FitterOptions {
  Optimizer optimizer = Optimizer::kLm;
  int num_output_samples = 3000;  // output-to-target samples per correspondence update
  int num_target_samples = 3000;  // target-to-output samples (the first of the target's samples)
  double output_to_target_weight = 1.0;
  double target_to_output_weight = 1.0;
  ChamferMetric metric = ChamferMetric::kPointToPlane;
  RobustLoss loss = RobustLoss::kNone;
  double loss_scale = 0.02;  // robust loss scale, unit-box units
  bool fit_gates = false;
  double gate_sparsity_weight = 1e-4;  // stage 2: adds weight * g^2 per free gate to the loss
  double prune_gate = 0.5;
  int max_outer_iterations = 40;    // correspondence updates per stage (stops earlier on stagnation)
  int max_inner_iterations = 5;     // LM iterations per solve (short: correspondences go stale)
  double initial_trust_region_radius = 1e-2;  // LM's first; later solves continue from the last
  int adam_iterations = 150;        // Adam steps per solve
  double adam_learning_rate = 0.01;
  double min_relative_improvement = 1e-3;  // an update improving less than this has stalled
  // Stalled updates in a row a stage carries on through (from where the last solve ended; the
  // best point is kept) before it stops: the loss with fresh correspondences is noisy at the
  // percent level, so one update that does not improve it does not mean the fit has converged.
  int max_stalled_updates = 2;
  int num_threads = 1;
  uint64_t seed = 1;
  std::vector<ParameterRangeRule> domain_rules;
  // Discrete choices fitted by softmax branch weights (program.h): options of equal topology
  // blend positions; options of different topology (last op only) mix their Chamfer terms.
  std::vector<BranchChoice> branches;
  // Extrude ops given the Boolean weight beta (only the last op; solver/boolean_weight.h).
  std::vector<int> boolean_weight_ops;
  std::ostream* progress = nullptr;  // one line per solve when set
  // A cap on Fit()'s wall time in seconds (0: none, the default: then the result does not
  // depend on time). At the cap the correspondence updates stop and the solve under way is cut
  // (Ceres' max_solver_time_in_seconds); the best parameters so far are kept.
  double max_seconds = 0;
  // Empty when valid, else the problem.
  std::string Check() const;
};

struct FitSummary {
  double initial_loss = 0;  // data loss at the start (mean squared distances, unit box, summed)
  double final_loss = 0;
  int outer_iterations = 0;
  int inner_iterations = 0;      // LM iterations or Adam steps
  int jacobian_evaluations = 0;
  // The program's size at the end (a Jacobian evaluation's cost grows with both).
  int num_parameters = 0;  // columns
  int num_vertices = 0;    // of the output
  double seconds = 0;
  bool cut_by_time = false;  // FitterOptions::max_seconds ended the fit early
  std::vector<double> gates_before_finalisation;  // per op of the input sequence
  std::vector<int> pruned_ops;                    // indices in the input sequence
  // Per branch choice (options.branches order): the weights when committed, and the option
  // chosen (their argmax).
  std::vector<std::vector<double>> branch_weights;
  std::vector<int> branch_choices;
  // Per boolean_weight_ops entry: beta after the parameter stage.
  std::vector<double> boolean_weights;
  // The loss with fresh correspondences (a function of the parameters only, so comparable
  // across optimizers) at each correspondence update and at the end.
  struct Point {
    double seconds;   // since Fit() started
    int iterations;   // inner iterations so far
    double loss;
    // The sequence as written rebuilds the program here (its targets select what the program
    // was built with), so a fit may return this point; a stage may pass through points that
    // it may not. The final point: the last stage's result.
    bool reproducible;
  };
  std::vector<Point> history;
};

struct Objective;         // residual blocks at fixed correspondences (solver/objective.h)
struct ObjectiveScratch;  // its evaluation buffers
struct FreeColumns;       // the columns a solve moves (solver/fitter_solvers.h)
struct FitCorrespondences;  // solver/fit_correspondences.h
class FreshPoints;          // solver/fresh_points.h

class Fitter {
 public:
  // Prepares the sequence's topology at its current parameters (discrete choices fixed).
  // Throws SequenceError like EvaluateSequence; std::invalid_argument on bad options.
  Fitter(const Target& target, Sequence* sequence, const FitterOptions& options);
  ~Fitter();

  // The program being fitted (its blocks alias the sequence's op parameters, so a caller may
  // set start values after construction without changing the discrete choices).
  Program& program() { return *program_; }

  // Fits in place. The sequence afterwards holds the fitted parameters and gates (pruned ops
  // removed when fitting gates).
  FitSummary Fit();

  // Data loss at the current parameters with fresh correspondences.
  double CurrentLoss();

  // The objective at one point, for checking that every optimizer sees the same one.
  struct ObjectiveEvaluation {
    double loss = 0;
    std::vector<double> gradient;  // per Program column (Ceres: per parameter of the blocks it varies)
    Eigen::MatrixXd jtj;           // Gauss-Newton J^T J of the (robust-corrected) residuals
    Eigen::VectorXd jtr;           // J^T r (own evaluation only; the gradient is 2 J^T r)
  };
  // At the current parameters and fresh correspondences: the objective as the fitter's own
  // optimizers evaluate it (EvaluateObjective, EvaluateNormalEquations over the free columns),
  // and as Ceres does (Problem::Evaluate over the same residual blocks: 2 x its cost and
  // gradient, and J^T J of its Jacobian).
  void EvaluateBothWays(ObjectiveEvaluation* own, ObjectiveEvaluation* ceres);

 private:
  // The objective's residual blocks over the program's parameter blocks (held ones constant).
  std::unique_ptr<ceres::Problem> MakeCeresProblem(const Objective& objective) const;
  // Whether the solver holds `block` constant: fixed by the program, held in this stage, or
  // belonging to a pinned op.
  bool Held(const ProgramBlock& block) const;
  void BuildCorrespondences(uint64_t seed, FitCorrespondences* out);
  // The residual blocks at fixed correspondences (the current stage's sparsity weight).
  void MakeObjective(const FitCorrespondences& correspondences, Objective* objective) const;
  double RunStage(double sparsity_weight, FitSummary* summary);
  // Every program block's values, in block order.
  std::vector<double> BlockValues() const;
  double Solve(const FitCorrespondences& correspondences, double sparsity_weight, FitSummary* summary);
  double SolveWithCeres(const Objective& objective, FitSummary* summary);
  // The Program columns the current stage moves (not held, not constant within a block).
  FreeColumns FindFreeColumns() const;
  void Finalise(FitSummary* summary);
  // Writes the branch choices' argmax into the sequence and rebuilds the program without them.
  // Returns whether there were any.
  bool CommitBranches(FitSummary* summary);
  // Whether the sequence as it would be written (re-parsed, topology passes re-run) rebuilds
  // the program's current output, gives another topology or output, or fails to evaluate.
  enum class Reproduction { kSame, kDifferent, kFails };
  Reproduction CheckReproduction() const;
  // Rebuilds the program when the topology passes now resolve differently. Returns whether the
  // program then matches the sequence (false: the sequence does not evaluate here).
  bool ResolveTopology();
  // A program without branches over the sequence as it now stands, with the replaced one's
  // gates and Boolean weights exactly.
  void RebuildProgram();

  const Target& target_;
  Sequence* sequence_;
  FitterOptions options_;
  std::unique_ptr<Program> program_;
  std::unique_ptr<ObjectiveScratch> scratch_;
  int program_generation_ = 0;  // counts the programs built (a new one may have another topology)
  std::unique_ptr<FreshPoints> fresh_points_;
  double sparsity_weight_ = 0;
  double trust_region_radius_ = 0;
  bool hold_params_ = false, hold_gates_ = false;  // blocks held constant in the current stage
  bool free_gates_ = false;
  std::vector<int> boolean_weight_ops_;  // cleared when the gate finalisation renumbers ops
  int retired_jacobian_evaluations_ = 0;  // by programs replaced during the fit
  uint64_t update_count_ = 0;
  bool stage_result_reproducible_ = true;  // the last RunStage's result (FitSummary::Point)
  double start_time_ = 0;
  Deadline deadline_;  // FitterOptions::max_seconds from Fit()'s start
};

// Runs Fitter(target, sequence, options).Fit().
FitSummary FitSequence(const Target& target, Sequence* sequence, const FitterOptions& options);

}  // namespace opgraph
