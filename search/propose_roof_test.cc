// The roof family on targets built by known sequences: a gable-roofed block is proposed as its
// walls with the ridge at its known height (the proposal builds the target itself, unfitted).
#include <gtest/gtest.h>

#include "ops/builders.h"
#include "ops/sequence.h"
#include "search/loop_ops.h"
#include "search/pose.h"
#include "search/proposals.h"

namespace opgraph {
namespace {

Mesh Build(const Json& document) {
  Sequence sequence = ParseSequence(document);
  return EvaluateSequence(&sequence).back();
}

// The largest distance from a vertex of `a` to the nearest of `b`'s, both ways.
double VertexDistance(const Mesh& a, const Mesh& b) {
  auto one_way = [](const Mesh& from, const Mesh& to) {
    double largest = 0;
    for (const Vec3d& p : from.vertices) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const Vec3d& q : to.vertices) nearest = std::min(nearest, (p - q).norm());
      largest = std::max(largest, nearest);
    }
    return largest;
  };
  return std::max(one_way(a, b), one_way(b, a));
}

// Walls 2 x 1.6 x 1.2 (X, Y, Z) and a ridge along Y raised 0.7 above them.
std::vector<Json> House() {
  const Vec3d half(1.0, 0.8, 0.6);
  return {build::GlobalScale(half), RaisedRidge(/*cut_axis=*/0, /*up_axis=*/2, /*up_sign=*/1, half, 0.7)[0],
          RaisedRidge(0, 2, 1, half, 0.7)[1]};
}

TEST(ProposeRoofs, TheWallsAndTheRidgeOfAHouse) {
  const Mesh house = Build(build::Document(House()));
  const Target target(house, {}, TargetOptions());
  const std::vector<Expansion> roofs = ProposeRoofs(target, PoseLayout(target, Eigen::Matrix3d::Identity()));
  ASSERT_FALSE(roofs.empty());
  EXPECT_NE(roofs[0].what.find("along Z, its ridge across X raised along +Z"), std::string::npos) << roofs[0].what;
  // The walls' box to within the body finder's bins (50 over the 1.9 the house spans in Z),
  // so the proposal, unfitted, nearly rebuilds the house.
  const Layout& roof = roofs[0].layout;
  EXPECT_NEAR(roof.half_extent.x(), 1.0, 1e-9);
  EXPECT_NEAR(roof.half_extent.y(), 0.8, 1e-9);
  EXPECT_NEAR(roof.half_extent.z(), 0.6, 2.0 * 1.9 / 50);
  const Mesh proposed = Build(roof.Document());
  EXPECT_EQ(proposed.NumVertices(), house.NumVertices());
  EXPECT_EQ(proposed.NumFaces(), house.NumFaces());
  EXPECT_LT(VertexDistance(proposed, house), 2.0 * 1.9 / 50);
}

TEST(ProposeRoofs, NoneForABoxOrAHouseTurnedOver) {
  const Target box(Build(build::Document({build::GlobalScale(Vec3d(1.0, 0.8, 0.6))})), {}, TargetOptions());
  EXPECT_TRUE(ProposeRoofs(box, PoseLayout(box, Eigen::Matrix3d::Identity())).empty());
  // Upside down, the ridge is raised along -Z.
  std::vector<Json> ops = House();
  ops.push_back(build::GlobalRotate(Vec3d(180, 0, 0)));
  const Target turned(Build(build::Document(ops)), {}, TargetOptions());
  const std::vector<Expansion> roofs = ProposeRoofs(turned, PoseLayout(turned, Eigen::Matrix3d::Identity()));
  ASSERT_FALSE(roofs.empty());
  EXPECT_NE(roofs[0].what.find("raised along -Z"), std::string::npos) << roofs[0].what;
}

}  // namespace
}  // namespace opgraph
