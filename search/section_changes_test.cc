// Section changes on targets built by known sequences: a loop's scale marks its axis, a boss
// on one side marks none; the profile family then adds that axis to the long one.
#include "search/section_changes.h"

#include <gtest/gtest.h>

#include "ops/builders.h"
#include "ops/sequence.h"
#include "search/loop_ops.h"
#include "search/pose.h"
#include "search/proposals.h"

namespace opgraph {
namespace {

Target BuildTarget(const std::vector<Json>& ops) {
  Sequence sequence = ParseSequence(build::Document(ops));
  return Target(EvaluateSequence(&sequence).back(), {}, TargetOptions());
}

Vec3d ChangesOf(const Target& target) { return SectionChanges(LocalSamples(target, Eigen::Matrix3d::Identity())); }

// A box 1 x 1.8 x 1.4, one loop across Z (its shortest-but-one axis) scaled by `bulge`.
std::vector<Json> BulgedAcrossZ(double bulge) {
  std::vector<Json> ops = LoopCutWithScales(/*axis=*/2, /*cuts=*/1, /*expect=*/4);
  ops[1]["params"]["scale"] = ToJson(Vec3d(bulge, bulge, 1.0));
  ops.push_back(build::GlobalScale(Vec3d(0.5, 0.9, 0.7)));
  return ops;
}

TEST(SectionChanges, ALoopScaleMarksItsAxisOnly) {
  const Target target = BuildTarget(BulgedAcrossZ(1.4));
  const Vec3d changes = ChangesOf(target);
  // The section grows linearly from 1 at the ends to 1.4 in the middle (median about 1.2):
  // about 1.4 / 1.2 - 1 at the middle bins. Across X and Y one side pair is constant.
  EXPECT_GT(changes.z(), 0.1);
  EXPECT_LT(changes.z(), 0.25);
  EXPECT_LT(changes.x(), 0.02);
  EXPECT_LT(changes.y(), 0.02);
  const Layout pose = PoseLayout(target, Eigen::Matrix3d::Identity());
  EXPECT_EQ(ProfileAxes(pose, changes), (std::vector<int>{1, 2}));  // the long axis first
  // The profile family offers both axes as alternatives of each decision.
  const std::vector<Round> rounds = ProposeProfiles(pose, changes);
  ASSERT_FALSE(rounds.empty());
  EXPECT_EQ(rounds[0].alternatives.size(), 4u);  // two axes, each also subdivided
  Layout profiled = pose;
  EXPECT_NE(rounds[0].alternatives[2](&profiled).find("LoopCut Z"), std::string::npos);
}

TEST(SectionChanges, ABossOnOneSideOrAPlainBoxMarksNoAxis) {
  // A block 3 x 1 x 0.6, the middle third of its +Y face raised by 0.4: along X only the +Y
  // side changes; along Y the boss is narrower across X only.
  build::ExtrudeArgs boss;
  boss.faces.normals = {Vec3d::UnitY()};
  boss.faces.centers = {Vec3d(0, 0.5, 0)};
  boss.faces.expect = 1;
  boss.height = 0.4;
  const Target bossed = BuildTarget({build::LoopCut(build::Axis::kX, 2, Vec3d::Zero()),
                                     build::GlobalScale(Vec3d(1.5, 0.5, 0.3)), build::Extrude(boss)});
  const Target box = BuildTarget({build::GlobalScale(Vec3d(0.5, 0.9, 0.7))});
  for (const Target* target : {&bossed, &box}) {
    const Vec3d changes = ChangesOf(*target);
    EXPECT_LT(changes.maxCoeff(), 0.02) << changes.transpose();
    const Layout pose = PoseLayout(*target, Eigen::Matrix3d::Identity());
    EXPECT_EQ(ProfileAxes(pose, changes), std::vector<int>{LongAxis(pose)});
  }
}

TEST(SectionChanges, NoSignalFromAFlatOrEmptySampleSet) {
  EXPECT_EQ(SectionChanges({}), Vec3d::Zero());
  EXPECT_EQ(SectionChanges({Vec3d(0, 0, 0), Vec3d(1, 1, 0)}), Vec3d::Zero());
}

}  // namespace
}  // namespace opgraph
