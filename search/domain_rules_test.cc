// Domain rules in the search's fits: a hole's cutter, whose length past the shape the target
// cannot see, is held within kMaxBooleanSize half extents (Blender keeps its corners in float32).
#include "search/domain_rules.h"

#include <gtest/gtest.h>

#include "ops/builders.h"
#include "ops/sequence.h"
#include "search/evaluator.h"
#include "search/pose.h"

namespace opgraph {
namespace {

Json Hole(double width, double length) {
  build::BooleanArgs hole;
  hole.difference = true;
  hole.primitive = build::Primitive::kPrism8;
  hole.size = Vec3d(width, width, length);
  hole.location = Vec3d(0.01, -0.007, 0);
  return build::Boolean(hole);
}

TEST(DomainRules, AHolesCutterStaysWithinItsSizeBound) {
  // A block 2 x 2 x 1 with a bore 0.8 wide along Z; the search's cutter starts 0.6 wide and 40
  // half extents long (without the rule the fit leaves that length as it is).
  Sequence truth = ParseSequence(build::Document({build::GlobalScale(Vec3d(1, 1, 0.5)), Hole(0.8, 3)}));
  const Target target(EvaluateSequence(&truth).back(), {}, TargetOptions{});
  Layout layout = PoseLayoutOnBox(Eigen::Matrix3d::Identity(), Vec3d(-1, -1, -0.5), Vec3d(1, 1, 0.5));
  const double max_half_extent = layout.half_extent.maxCoeff();
  static_assert(kMaxBooleanSize < 40, "the cutter must start beyond the bound");
  layout.details.push_back(Hole(0.6, 40 * max_half_extent));
  Evaluator evaluator(target, ZeroShotOptions{});
  const Trial trial = evaluator.Fit(layout);
  ASSERT_TRUE(trial.ok);
  const Json& size = trial.layout.details.at(0)["params"]["size"];
  EXPECT_LE(size[2].get<double>(), 1.01 * kMaxBooleanSize * max_half_extent) << size.dump();
  EXPECT_GE(size[2].get<double>(), 1.0);  // still through the block
  // And the bore has grown from 0.6 to the target's 0.8, to within what one search fit (eight
  // correspondence updates) reaches.
  EXPECT_NEAR(size[0].get<double>(), 0.8, 0.03) << size.dump();
}

}  // namespace
}  // namespace opgraph
