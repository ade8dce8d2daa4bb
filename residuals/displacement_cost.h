// Residual blocks of the free-form stage (solver/freeform_fit.h): Chamfer terms on a surface
// that is linear in per-vertex displacements, and a smoothness prior on the displacements.
#pragma once

#include <ceres/cost_function.h>
#include <ceres/sized_cost_function.h>

#include <vector>

#include "residuals/correspondence_cost.h"

namespace opgraph {

// A point p(d) = base + sum_j A_j d_j of the output surface (d_j the displacement of cage
// vertex j, one parameter block of 3 each) against a fixed target point q with normal n, in
// the layout of CorrespondenceCost (`metric`): [w n.(p - q)], [w (p - q)] or both, the point
// term scaled by kPointToPointShare.
class LinearPointCost : public ceres::CostFunction {
 public:
  struct Term {
    int vertex;
    Eigen::Matrix3d matrix;  // A_j
  };

  // `terms` name the blocks in order; `base` is p at zero displacement.
  static ceres::CostFunction* Create(const Vec3d& base, std::vector<Term> terms, const Vec3d& target_point,
                                     const Vec3d& target_normal, ChamferMetric metric, double weight) {
    return new LinearPointCost(base, std::move(terms), target_point, target_normal, metric, weight);
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    Vec3d p = base_;
    for (size_t j = 0; j < terms_.size(); ++j) p += terms_[j].matrix * Eigen::Map<const Vec3d>(parameters[j]);
    const Vec3d difference = p - target_point_;
    const bool plane = metric_ != ChamferMetric::kPointToPoint, point = metric_ != ChamferMetric::kPointToPlane;
    const double point_weight = weight_ * (plane ? kPointToPointShare : 1.0);
    const int first_point = plane ? 1 : 0;
    if (plane) residuals[0] = weight_ * target_normal_.dot(difference);
    if (point) {
      for (int d = 0; d < 3; ++d) residuals[first_point + d] = point_weight * difference[d];
    }
    if (jacobians == nullptr) return true;
    for (size_t j = 0; j < terms_.size(); ++j) {
      if (jacobians[j] == nullptr) continue;
      // Row-major num_residuals x 3.
      Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>> jacobian(jacobians[j], num_residuals(), 3);
      if (plane) jacobian.row(0) = weight_ * target_normal_.transpose() * terms_[j].matrix;
      if (point) jacobian.middleRows(first_point, 3) = point_weight * terms_[j].matrix;
    }
    return true;
  }

  const std::vector<Term>& terms() const { return terms_; }

 private:
  LinearPointCost(const Vec3d& base, std::vector<Term> terms, const Vec3d& target_point, const Vec3d& target_normal,
                  ChamferMetric metric, double weight)
      : base_(base), terms_(std::move(terms)), target_point_(target_point), target_normal_(target_normal),
        metric_(metric), weight_(weight) {
    set_num_residuals(metric == ChamferMetric::kPointToPoint ? 3 : metric == ChamferMetric::kPointToPlane ? 1 : 4);
    for (size_t j = 0; j < terms_.size(); ++j) mutable_parameter_block_sizes()->push_back(3);
  }

  Vec3d base_;
  std::vector<Term> terms_;
  Vec3d target_point_, target_normal_;
  ChamferMetric metric_;
  double weight_;
};

// Smoothness of the displacements along a cage edge (u, v): r = w (d_u - d_v).
class DisplacementDifferenceCost : public ceres::SizedCostFunction<3, 3, 3> {
 public:
  static ceres::CostFunction* Create(double weight) { return new DisplacementDifferenceCost(weight); }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    for (int d = 0; d < 3; ++d) residuals[d] = weight_ * (parameters[0][d] - parameters[1][d]);
    if (jacobians == nullptr) return true;
    for (int b = 0; b < 2; ++b) {
      if (jacobians[b] == nullptr) continue;
      Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> jacobian(jacobians[b]);
      jacobian = (b == 0 ? weight_ : -weight_) * Eigen::Matrix3d::Identity();
    }
    return true;
  }

 private:
  explicit DisplacementDifferenceCost(double weight) : weight_(weight) {}
  double weight_;
};

}  // namespace opgraph
