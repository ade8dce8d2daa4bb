// Discrete choices the zero-shot search makes by fitting, recovered from shapes built with known
// values: a deformation's ring count, a cutter's primitive and place, a loop's kind of move.
#include <gtest/gtest.h>

#include "core/metrics.h"
#include "ops/builders.h"
#include "ops/sequence.h"
#include "ops/sequence_op_names.h"
#include "search/zero_shot.h"
#include "tests/known_shapes.h"

namespace opgraph {
namespace {

using build::Axis;

struct Recovered {
  Json sequence;
  std::vector<std::string> ops;
  double chamfer = 0;  // of the recovered sequence's mesh to the truth's
};

// The search's result on the mesh `truth_ops` build, with a small budget (the main-form choice
// and a little more: about 8 s).
Recovered RecoverFromTruth(const std::vector<Json>& truth_ops) {
  Sequence truth = ParseSequence(build::Document(truth_ops));
  const Mesh target_mesh = EvaluateSequence(&truth).back();
  Target target(target_mesh, {}, TargetOptions());
  ZeroShotOptions options;
  options.work_budget = 60000;
  Recovered recovered;
  recovered.sequence = RecoverSequence(target, options).sequence;
  recovered.ops = SequenceOpNames(recovered.sequence);
  Sequence found = ParseSequence(recovered.sequence);
  recovered.chamfer = ComputeShapeMetrics(EvaluateSequence(&found).back(), target_mesh).chamfer.Sum();
  return recovered;
}

// A twisted block's facets lie between its rings, so a twist fitted on another number of rings
// leaves a residual no continuous parameter removes: the search must find the count.
TEST(ZeroShotDiscrete, RecoversATwistsRingCount) {
  for (const int cuts : {3, 5}) {
    const Recovered result = RecoverFromTruth({build::GlobalScale(Vec3d(0.4, 0.3, 1.1)),
                                               build::LoopCut(Axis::kZ, cuts, Vec3d::Zero()),
                                               build::SimpleDeform(build::Deform::kTwist, Axis::kZ, 65)});
    int found_cuts = -1;
    for (const Json& op : result.sequence.at("operations")) {
      if (op.at("op") == "LoopCut") found_cuts = op.at("params").at("cuts").get<int>();
    }
    EXPECT_EQ(found_cuts, cuts) << result.sequence.dump();
    EXPECT_LT(result.chamfer, 1e-3) << result.sequence.dump();
  }
}

// A block with a slot cut through it off its centre, turned about the slot's axis: one Boolean
// difference explains it. Before the holes through the target's surface inside the cage, the
// search found an Inset and an Extrude in through the block instead (Chamfer 9e-3 on a model
// of this kind).
TEST(ZeroShotDiscrete, RecoversAnOffCentreSlotAsOneBoolean) {
  const Recovered result = RecoverFromTruth(SlottedBlock());
  EXPECT_EQ(result.ops, (std::vector<std::string>{"GlobalAffineScale", "Boolean"})) << result.sequence.dump();
  EXPECT_LT(result.chamfer, 1e-3) << result.sequence.dump();
}

// A bar whose middle loop is tilted (a kinked profile): a rotation of the loop explains it with
// the same ops as the scale the profile stage fits first, which only imitates it. Before the
// rotation replaced the scale, from a tilt on the scaled cage, the search kept the scale.
TEST(ZeroShotDiscrete, RecoversATiltedLoopAsARotation) {
  build::VertexTarget middle;
  middle.box.lo[2] = -0.4, middle.box.hi[2] = 0.4;
  middle.expect = 4;
  const Recovered result = RecoverFromTruth({build::GlobalScale(Vec3d(0.6, 0.5, 1.6)),
                                             build::LoopCut(Axis::kZ, 1, Vec3d::Zero()),
                                             build::EdgeLoopRotate(middle, Vec3d(0, 14, 0))});
  EXPECT_EQ(result.ops, (std::vector<std::string>{"GlobalAffineScale", "LoopCut", "EdgeLoopAffineRotate"}))
      << result.sequence.dump();
  EXPECT_LT(result.chamfer, 1e-3) << result.sequence.dump();
}

}  // namespace
}  // namespace opgraph
