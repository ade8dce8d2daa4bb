// The free-form stage's parts: the affine tail against the sequence's own evaluation, the
// linear point cost's Jacobian against finite differences, and known displacements recovered.
#include "solver/freeform_fit.h"

#include <gtest/gtest.h>

#include <ceres/ceres.h>

#include <iostream>

#include "core/metrics.h"
#include "ops/builders.h"
#include "residuals/displacement_cost.h"

namespace opgraph {
namespace {

using build::Axis;

// A loop-cut box (the cage: its ops before `first_tail_op`) with Subdivision and a pose after it.
Json CageThenTail() {
  return build::Document({build::LoopCut(Axis::kX, 6, Vec3d::Zero()), build::GlobalScale(Vec3d(1.5, 1.0, 0.6)),
                          build::Subdivision(2), build::GlobalRotate(Vec3d(10, -20, 35)),
                          build::GlobalTranslate(Vec3d(3, -1, 2))});
}
constexpr int kFirstTailOp = 2;

// Smooth displacements of the cage's vertices (a bulge and a shear), up to about `size`.
Positions<double> Displacements(const Positions<double>& cage, double size) {
  Positions<double> d(cage.size());
  for (size_t v = 0; v < cage.size(); ++v) {
    const Vec3d& p = cage[v];
    d[v] = size * Vec3d(0.5 * std::sin(p.y() + 0.3), 0.8 * std::cos(1.2 * p.x()) * p.y(), std::sin(0.9 * p.x() + p.z()));
  }
  return d;
}

TEST(AffineTail, MatchesTheSequenceAtADisplacedCage) {
  Sequence sequence = ParseSequence(CageThenTail());
  const std::vector<Mesh> steps = EvaluateSequence(&sequence);
  const Mesh& cage = steps[kFirstTailOp - 1];
  const AffineTail tail = ProbeAffineTail(sequence, kFirstTailOp, cage, steps.back());
  ASSERT_EQ(tail.offset.size(), steps.back().vertices.size());
  // The same ops evaluated on a displaced cage, independently of the probe.
  Mesh displaced = cage;
  const Positions<double> d = Displacements(cage.vertices, 0.2);
  for (int v = 0; v < cage.NumVertices(); ++v) displaced.vertices[v] += d[v];
  Mesh current = displaced;
  for (size_t k = kFirstTailOp; k < sequence.ops.size(); ++k) current = ApplyOp(sequence.ops[k].get(), 1.0, current);
  const Positions<double> mapped = tail.Apply(displaced.vertices);
  for (size_t o = 0; o < mapped.size(); ++o) EXPECT_LT((mapped[o] - current.vertices[o]).norm(), 1e-9) << o;
  // Subdivision is local: an output vertex depends on a few cage vertices, not all.
  size_t max_terms = 0;
  for (const auto& terms : tail.terms) max_terms = std::max(max_terms, terms.size());
  EXPECT_LT(max_terms, static_cast<size_t>(cage.NumVertices()));
}

TEST(AffineTail, RejectsOpsThatAreNotAffine) {
  Json document = build::Document({build::LoopCut(Axis::kZ, 4, Vec3d::Zero()),
                                   build::SimpleDeform(build::Deform::kTwist, Axis::kZ, 60)});
  Sequence sequence = ParseSequence(document);
  const std::vector<Mesh> steps = EvaluateSequence(&sequence);
  EXPECT_THROW(ProbeAffineTail(sequence, 1, steps[0], steps.back()), std::runtime_error);
}

TEST(LinearPointCost, JacobianMatchesFiniteDifferences) {
  std::vector<LinearPointCost::Term> terms;
  for (int j = 0; j < 3; ++j) {
    Eigen::Matrix3d matrix;
    matrix << 0.3 + j, -0.2, 0.1, 0.05, 0.7, -0.4 * j, 0.2, 0.1, 0.9;
    terms.push_back({j, matrix});
  }
  std::unique_ptr<ceres::CostFunction> cost(LinearPointCost::Create(
      Vec3d(0.1, 0.2, 0.3), terms, Vec3d(1, -1, 0.5), Vec3d(0, 0.6, 0.8), ChamferMetric::kPlaneAndPoint, 1.7));
  double d[3][3] = {{0.1, -0.2, 0.3}, {0.4, 0.5, -0.6}, {-0.7, 0.8, 0.9}};
  const double* parameters[3] = {d[0], d[1], d[2]};
  double residuals[4], jacobian_data[3][12];
  double* jacobians[3] = {jacobian_data[0], jacobian_data[1], jacobian_data[2]};
  ASSERT_TRUE(cost->Evaluate(parameters, residuals, jacobians));
  constexpr double kStep = 1e-6;
  for (int j = 0; j < 3; ++j) {
    for (int c = 0; c < 3; ++c) {
      double plus[4], minus[4];
      d[j][c] += kStep;
      cost->Evaluate(parameters, plus, nullptr);
      d[j][c] -= 2 * kStep;
      cost->Evaluate(parameters, minus, nullptr);
      d[j][c] += kStep;
      for (int r = 0; r < 4; ++r) EXPECT_NEAR(jacobian_data[j][3 * r + c], (plus[r] - minus[r]) / (2 * kStep), 1e-7);
    }
  }
}

TEST(FitDisplacements, RecoversKnownDisplacements) {
  Sequence sequence = ParseSequence(CageThenTail());
  const std::vector<Mesh> steps = EvaluateSequence(&sequence);
  const Mesh& cage = steps[kFirstTailOp - 1];
  const AffineTail tail = ProbeAffineTail(sequence, kFirstTailOp, cage, steps.back());
  // The target: the tail of a cage with known displacements.
  Positions<double> moved = cage.vertices;
  const Positions<double> known = Displacements(cage.vertices, 0.1);
  for (int v = 0; v < cage.NumVertices(); ++v) moved[v] += known[v];
  Target target(Mesh{tail.Apply(moved), tail.faces}, {}, TargetOptions{});
  FreeformOptions options;
  options.smoothness_weight = 1e-4;
  options.max_outer_iterations = 10;
  const FreeformResult fit = FitDisplacements(target, cage, tail, options);
  EXPECT_LT(fit.final_loss, 0.05 * fit.initial_loss);
  // The shape is recovered (sliding along the surface is barely observed, so the displacements
  // themselves are not compared): point-to-surface distances to the target, unit box.
  Positions<double> fitted = cage.vertices;
  for (int v = 0; v < cage.NumVertices(); ++v) fitted[v] += fit.displacements[v];
  MetricsOptions metrics;
  metrics.num_samples = 4000;
  const double before = ComputeShapeMetrics(Mesh{tail.Apply(cage.vertices), tail.faces}, target.shape(), metrics).chamfer.Sum();
  const double after = ComputeShapeMetrics(Mesh{tail.Apply(fitted), tail.faces}, target.shape(), metrics).chamfer.Sum();
  EXPECT_LT(after, 0.05 * before) << before << " -> " << after;
  std::cout << "[freeform] Chamfer " << before << " -> " << after << ", loss " << fit.initial_loss << " -> " << fit.final_loss << std::endl;
}

}  // namespace
}  // namespace opgraph
