// The fitter's objective at fixed correspondences (solver/objective.h): the Chamfer terms both
// ways (with the Boolean weight's and a mixed branch's scaling), the gates' sparsity and the
// domain rules, each residual block over the program's parameter blocks.
#pragma once

#include "program/program.h"
#include "solver/fit_correspondences.h"
#include "solver/fitter.h"
#include "solver/objective.h"

namespace opgraph {

// `unit_scale`: the target's scale (its unit box), which the robust loss's scale is relative to;
// `sparsity_weight` is read at each evaluation (the gate stage changes it).
void BuildFitObjective(const Program& program, const FitterOptions& options, double unit_scale,
                       const FitCorrespondences& correspondences, const double* sparsity_weight, Objective* objective);

}  // namespace opgraph
