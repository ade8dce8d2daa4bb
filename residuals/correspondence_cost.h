// Chamfer residuals with correspondences fixed within a solve: a point on the output surface
// (a triangle's 3 vertices and barycentric weights, so it moves with the program) against a
// fixed target point. Output-to-target terms use an output sample and its nearest target
// sample; target-to-output terms use a target sample and its closest output point.
//   point-to-point: r = weight (p - q)            (3 residuals)
//   point-to-plane: r = weight n . (p - q)        (1 residual; n the target's normal)
//   plane and point: r = weight (n . (p - q), a (p - q))  (4 residuals; a = kPointToPointShare):
//                   point-to-plane's fast convergence on flat parts, with a point-to-point share
//                   so that a surface cannot leave part of the target uncovered by sliding along
//                   its plane (a closest point there has zero point-to-plane distance).
// p and dp/dparams come from the Program's cache (chain rule through the barycentric weights);
// the parameter blocks are all the Program's blocks, in its order.
#pragma once

#include <ceres/cost_function.h>
#include <ceres/sized_cost_function.h>

#include "program/program.h"

namespace opgraph {

struct SurfaceCorrespondence {
  int vertices[3];     // output vertices of the triangle holding p
  double weights[3];   // barycentric weights of p
  Vec3d target_point;  // q
  Vec3d target_normal; // n (unit)
  Vec3d offset = Vec3d::Zero();  // added to p: a point of a virtual surface (solver/boolean_weight.h)
};

enum class ChamferMetric { kPointToPoint, kPointToPlane, kPlaneAndPoint };
constexpr double kPointToPointShare = 0.3;

class CorrespondenceCost : public ceres::CostFunction {
 public:
  // `weight` multiplies the residual (e.g. sqrt(term weight / #samples) x the unit-box scale).
  CorrespondenceCost(const Program* program, const SurfaceCorrespondence& correspondence, ChamferMetric metric,
                     double weight);
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

 private:
  const Program* program_;
  SurfaceCorrespondence correspondence_;
  ChamferMetric metric_;
  double weight_;
};

// A correspondence residual r_c scaled by a mixture weight's square root s(theta), theta the
// program block `scale_block`: r = s r_c, so the cost s^2 |r_c|^2 is the weighted squared
// distance. Subclasses give s and ds/dtheta.
class ScaledCorrespondenceCost : public ceres::CostFunction {
 public:
  ScaledCorrespondenceCost(const Program* program, const SurfaceCorrespondence& correspondence, ChamferMetric metric,
                           double weight, int scale_block);
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

 protected:
  // s at `theta` (the block's values), with ds/dtheta in `gradient` (block size entries).
  virtual double Scale(const double* theta, double* gradient) const = 0;

 private:
  CorrespondenceCost unweighted_;
  int scale_block_;
};

// The Boolean weight's terms (solver/boolean_weight.h): s = sqrt(1 - beta) (`boolean_side`
// false: the extrusion's) or sqrt(beta) (true: the Boolean surface's), beta = sigmoid(logit).
class BooleanWeightedCost : public ScaledCorrespondenceCost {
 public:
  BooleanWeightedCost(const Program* program, const SurfaceCorrespondence& correspondence, ChamferMetric metric,
                      double weight, int beta_block, bool boolean_side)
      : ScaledCorrespondenceCost(program, correspondence, metric, weight, beta_block), boolean_side_(boolean_side) {}

 protected:
  double Scale(const double* theta, double* gradient) const override;

 private:
  bool boolean_side_;
};

// A mixed branch's terms (program/program.h): s = sqrt(w_k), w = softmax(alpha) of the branch's
// logit block, for a correspondence on option k's surface.
class BranchWeightedCost : public ScaledCorrespondenceCost {
 public:
  BranchWeightedCost(const Program* program, const SurfaceCorrespondence& correspondence, ChamferMetric metric,
                     double weight, int branch_block, int option);

 protected:
  double Scale(const double* theta, double* gradient) const override;

 private:
  int option_, num_options_;
};

// Gate sparsity: r = sqrt(*weight) sigmoid(w) on a gate logit w, so the cost is weight g^2 / 2.
// `weight` is read at every evaluation (the fitter stages it).
class GateSparsityCost : public ceres::SizedCostFunction<1, 1> {
 public:
  explicit GateSparsityCost(const double* weight) : weight_(weight) {}
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

 private:
  const double* weight_;
};

// Domain-rule hook: a soft range on one parameter of one op (a rule such as "an extrusion's
// width stays above 0.05"): r = sqrt(weight) (max(0, lower - x) + max(0, x - upper)) on the
// op's parameter block.
struct ParameterRangeRule {
  int op;
  int param;
  double lower;
  double upper;
  double weight;
};

class ParameterRangeCost : public ceres::CostFunction {
 public:
  ParameterRangeCost(const ParameterRangeRule& rule, int block_size);
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

 private:
  ParameterRangeRule rule_;
  int block_size_;
};

}  // namespace opgraph
