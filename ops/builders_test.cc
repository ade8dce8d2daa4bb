// Every typed builder makes an entry the engine parses and applies, and together they name all
// 19 ops: a schema change in an op breaks this test, not a producer of sequences silently.
#include "ops/builders.h"

#include <gtest/gtest.h>

#include <set>

#include "ops/op.h"
#include "ops/sequence.h"

namespace opgraph {
namespace {

TEST(Builders, EveryOpParsesAndApplies) {
  using namespace build;
  FaceTarget top;
  top.normals = {Vec3d::UnitZ()};
  top.expect = 1;
  VertexTarget upper;
  upper.box.lo[2] = 0.5;
  ExtrudeArgs extrude;
  extrude.faces = top;
  extrude.height = 0.5;
  extrude.width = 0.8;
  extrude.tilt_deg[0] = 5;
  BooleanArgs hole;
  hole.difference = true;
  hole.primitive = Primitive::kPrism8;
  hole.size = Vec3d(0.5, 0.5, 1);
  hole.location = Vec3d(0, 0, -1);
  FaceTarget front;
  front.normals = {-Vec3d::UnitY(), Vec3d::UnitX()};
  front.min_dot = 0.95;
  front.box.hi[2] = 0.9;
  front.centers = {Vec3d(0, -1, 0)};
  front.expect = 1;
  const std::vector<Json> ops = {
      GlobalScale(Vec3d(1.2, 1, 0.8)),
      Boolean(hole),
      Inset(top, 0.2, 0.05),
      Extrude(extrude),
      KnifeEdges(front, Vec3d(-1, -1, 0), Vec3d(1, -1, 0)),
      KnifePlane(Vec3d(0, 0, 0.3), Vec3d::UnitZ()),
      LoopCut(Axis::kX, 2, Vec3d::Zero()),
      EdgeLoopScale(upper, Vec3d(1.1, 1.1, 1)),
      EdgeLoopRotate(upper, Vec3d(0, 0, 10)),
      EdgeLoopTranslate(upper, Vec3d(0.1, 0, 0)),
      VertexDisplace({{upper, Vec3d(0, 0, 0.1)}}),
      SimpleDeform(Deform::kTwist, Axis::kZ, 20),
      SimpleDeform(Deform::kBend, Axis::kX, 15, 0.1, 0.9),
      SimpleDeform(Deform::kTaper, Axis::kZ, 0.2),
      SimpleDeform(Deform::kStretch, Axis::kZ, 0.1),
      GlobalRotate(Vec3d(0, 0, 30)),
      GlobalTranslate(Vec3d(3, 0, 0)),
      Mirror({Axis::kX}),
      Subdivision(1),
  };
  std::set<std::string> names;
  for (const Json& op : ops) names.insert(op.at("op").get<std::string>());
  names.insert(Bevel(0.05, 2, 30).at("op").get<std::string>());
  const std::vector<std::string> all = OpNames();
  EXPECT_EQ(names, std::set<std::string>(all.begin(), all.end()));

  Sequence sequence = ParseSequence(Document(ops));
  const std::vector<Mesh> steps = EvaluateSequence(&sequence);
  ASSERT_EQ(steps.size(), ops.size());
  EXPECT_GT(steps.back().NumFaces(), 100);
  // The written form reads back as it was built.
  EXPECT_EQ(SequenceToJson(sequence).at("operations").size(), ops.size());
  Sequence bevelled = ParseSequence(Document({GlobalScale(Vec3d(1, 1, 0.5)), Bevel(0.05, 2, 30)}));
  EXPECT_GT(EvaluateSequence(&bevelled).back().NumFaces(), 6 + 12 * 2);
}

TEST(Builders, AxisNamesRoundTrip) {
  using build::Axis;
  for (Axis axis : {Axis::kX, Axis::kY, Axis::kZ}) EXPECT_EQ(build::AxisNamed(build::AxisName(axis)), axis);
}

}  // namespace
}  // namespace opgraph
