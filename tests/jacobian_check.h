// Residual Jacobians against central finite differences, through the Program's shared
// EvaluationCallback cache (used by the program and Boolean weight tests).
#pragma once

#include <ceres/cost_function.h>

#include <string>
#include <vector>

#include "program/program.h"

namespace opgraph {

// Residuals of `cost` at the program's current parameters (re-evaluated).
std::vector<double> CostResiduals(Program* program, const ceres::CostFunction& cost);

struct JacobianComparison {
  int compared = 0;                      // entries compared (held entries excluded)
  std::vector<int> nonzero_per_block;    // per program block: derivatives above 1e-6
  int nonzero() const;
};

// Compares every entry of `cost`'s Jacobian (all the program's blocks) with central differences
// (step 1e-6 max(1, |x|)) to `tolerance` x max(1, |derivative|); entries a block holds constant
// must be 0. Failures are reported with `what`.
JacobianComparison ExpectJacobianMatchesCentralDifferences(Program* program, const ceres::CostFunction& cost,
                                                           const std::string& what, double tolerance);

}  // namespace opgraph
