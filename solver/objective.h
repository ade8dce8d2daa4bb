// The fitter's objective at fixed correspondences: residual blocks (Ceres cost functions over
// the Program's parameter blocks) that every optimizer and every loss report evaluate the same
// way: the loss is the sum over blocks of rho(|r|^2) (Ceres' cost is half of it).
#pragma once

#include <deque>
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <ceres/cost_function.h>
#include <ceres/loss_function.h>

#include "program/program.h"
#include "residuals/correspondence_cost.h"

namespace opgraph {

struct Objective {
  // The parameter blocks a term reads, in its cost function's order. Shared: every
  // correspondence term reads all of the Program's blocks, and one list per term would cost
  // thousands of allocations per correspondence update.
  struct Blocks {
    std::vector<double*> data;
    std::vector<int> columns;  // first Program Jacobian column of each block
  };
  struct Term {
    const ceres::CostFunction* cost;  // one of correspondence_costs or other_costs
    const ceres::LossFunction* loss;  // null: rho(s) = s
    const Blocks* blocks;             // one of block_lists
  };
  std::vector<Term> terms;
  // Deques: terms point into them while they grow, and thousands of correspondence terms take a
  // few blocks of memory instead of one allocation each.
  std::deque<Blocks> block_lists;
  std::deque<CorrespondenceCost> correspondence_costs;
  std::vector<std::unique_ptr<ceres::CostFunction>> other_costs;
  std::vector<std::unique_ptr<ceres::LossFunction>> losses;
};

// Buffers an evaluation reuses, so that repeated evaluations allocate nothing.
struct ObjectiveScratch {
  std::vector<double> residuals, jacobian;
  std::vector<double*> jacobian_pointers;
  // The corrected residual rows over the free columns (#rows by #free) and their residuals.
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rows;
  Eigen::VectorXd row_residuals;
};

// The loss at the program's current evaluation; with `gradient` (one entry per Program
// Jacobian column) also its gradient. +inf when the program or a term is invalid.
double EvaluateObjective(const Program& program, const Objective& objective, std::vector<double>* gradient,
                         ObjectiveScratch* scratch);

// The loss and the Gauss-Newton normal equations over the free columns: `free_index` maps each
// Program column to its place among the free ones (-1: held). `jtj` (#free by #free) and `jtr`
// (#free) are J^T J and J^T r of the residuals, each block's corrected for its robust loss as
// Ceres corrects them (Triggs et al.'s correction: the loss's gradient is then 2 J^T r and its
// Gauss-Newton Hessian 2 J^T J). Needs the program's Jacobian. +inf when invalid.
double EvaluateNormalEquations(const Program& program, const Objective& objective, const std::vector<int>& free_index,
                               Eigen::MatrixXd* jtj, Eigen::VectorXd* jtr, ObjectiveScratch* scratch);

}  // namespace opgraph
