#include "solver/objective.h"

#include <cmath>
#include <limits>

namespace opgraph {

namespace {

// Evaluates term `term` into scratch->residuals (and, with `with_jacobian`, its block Jacobians
// into scratch->jacobian, row-major per block, pointed to by scratch->jacobian_pointers).
// Returns whether the term could be evaluated.
bool EvaluateTerm(const Objective::Term& term, bool with_jacobian, ObjectiveScratch* scratch) {
  const ceres::CostFunction& cost = *term.cost;
  const int m = cost.num_residuals();
  scratch->residuals.resize(m);
  const std::vector<int32_t>& sizes = cost.parameter_block_sizes();
  size_t width = 0;
  for (int s : sizes) width += s;
  scratch->jacobian.resize(m * width);
  scratch->jacobian_pointers.resize(sizes.size());
  for (size_t b = 0, offset = 0; b < sizes.size(); offset += static_cast<size_t>(m) * sizes[b], ++b) {
    scratch->jacobian_pointers[b] = scratch->jacobian.data() + offset;
  }
  return cost.Evaluate(term.blocks->data.data(), scratch->residuals.data(),
                       with_jacobian ? scratch->jacobian_pointers.data() : nullptr);
}

// rho(s), rho'(s), rho''(s) of the term's loss at s = |r|^2.
void EvaluateLoss(const Objective::Term& term, double s, double rho[3]) {
  rho[0] = s, rho[1] = 1, rho[2] = 0;
  if (term.loss) term.loss->Evaluate(s, rho);
}

int CountRows(const Objective& objective) {
  int rows = 0;
  for (const Objective::Term& term : objective.terms) rows += term.cost->num_residuals();
  return rows;
}

}  // namespace

double EvaluateObjective(const Program& program, const Objective& objective, std::vector<double>* gradient,
                         ObjectiveScratch* scratch) {
  if (!program.valid()) return std::numeric_limits<double>::infinity();
  if (gradient) gradient->assign(program.num_columns(), 0.0);
  double total = 0;
  for (const Objective::Term& term : objective.terms) {
    if (!EvaluateTerm(term, gradient != nullptr, scratch)) return std::numeric_limits<double>::infinity();
    const std::vector<double>& r = scratch->residuals;
    double s = 0;
    for (double value : r) s += value * value;
    double rho[3];
    EvaluateLoss(term, s, rho);
    total += rho[0];
    if (!gradient) continue;
    // d rho / d params = 2 rho'(s) J^T r; each block maps to its Program columns.
    const std::vector<int32_t>& sizes = term.cost->parameter_block_sizes();
    for (size_t b = 0; b < sizes.size(); ++b) {
      const double* jacobian = scratch->jacobian_pointers[b];
      for (int j = 0; j < sizes[b]; ++j) {
        double g = 0;
        for (size_t i = 0; i < r.size(); ++i) g += jacobian[i * sizes[b] + j] * r[i];
        (*gradient)[term.blocks->columns[b] + j] += 2 * rho[1] * g;
      }
    }
  }
  return total;
}

double EvaluateNormalEquations(const Program& program, const Objective& objective, const std::vector<int>& free_index,
                               Eigen::MatrixXd* jtj, Eigen::VectorXd* jtr, ObjectiveScratch* scratch) {
  int num_free = 0;
  for (int index : free_index) num_free += index >= 0;
  jtj->setZero(num_free, num_free);
  jtr->setZero(num_free);
  if (!program.valid()) return std::numeric_limits<double>::infinity();
  scratch->rows.setZero(CountRows(objective), num_free);
  scratch->row_residuals.resize(scratch->rows.rows());
  double total = 0;
  int row = 0;
  for (const Objective::Term& term : objective.terms) {
    if (!EvaluateTerm(term, true, scratch)) return std::numeric_limits<double>::infinity();
    const std::vector<double>& r = scratch->residuals;
    const int m = static_cast<int>(r.size());
    double s = 0;
    for (double value : r) s += value * value;
    double rho[3];
    EvaluateLoss(term, s, rho);
    total += rho[0];
    // Ceres' corrector: r~ = sqrt(rho') / (1 - alpha) r and J~ = sqrt(rho') (I - alpha r r^T / s) J,
    // alpha = 1 - sqrt(1 + 2 s rho'' / rho') where rho'' > 0 (else 0).
    const double sqrt_rho1 = std::sqrt(rho[1]);
    double residual_scaling = sqrt_rho1, alpha_over_s = 0;
    if (s > 0 && rho[2] > 0) {
      const double alpha = 1 - std::sqrt(1 + 2 * s * rho[2] / rho[1]);
      residual_scaling = sqrt_rho1 / (1 - alpha);
      alpha_over_s = alpha / s;
    }
    const std::vector<int32_t>& sizes = term.cost->parameter_block_sizes();
    for (size_t b = 0; b < sizes.size(); ++b) {
      const double* jacobian = scratch->jacobian_pointers[b];
      for (int j = 0; j < sizes[b]; ++j) {
        const int column = free_index[term.blocks->columns[b] + j];
        if (column < 0) continue;
        double r_dot_column = 0;
        if (alpha_over_s != 0) {
          for (int i = 0; i < m; ++i) r_dot_column += r[i] * jacobian[i * sizes[b] + j];
        }
        for (int i = 0; i < m; ++i) {
          scratch->rows(row + i, column) =
              sqrt_rho1 * (jacobian[i * sizes[b] + j] - alpha_over_s * r[i] * r_dot_column);
        }
      }
    }
    for (int i = 0; i < m; ++i) scratch->row_residuals[row + i] = residual_scaling * r[i];
    row += m;
  }
  jtj->selfadjointView<Eigen::Lower>().rankUpdate(scratch->rows.transpose());
  *jtj = jtj->selfadjointView<Eigen::Lower>();
  jtr->noalias() = scratch->rows.transpose() * scratch->row_residuals;
  return total;
}

}  // namespace opgraph
