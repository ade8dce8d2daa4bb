#include "solver/fitter_solvers.h"

#include <algorithm>
#include <cmath>

namespace opgraph {

Eigen::VectorXd FreeColumns::Values() const {
  Eigen::VectorXd values(size());
  for (int c = 0; c < size(); ++c) values[c] = *address[c];
  return values;
}

void FreeColumns::Set(const Eigen::VectorXd& values) const {
  for (int c = 0; c < size(); ++c) *address[c] = values[c];
}

namespace {

// The objective as a function of the free columns, for MinimizeDenseLm. The program keeps its
// values from the last point evaluated, so evaluating the normal equations at the point whose
// cost was just evaluated reuses them.
class ObjectiveOverColumns : public DenseLmProblem {
 public:
  ObjectiveOverColumns(Program* program, const Objective& objective, const FreeColumns& columns,
                       ObjectiveScratch* scratch)
      : program_(program), objective_(objective), columns_(columns), scratch_(scratch) {}

  double Evaluate(const Eigen::VectorXd& x, Eigen::MatrixXd* jtj, Eigen::VectorXd* jtr) override {
    const bool new_point = !(x.size() == last_x_.size() && x == last_x_);
    if (new_point) {
      columns_.Set(x);
      last_x_ = x;
    }
    program_->PrepareForEvaluation(jtj != nullptr, new_point);
    if (!jtj) return EvaluateObjective(*program_, objective_, nullptr, scratch_);
    return EvaluateNormalEquations(*program_, objective_, columns_.index, jtj, jtr, scratch_);
  }

 private:
  Program* program_;
  const Objective& objective_;
  const FreeColumns& columns_;
  ObjectiveScratch* scratch_;
  Eigen::VectorXd last_x_;
};

}  // namespace

double SolveWithDenseLm(Program* program, const Objective& objective, const FreeColumns& columns,
                        const DenseLmOptions& options, DenseLmSummary* summary, ObjectiveScratch* scratch) {
  ObjectiveOverColumns problem(program, objective, columns, scratch);
  Eigen::VectorXd x = columns.Values();
  *summary = MinimizeDenseLm(&problem, columns.lower, columns.upper, options, &x);
  columns.Set(x);
  program->PrepareForEvaluation(false, true);  // leave the cache at the solution
  return summary->final_cost;
}

double SolveWithAdam(Program* program, const Objective& objective, const FreeColumns& columns, int steps,
                     double learning_rate, const Deadline& deadline, int* steps_taken, ObjectiveScratch* scratch) {
  const int n = columns.size();
  std::vector<double> m(n, 0.0), v(n, 0.0), gradient;
  constexpr double kBeta1 = 0.9, kBeta2 = 0.999, kEpsilon = 1e-8;
  for (int step = 1; step <= steps && !deadline.Passed(); ++step) {
    program->PrepareForEvaluation(true, true);
    if (!std::isfinite(EvaluateObjective(*program, objective, &gradient, scratch))) break;
    for (size_t column = 0; column < columns.index.size(); ++column) {
      const int c = columns.index[column];
      if (c < 0) continue;
      m[c] = kBeta1 * m[c] + (1 - kBeta1) * gradient[column];
      v[c] = kBeta2 * v[c] + (1 - kBeta2) * gradient[column] * gradient[column];
      const double m_hat = m[c] / (1 - std::pow(kBeta1, step)), v_hat = v[c] / (1 - std::pow(kBeta2, step));
      double& x = *columns.address[c];
      x = std::min(columns.upper[c], std::max(columns.lower[c], x - learning_rate * m_hat / (std::sqrt(v_hat) + kEpsilon)));
    }
    ++*steps_taken;
  }
  program->PrepareForEvaluation(false, true);
  return EvaluateObjective(*program, objective, nullptr, scratch);
}

}  // namespace opgraph
