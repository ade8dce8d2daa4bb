// Discrete choices the zero-shot search makes by fitting, recovered from shapes built with known
// values: a deformation's ring count, a cutter's primitive and place.
#include <gtest/gtest.h>

#include "core/metrics.h"
#include "ops/builders.h"
#include "ops/sequence.h"
#include "search/zero_shot.h"
#include "tests/known_shapes.h"

namespace opgraph {
namespace {

using build::Axis;

// A twisted block's facets lie between its rings, so a twist fitted on another number of rings
// leaves a residual no continuous parameter removes: the search must find the count.
TEST(ZeroShotDiscrete, RecoversATwistsRingCount) {
  for (const int cuts : {3, 5}) {
    Sequence truth = ParseSequence(build::Document({build::GlobalScale(Vec3d(0.4, 0.3, 1.1)),
                                                    build::LoopCut(Axis::kZ, cuts, Vec3d::Zero()),
                                                    build::SimpleDeform(build::Deform::kTwist, Axis::kZ, 65)}));
    const Mesh target_mesh = EvaluateSequence(&truth).back();
    Target target(target_mesh, {}, TargetOptions());
    ZeroShotOptions options;
    options.work_budget = 60000;  // the main-form choice and a little more: about 8 s
    const ZeroShotResult result = RecoverSequence(target, options);
    int found_cuts = -1;
    for (const Json& op : result.sequence.at("operations")) {
      if (op.at("op") == "LoopCut") found_cuts = op.at("params").at("cuts").get<int>();
    }
    EXPECT_EQ(found_cuts, cuts) << result.sequence.dump();
    Sequence found = ParseSequence(result.sequence);
    const ShapeMetrics metrics = ComputeShapeMetrics(EvaluateSequence(&found).back(), target_mesh);
    EXPECT_LT(metrics.chamfer.Sum(), 1e-3) << result.sequence.dump();
  }
}

// A block with a slot cut through it off its centre, turned about the slot's axis: one Boolean
// difference explains it. Before the holes through the target's surface inside the cage, the
// search found an Inset and an Extrude in through the block instead (Chamfer 9e-3 on a model
// of this kind).
TEST(ZeroShotDiscrete, RecoversAnOffCentreSlotAsOneBoolean) {
  Sequence truth = ParseSequence(build::Document(SlottedBlock()));
  const Mesh target_mesh = EvaluateSequence(&truth).back();
  Target target(target_mesh, {}, TargetOptions());
  ZeroShotOptions options;
  options.work_budget = 60000;
  const ZeroShotResult result = RecoverSequence(target, options);
  std::vector<std::string> ops;
  for (const Json& op : result.sequence.at("operations")) ops.push_back(op.at("op"));
  EXPECT_EQ(ops, (std::vector<std::string>{"GlobalAffineScale", "Boolean"})) << result.sequence.dump();
  Sequence found = ParseSequence(result.sequence);
  const ShapeMetrics metrics = ComputeShapeMetrics(EvaluateSequence(&found).back(), target_mesh);
  EXPECT_LT(metrics.chamfer.Sum(), 1e-3) << result.sequence.dump();
}

}  // namespace
}  // namespace opgraph
