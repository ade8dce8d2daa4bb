// The free-form finishing stage on targets with and without detail the cage lacks, and the kept
// result replayed in real Blender.
#include "ops/blender_script.h"
#include "search/freeform.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/metrics.h"
#include "core/surface_distance.h"
#include "ops/builders.h"
#include "ops/sequence.h"
#include "tests/blender_runner.h"

namespace opgraph {
namespace {

using build::Axis;

// A loop-cut box, subdivided and posed: the structure the search would have found.
std::vector<Json> Structure() {
  return {build::LoopCut(Axis::kZ, 3, Vec3d::Zero()), build::GlobalScale(Vec3d(1.2, 0.8, 1.6))};
}
std::vector<Json> Tail() { return {build::Subdivision(2), build::GlobalRotate(Vec3d(0, 0, 30)), build::GlobalTranslate(Vec3d(4, 0, 1))}; }

Mesh Build(const std::vector<Json>& ops) {
  Sequence sequence = ParseSequence(build::Document(ops));
  return EvaluateSequence(&sequence).back();
}

// The structure with two cage vertices pulled out (a lump no structured op of the search makes).
Mesh WithLumps() {
  std::vector<Json> ops = Structure();
  build::DisplaceGroup lump{{}, Vec3d(0.5, 0.3, 0.2)}, dent{{}, Vec3d(0, -0.3, 0)};
  lump.verts.box.lo[0] = 1.0, lump.verts.box.lo[1] = 0.7, lump.verts.box.lo[2] = 0.7, lump.verts.box.hi[2] = 0.9;
  dent.verts.box.hi[0] = -1.0, dent.verts.box.hi[1] = -0.7, dent.verts.box.lo[2] = -0.9, dent.verts.box.hi[2] = -0.7;
  lump.verts.expect = dent.verts.expect = 1;
  ops.push_back(build::VertexDisplace({lump, dent}));
  for (const Json& op : Tail()) ops.push_back(op);
  return Build(ops);
}

Json StructureDocument() {
  std::vector<Json> ops = Structure();
  for (const Json& op : Tail()) ops.push_back(op);
  return build::Document(ops);
}

TEST(Freeform, DisplacesTheCageTowardDetailItLacks) {
  Target target(WithLumps(), {}, TargetOptions{});
  Evaluator evaluator(target, ZeroShotOptions{});
  const FreeformOutcome outcome = AddFreeformDetail(&evaluator, StructureDocument());
  ASSERT_TRUE(outcome.used);
  MetricsOptions metrics;
  metrics.num_samples = 4000;
  Sequence before = ParseSequence(StructureDocument()), after = ParseSequence(outcome.document);
  const double chamfer_before = ComputeShapeMetrics(EvaluateSequence(&before).back(), target.shape(), metrics).chamfer.Sum();
  const Mesh result = EvaluateSequence(&after).back();
  const double chamfer_after = ComputeShapeMetrics(result, target.shape(), metrics).chamfer.Sum();
  EXPECT_LT(chamfer_after, 0.5 * chamfer_before);
  // The displacements sit before the final Subdivision, the earlier ops held.
  const Json& operations = outcome.document["operations"];
  int displace = -1;
  for (size_t k = 0; k < operations.size(); ++k) {
    if (operations[k]["op"] == "VertexDisplace") displace = static_cast<int>(k);
  }
  ASSERT_GE(displace, 2);
  EXPECT_EQ(operations[displace + 1]["op"], "Subdivision");
  for (int k = 0; k < 2; ++k) EXPECT_EQ(operations[k], StructureDocument()["operations"][k]);

  // Real Blender rebuilds it: every per-vertex group finds its vertex in float32 coordinates.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "opgraph_freeform_test";
  std::filesystem::create_directories(dir);
  std::ofstream((dir / "rebuild_blender.py").string()) << BlenderScript(after);
  const Mesh blender = RunBlender((dir / "rebuild_blender.py").string(), (dir / "blender.obj").string());
  EXPECT_EQ(blender.NumVertices(), result.NumVertices());
  EXPECT_EQ(blender.NumFaces(), result.NumFaces());
  EXPECT_LT(SymmetricSurfaceDistanceRelative(result, blender), 1e-6);
}

TEST(Freeform, NotUsedWhereTheStructureExplainsTheShape) {
  Sequence sequence = ParseSequence(StructureDocument());
  Target target(EvaluateSequence(&sequence).back(), {}, TargetOptions{});
  Evaluator evaluator(target, ZeroShotOptions{});
  const FreeformOutcome outcome = AddFreeformDetail(&evaluator, StructureDocument());
  EXPECT_FALSE(outcome.used);
  EXPECT_EQ(outcome.document, StructureDocument());
}

TEST(Freeform, NotTriedOnABevelledCage) {
  // Bevel profiles match Blender's surface but not always its vertex positions along it, so
  // per-vertex boxes could miss their vertex in Blender.
  std::vector<Json> ops = Structure();
  ops.push_back(build::Bevel(0.1, 3));
  for (const Json& op : Tail()) ops.push_back(op);
  Target target(WithLumps(), {}, TargetOptions{});
  Evaluator evaluator(target, ZeroShotOptions{});
  EXPECT_FALSE(AddFreeformDetail(&evaluator, build::Document(ops)).used);
}

}  // namespace
}  // namespace opgraph
