#include "residuals/correspondence_cost.h"

#include <algorithm>
#include <cmath>

namespace opgraph {

CorrespondenceCost::CorrespondenceCost(const Program* program, const SurfaceCorrespondence& correspondence,
                                       ChamferMetric metric, double weight)
    : program_(program), correspondence_(correspondence), metric_(metric), weight_(weight) {
  set_num_residuals(metric == ChamferMetric::kPointToPoint ? 3 : metric == ChamferMetric::kPointToPlane ? 1 : 4);
  *mutable_parameter_block_sizes() = program->BlockSizes();
}

bool CorrespondenceCost::Evaluate(double const* const*, double* residuals, double** jacobians) const {
  if (!program_->valid()) return false;
  const SurfaceCorrespondence& c = correspondence_;
  const Positions<double>& positions = program_->positions();
  Vec3d p = c.offset;
  for (int k = 0; k < 3; ++k) p += c.weights[k] * positions[c.vertices[k]];
  const Vec3d difference = p - c.target_point;
  // Residual layout: [n . d] for point-to-plane, [d] for point-to-point, [n . d, a d] for both
  // (a = kPointToPointShare).
  const bool plane = metric_ != ChamferMetric::kPointToPoint, point = metric_ != ChamferMetric::kPointToPlane;
  const double point_weight = weight_ * (plane ? kPointToPointShare : 1.0);
  const int first_point = plane ? 1 : 0;
  if (plane) residuals[0] = weight_ * c.target_normal.dot(difference);
  if (point) {
    for (int d = 0; d < 3; ++d) residuals[first_point + d] = point_weight * difference[d];
  }
  if (jacobians == nullptr) return true;
  const int num_columns = program_->num_columns();
  const double* rows[3] = {program_->JacobianRows(c.vertices[0]), program_->JacobianRows(c.vertices[1]),
                           program_->JacobianRows(c.vertices[2])};
  const std::vector<ProgramBlock>& blocks = program_->blocks();
  for (size_t b = 0; b < blocks.size(); ++b) {
    if (jacobians[b] == nullptr) continue;
    const int size = blocks[b].size, column = blocks[b].column;
    for (int j = 0; j < size; ++j) {
      double dp[3];
      for (int d = 0; d < 3; ++d) {
        const size_t offset = static_cast<size_t>(d) * num_columns + column + j;
        dp[d] = c.weights[0] * rows[0][offset] + c.weights[1] * rows[1][offset] + c.weights[2] * rows[2][offset];
      }
      if (plane) {
        jacobians[b][j] = weight_ * (c.target_normal[0] * dp[0] + c.target_normal[1] * dp[1] + c.target_normal[2] * dp[2]);
      }
      if (point) {
        for (int d = 0; d < 3; ++d) jacobians[b][(first_point + d) * size + j] = point_weight * dp[d];
      }
    }
  }
  return true;
}

ScaledCorrespondenceCost::ScaledCorrespondenceCost(const Program* program, const SurfaceCorrespondence& correspondence,
                                                   ChamferMetric metric, double weight, int scale_block)
    : unweighted_(program, correspondence, metric, weight), scale_block_(scale_block) {
  set_num_residuals(unweighted_.num_residuals());
  *mutable_parameter_block_sizes() = unweighted_.parameter_block_sizes();
}

bool ScaledCorrespondenceCost::Evaluate(double const* const* parameters, double* residuals, double** jacobians) const {
  if (!unweighted_.Evaluate(parameters, residuals, jacobians)) return false;
  double gradient[kMaxBranchOptions];
  const double s = Scale(parameters[scale_block_], gradient);
  const int m = num_residuals();
  if (jacobians) {
    const std::vector<int32_t>& sizes = parameter_block_sizes();
    for (size_t b = 0; b < sizes.size(); ++b) {
      if (jacobians[b] == nullptr) continue;
      for (int i = 0; i < m * sizes[b]; ++i) jacobians[b][i] *= s;
    }
    // The positions do not depend on the scale's block: its columns are d s / d theta x r_c.
    const int n = sizes[scale_block_];
    if (jacobians[scale_block_]) {
      for (int i = 0; i < m; ++i) {
        for (int j = 0; j < n; ++j) jacobians[scale_block_][i * n + j] = gradient[j] * residuals[i];
      }
    }
  }
  for (int i = 0; i < m; ++i) residuals[i] *= s;
  return true;
}

double BooleanWeightedCost::Scale(const double* theta, double* gradient) const {
  const double beta = 1.0 / (1.0 + std::exp(-theta[0]));
  const double s = boolean_side_ ? std::sqrt(beta) : std::sqrt(1 - beta);
  gradient[0] = boolean_side_ ? 0.5 * s * (1 - beta) : -0.5 * beta * s;  // dbeta/dlogit = beta (1 - beta)
  return s;
}

BranchWeightedCost::BranchWeightedCost(const Program* program, const SurfaceCorrespondence& correspondence,
                                       ChamferMetric metric, double weight, int branch_block, int option)
    : ScaledCorrespondenceCost(program, correspondence, metric, weight, branch_block),
      option_(option),
      num_options_(program->blocks()[branch_block].size) {}

double BranchWeightedCost::Scale(const double* theta, double* gradient) const {
  const double top = *std::max_element(theta, theta + num_options_);
  double sum = 0;
  for (int j = 0; j < num_options_; ++j) sum += gradient[j] = std::exp(theta[j] - top);
  for (int j = 0; j < num_options_; ++j) gradient[j] /= sum;  // the weights w
  const double s = std::sqrt(gradient[option_]);
  // d sqrt(w_k) / d alpha_j = sqrt(w_k) (delta_kj - w_j) / 2.
  for (int j = 0; j < num_options_; ++j) gradient[j] = 0.5 * s * ((j == option_) - gradient[j]);
  return s;
}

bool GateSparsityCost::Evaluate(double const* const* parameters, double* residuals, double** jacobians) const {
  const double gate = 1.0 / (1.0 + std::exp(-parameters[0][0]));
  const double root = std::sqrt(std::max(0.0, *weight_));
  residuals[0] = root * gate;
  if (jacobians && jacobians[0]) jacobians[0][0] = root * gate * (1 - gate);
  return true;
}

ParameterRangeCost::ParameterRangeCost(const ParameterRangeRule& rule, int block_size)
    : rule_(rule), block_size_(block_size) {
  set_num_residuals(1);
  mutable_parameter_block_sizes()->push_back(block_size);
}

bool ParameterRangeCost::Evaluate(double const* const* parameters, double* residuals, double** jacobians) const {
  const double x = parameters[0][rule_.param];
  const double root = std::sqrt(rule_.weight);
  double slope = 0;
  residuals[0] = 0;
  if (x < rule_.lower) {
    residuals[0] = root * (rule_.lower - x);
    slope = -root;
  } else if (x > rule_.upper) {
    residuals[0] = root * (x - rule_.upper);
    slope = root;
  }
  if (jacobians && jacobians[0]) {
    for (int j = 0; j < block_size_; ++j) jacobians[0][j] = j == rule_.param ? slope : 0.0;
  }
  return true;
}

}  // namespace opgraph
