#include "solver/dense_lm.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Cholesky>

namespace opgraph {

std::string DenseLmOptions::Check() const {
  if (max_iterations < 1) return "max_iterations must be >= 1";
  if (!(min_radius > 0 && initial_radius >= min_radius && max_radius >= initial_radius)) {
    return "need 0 < min_radius <= initial_radius <= max_radius";
  }
  if (!(min_relative_decrease > 0 && min_relative_decrease < 1)) return "min_relative_decrease must be in (0, 1)";
  if (!(function_tolerance >= 0) || !(parameter_tolerance >= 0) || !(gradient_tolerance >= 0)) {
    return "tolerances must be >= 0";
  }
  return "";
}

namespace {

// The state at the current point.
struct Point {
  Eigen::VectorXd x;
  double cost = 0;
  Eigen::MatrixXd jtj;
  Eigen::VectorXd jtr;
};

// max |x - P(x - g)| with g = 2 J^T r the cost's gradient: zero at a bounded minimum.
double ProjectedGradientNorm(const Point& point, const Eigen::VectorXd& lower, const Eigen::VectorXd& upper) {
  const Eigen::VectorXd moved = (point.x - 2 * point.jtr).cwiseMax(lower).cwiseMin(upper);
  return (point.x - moved).cwiseAbs().maxCoeff();
}

// Which variables sit on a bound that the descent direction -g presses against: the step
// holds them (their rows and columns drop out of the system), so the free ones get the step
// that is best with them held instead of one computed as if they could move, then cut off.
std::vector<char> ActiveBounds(const Point& point, const Eigen::VectorXd& lower, const Eigen::VectorXd& upper) {
  std::vector<char> active(point.x.size(), 0);
  for (int i = 0; i < point.x.size(); ++i) {
    active[i] = (point.x[i] <= lower[i] && point.jtr[i] > 0) || (point.x[i] >= upper[i] && point.jtr[i] < 0);
  }
  return active;
}

// The Levenberg-Marquardt step at `radius` over the free variables, Jacobi-scaled as Ceres
// scales it: with S = diag(1 / (1 + sqrt(diag J^T J))), solves (S J^T J S + D / radius) u =
// -S J^T r, D the clamped diagonal of S J^T J S, and returns S u (0 for held variables).
Eigen::VectorXd ComputeStep(const Point& point, const std::vector<char>& active, double radius) {
  const Eigen::VectorXd scale = (point.jtj.diagonal().cwiseMax(0).cwiseSqrt().array() + 1).inverse().matrix();
  Eigen::MatrixXd scaled = scale.asDiagonal() * point.jtj * scale.asDiagonal();
  Eigen::VectorXd rhs = -scale.cwiseProduct(point.jtr);
  const Eigen::VectorXd damping = scaled.diagonal().cwiseMax(1e-6).cwiseMin(1e32) / radius;
  scaled.diagonal() += damping;
  for (int i = 0; i < static_cast<int>(active.size()); ++i) {
    if (!active[i]) continue;
    scaled.row(i).setZero();
    scaled.col(i).setZero();
    scaled(i, i) = 1;
    rhs[i] = 0;
  }
  const Eigen::VectorXd u = scaled.ldlt().solve(rhs);
  return scale.cwiseProduct(u);
}

// The model's reduction of the cost for step d: -(2 g.d + d^T J^T J d).
double PredictedReduction(const Point& point, const Eigen::VectorXd& step) {
  return -(2 * point.jtr.dot(step) + step.dot(point.jtj * step));
}

}  // namespace

DenseLmSummary MinimizeDenseLm(DenseLmProblem* problem, const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                               const DenseLmOptions& options, Eigen::VectorXd* x) {
  const int n = static_cast<int>(x->size());
  DenseLmSummary summary;
  summary.radius = options.initial_radius;
  Point point;
  point.x = x->cwiseMax(lower).cwiseMin(upper);
  point.jtj.resize(n, n);
  point.jtr.resize(n);
  point.cost = problem->Evaluate(point.x, &point.jtj, &point.jtr);
  ++summary.jacobian_evaluations;
  summary.initial_cost = summary.final_cost = point.cost;
  *x = point.x;
  if (!std::isfinite(point.cost) || n == 0) return summary;
  double radius = options.initial_radius, decrease_factor = 2;
  bool converged = ProjectedGradientNorm(point, lower, upper) <= options.gradient_tolerance;
  while (!converged && summary.iterations < options.max_iterations &&
         !(options.deadline && options.deadline->Passed())) {
    ++summary.iterations;
    const Eigen::VectorXd candidate =
        (point.x + ComputeStep(point, ActiveBounds(point, lower, upper), radius)).cwiseMax(lower).cwiseMin(upper);
    const Eigen::VectorXd step = candidate - point.x;
    if (step.norm() <= options.parameter_tolerance * (point.x.norm() + options.parameter_tolerance)) break;
    const double predicted = PredictedReduction(point, step);
    const double candidate_cost = predicted > 0 ? problem->Evaluate(candidate, nullptr, nullptr)
                                                : std::numeric_limits<double>::infinity();
    const double actual = point.cost - candidate_cost;
    const double ratio = std::isfinite(candidate_cost) ? actual / predicted : -1;
    if (ratio <= options.min_relative_decrease) {
      radius /= decrease_factor;
      decrease_factor *= 2;
      if (radius < options.min_radius) break;
      continue;
    }
    radius = std::min(options.max_radius, radius / std::max(1.0 / 3.0, 1.0 - std::pow(2 * ratio - 1, 3)));
    decrease_factor = 2;
    ++summary.successful_steps;
    converged = actual <= options.function_tolerance * point.cost;
    point.x = candidate;
    point.cost = problem->Evaluate(point.x, &point.jtj, &point.jtr);
    ++summary.jacobian_evaluations;
    converged = converged || ProjectedGradientNorm(point, lower, upper) <= options.gradient_tolerance;
  }
  *x = point.x;
  summary.final_cost = point.cost;
  summary.radius = radius;
  return summary;
}

}  // namespace opgraph
