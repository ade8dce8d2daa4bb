// The box-body family on targets built by known sequences: the cube lands on the block an
// extrusion grew from (found from the target's sections, not from the sequence), and the
// extrusion family then proposes that extrusion from it.
#include <gtest/gtest.h>

#include "ops/builders.h"
#include "ops/sequence.h"
#include "search/face_residuals.h"
#include "search/pose.h"
#include "search/proposals.h"

namespace opgraph {
namespace {

Target BuildTarget(const std::vector<Json>& ops) {
  Sequence sequence = ParseSequence(build::Document(ops));
  return Target(EvaluateSequence(&sequence).back(), {}, TargetOptions());
}

// A block 3 x 1 x 0.6 with a tapered tab grown from its -Y face (its cap narrowed to 0.8), as
// a modeller pulls a limb out of a body: the tab's sides slope, so the whole is no box.
std::vector<Json> BlockWithTab(double tab_height) {
  build::ExtrudeArgs tab;
  tab.faces.normals = {-Vec3d::UnitY()};
  tab.height = tab_height;
  tab.width = 0.8;
  return {build::GlobalScale(Vec3d(1.5, 0.5, 0.3)), build::Extrude(tab)};
}

TEST(ProposeBoxBodies, TheBlockATabGrewFrom) {
  const Target target = BuildTarget(BlockWithTab(1.0));
  const Layout pose = PoseLayout(target, Eigen::Matrix3d::Identity());
  const std::vector<Expansion> bodies = ProposeBoxBodies(target, pose);
  ASSERT_FALSE(bodies.empty());
  const Layout& body = bodies[0].layout;
  EXPECT_NE(bodies[0].what.find("along Y"), std::string::npos) << bodies[0].what;
  // Across, the block's sides; along Y, within two bins (2/50 of the 2.0 the target spans) of
  // the block's ends: the tab's taper starts slowly.
  EXPECT_NEAR(body.half_extent.x(), 1.5, 1e-6);
  EXPECT_NEAR(body.half_extent.y(), 0.5, 0.08 + 1e-6);
  EXPECT_NEAR(body.half_extent.z(), 0.3, 1e-6);
  EXPECT_NEAR(body.PoseTranslation().y(), 0.0, 0.04 + 1e-6);

  // From the placed block, the first extrusion proposed is the tab's, on the -Y face.
  const std::vector<Round> rounds = ProposeExtrusions(body, ComputeFaceResiduals(target, body));
  ASSERT_FALSE(rounds.empty());
  ASSERT_FALSE(rounds[0].alternatives.empty());
  Layout grown = body;
  ASSERT_FALSE(rounds[0].alternatives[0](&grown).empty());
  ASSERT_EQ(grown.details.size(), 1u);
  const Json& extrude = grown.details[0];
  EXPECT_EQ(extrude["op"], "Extrude");
  EXPECT_NEAR(extrude["params"]["faces"]["normal"][1].get<double>(), -1.0, 1e-9);
  EXPECT_NEAR(extrude["params"]["height"].get<double>(), 1.0, 0.3);
  Sequence sequence = ParseSequence(grown.Document());
  EXPECT_NO_THROW(EvaluateSequence(&sequence));
}

TEST(ProposeBoxBodies, NoneForABoxOrARoundedForm) {
  const Target box = BuildTarget({build::GlobalScale(Vec3d(1.5, 0.5, 0.3))});
  EXPECT_TRUE(ProposeBoxBodies(box, PoseLayout(box, Eigen::Matrix3d::Identity())).empty());
  // Smoothed, the block with its tab has no run of constant section.
  std::vector<Json> ops = BlockWithTab(1.0);
  ops.push_back(build::Subdivision(2));
  const Target rounded = BuildTarget(ops);
  EXPECT_TRUE(ProposeBoxBodies(rounded, PoseLayout(rounded, Eigen::Matrix3d::Identity())).empty());
}

TEST(ProposeBoxBodies, NoneWhenLittleGrowsBeyondTheBlock) {
  // A tab 1.5% of the length beyond the block is detail for the block's own extrusions.
  const Target target = BuildTarget(BlockWithTab(0.015));
  const Layout pose = PoseLayout(target, Eigen::Matrix3d::Identity());
  for (const Expansion& body : ProposeBoxBodies(target, pose)) {
    EXPECT_EQ(body.what.find("along Y"), std::string::npos) << body.what;
  }
}

}  // namespace
}  // namespace opgraph
