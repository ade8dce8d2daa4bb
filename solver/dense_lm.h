// Levenberg-Marquardt on dense normal equations, for least-squares problems of few parameters
// (tens) and many residuals (thousands), as the fitter's are: the problem hands over J^T J and
// J^T r directly (n by n), so a step costs one n by n factorisation, with no residual-block
// bookkeeping, Jacobian matrix or QR of it (Ceres' dense path spends most of a solve there;
// docs/benchmarks.md has the profile).
//
// The strategy is Ceres' Levenberg-Marquardt (trust-region form): Jacobi-scaled normal
// equations, damping diag(J^T J) / radius, the radius grown by 1 / max(1/3, 1 - (2 rho - 1)^3)
// after a step whose actual / predicted reduction rho exceeds min_relative_decrease, and cut by a
// doubling factor otherwise. Box bounds: variables on a bound that the gradient presses against
// are held for the step (the system is solved over the others), then the step is projected onto
// the box and its predicted reduction recomputed for the projected step (no line search).
// Stops at max_iterations trial steps, or when the cost's relative change, the step or the
// projected gradient falls below its tolerance, or at the deadline.
//
// The cost is C(x) = sum of squares (no factor 1/2): its gradient is 2 J^T r and its model
// C + 2 g.d + d^T (J^T J) d.
#pragma once

#include <string>

#include <Eigen/Core>

#include "core/deadline.h"

namespace opgraph {

class DenseLmProblem {
 public:
  virtual ~DenseLmProblem() = default;
  // The cost at x (+inf where the problem cannot be evaluated); with `jtj` (n by n) and `jtr`
  // (n) also the normal equations there. Both are resized by the caller.
  virtual double Evaluate(const Eigen::VectorXd& x, Eigen::MatrixXd* jtj, Eigen::VectorXd* jtr) = 0;
};

struct DenseLmOptions {
  int max_iterations = 5;              // trial steps, accepted or not
  double initial_radius = 1e-2;
  double max_radius = 1e16;
  double min_radius = 1e-32;
  double min_relative_decrease = 1e-3;
  double function_tolerance = 1e-8;    // |Delta C| / C
  double parameter_tolerance = 1e-10;  // |step| / (|x| + parameter_tolerance)
  double gradient_tolerance = 1e-10;   // max |x - P(x - g)|, P the projection onto the box
  const Deadline* deadline = nullptr;  // stops when passed
  // Empty when valid, else the problem.
  std::string Check() const;
};

struct DenseLmSummary {
  double initial_cost = 0;
  double final_cost = 0;
  int iterations = 0;            // trial steps
  int successful_steps = 0;
  int jacobian_evaluations = 0;  // Evaluate() calls with the normal equations
  double radius = 0;             // at the end, to start the next solve from
};

// Minimises problem's cost over x in [lower, upper] (n each) from `x` (clamped into the box
// first); `x` ends at the best point found.
DenseLmSummary MinimizeDenseLm(DenseLmProblem* problem, const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                               const DenseLmOptions& options, Eigen::VectorXd* x);

}  // namespace opgraph
