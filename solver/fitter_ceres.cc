// The fitter's Ceres path (`--optimizer ceres`) and the check that Ceres and the fitter's own
// optimizers see one objective (solver/fitter.h).
#include <ceres/crs_matrix.h>
#include <ceres/manifold.h>
#include <ceres/problem.h>
#include <ceres/solver.h>

#include <algorithm>

#include "solver/fit_correspondences.h"
#include "solver/fitter.h"
#include "solver/fitter_solvers.h"

namespace opgraph {

std::unique_ptr<ceres::Problem> Fitter::MakeCeresProblem(const Objective& objective) const {
  ceres::Problem::Options problem_options;
  problem_options.evaluation_callback = program_.get();
  problem_options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  auto problem = std::make_unique<ceres::Problem>(problem_options);
  for (const ProgramBlock& block : program_->blocks()) {
    problem->AddParameterBlock(block.data, block.size);
    if (Held(block)) {
      problem->SetParameterBlockConstant(block.data);
    } else if (!block.constant.empty()) {
      problem->SetManifold(block.data, new ceres::SubsetManifold(block.size, block.constant));
    }
    if (block.holds_op_params()) {
      const std::vector<ParamSpec>& specs = sequence_->ops[block.op]->specs();
      for (int i = 0; i < block.size; ++i) {
        problem->SetParameterLowerBound(block.data, i, specs[i].lower);
        problem->SetParameterUpperBound(block.data, i, specs[i].upper);
      }
    }
  }
  for (const Objective::Term& term : objective.terms) {
    problem->AddResidualBlock(const_cast<ceres::CostFunction*>(term.cost), const_cast<ceres::LossFunction*>(term.loss),
                              term.blocks->data);
  }
  return problem;
}

void Fitter::EvaluateBothWays(ObjectiveEvaluation* own, ObjectiveEvaluation* ceres) {
  FitCorrespondences correspondences;
  BuildCorrespondences(options_.seed, &correspondences);
  Objective objective;
  MakeObjective(correspondences, &objective);
  program_->PrepareForEvaluation(true, true);
  own->loss = EvaluateObjective(*program_, objective, &own->gradient, scratch_.get());
  EvaluateNormalEquations(*program_, objective, FindFreeColumns().index, &own->jtj, &own->jtr, scratch_.get());
  const std::unique_ptr<ceres::Problem> problem = MakeCeresProblem(objective);
  double cost = 0;
  ceres::CRSMatrix jacobian;
  problem->Evaluate(ceres::Problem::EvaluateOptions(), &cost, nullptr, &ceres->gradient, &jacobian);
  ceres->loss = 2 * cost;
  for (double& g : ceres->gradient) g *= 2;
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(jacobian.num_rows, jacobian.num_cols);
  for (int row = 0; row < jacobian.num_rows; ++row) {
    for (int k = jacobian.rows[row]; k < jacobian.rows[row + 1]; ++k) dense(row, jacobian.cols[k]) = jacobian.values[k];
  }
  ceres->jtj = dense.transpose() * dense;
}

double Fitter::SolveWithCeres(const Objective& objective, FitSummary* summary) {
  const std::unique_ptr<ceres::Problem> problem = MakeCeresProblem(objective);
  ceres::Solver::Options solver_options;
  solver_options.minimizer_type = ceres::TRUST_REGION;
  solver_options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  solver_options.linear_solver_type = ceres::DENSE_QR;
  solver_options.max_num_iterations = options_.max_inner_iterations;
  solver_options.num_threads = options_.num_threads;
  solver_options.logging_type = ceres::SILENT;
  solver_options.function_tolerance = 1e-8;
  solver_options.parameter_tolerance = 1e-10;
  solver_options.initial_trust_region_radius = trust_region_radius_;
  if (deadline_.limited()) solver_options.max_solver_time_in_seconds = deadline_.SecondsLeft();
  ceres::Solver::Summary solver_summary;
  ceres::Solve(solver_options, problem.get(), &solver_summary);
  summary->inner_iterations += static_cast<int>(solver_summary.iterations.size()) - 1;
  if (!solver_summary.iterations.empty()) {
    trust_region_radius_ = std::max(options_.initial_trust_region_radius,
                                    std::min(1e16, solver_summary.iterations.back().trust_region_radius));
  }
  program_->PrepareForEvaluation(false, true);  // leave the cache at the solution
  return 2 * solver_summary.final_cost;
}

}  // namespace opgraph
