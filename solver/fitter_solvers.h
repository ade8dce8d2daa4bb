// The fitter's own optimizers over an Objective (solver/objective.h), beside its Ceres solve:
// Levenberg-Marquardt on dense normal equations (solver/dense_lm.h) and Adam. Both move only
// the free Program columns, within their bounds, and leave the program evaluated at the result.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/deadline.h"
#include "program/program.h"
#include "solver/dense_lm.h"
#include "solver/objective.h"

namespace opgraph {

// The Program columns a solve moves: their values' addresses and bounds.
struct FreeColumns {
  std::vector<int> index;         // per Program column: its place among the free ones, or -1
  std::vector<double*> address;   // per free column
  Eigen::VectorXd lower, upper;   // per free column (infinite for gates and branch logits)

  int size() const { return static_cast<int>(address.size()); }
  Eigen::VectorXd Values() const;
  void Set(const Eigen::VectorXd& values) const;
};

// Levenberg-Marquardt from the current values; `options.initial_radius` is the trust region
// to start from. Returns the loss at the result.
double SolveWithDenseLm(Program* program, const Objective& objective, const FreeColumns& columns,
                        const DenseLmOptions& options, DenseLmSummary* summary, ObjectiveScratch* scratch);

// `steps` Adam steps (bias-corrected, the step clamped into the bounds), stopping early at the
// deadline; counts the steps into *steps_taken. Returns the loss at the result.
double SolveWithAdam(Program* program, const Objective& objective, const FreeColumns& columns, int steps,
                     double learning_rate, const Deadline& deadline, int* steps_taken, ObjectiveScratch* scratch);

}  // namespace opgraph
