#include "search/scale_first.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "ops/sequence.h"

namespace opgraph {
namespace {

Mesh Build(const Json& document) {
  Sequence sequence = ParseSequence(document);
  return EvaluateSequence(&sequence).back();
}

// Loop cuts on two axes, loop scales of one and of several loops, a loop translation, then the
// scale and an extrusion on the scaled mesh.
const char* const kProfileThenScale = R"({"operations": [
    {"op": "LoopCut", "params": {"axis": "X", "cuts": 4, "near": [0, 0, 0]}},
    {"op": "EdgeLoopAffineScale", "params": {"verts": {"box": [[-0.5, null, null], [0.5, null, null]], "expect": 8},
                                             "scale": [1.4, 0.5, 0.7]}},
    {"op": "EdgeLoopAffineScale", "params": {"verts": {"box": [[0.5, null, null], [0.7, null, null]], "expect": 4},
                                             "scale": [1, 1.3, 0.9]}},
    {"op": "LoopCut", "params": {"axis": "Z", "cuts": 2, "near": [0.9, 0.1, 0]}},
    {"op": "EdgeLoopAffineTranslate", "params": {"verts": {"box": [[null, null, 0.1], [null, null, 0.5]]},
                                                 "offset": [0.1, -0.2, 0.15]}},
    {"op": "GlobalAffineScale", "params": {"scale": [2.5, 0.6, 0.3]}},
    {"op": "Extrude", "params": {"faces": {"normal": [1, 0, 0]}, "height": 0.4, "mode": "individual"}}]})";

TEST(ScaleFirst, MovesTheScaleFirstAndBuildsTheSameMesh) {
  const Json document = Json::parse(kProfileThenScale);
  const Json reordered = ScaleFirst(document);
  ASSERT_EQ(reordered["operations"].size(), document["operations"].size());
  EXPECT_EQ(reordered["operations"][0]["op"], "GlobalAffineScale");
  EXPECT_EQ(reordered["operations"][1]["op"], "LoopCut");
  EXPECT_EQ(reordered["operations"][6]["op"], "Extrude");
  // A loop cut may seed its ring from another edge of the same ring after the scale, which
  // reorders the new vertices: the meshes are compared as counts and vertex sets.
  const Mesh original = Build(document), moved = Build(reordered);
  ASSERT_EQ(moved.NumVertices(), original.NumVertices());
  ASSERT_EQ(moved.NumFaces(), original.NumFaces());
  for (const Mesh* mesh : {&original, &moved}) {
    const Mesh& other = mesh == &original ? moved : original;
    for (const Vec3d& p : mesh->vertices) {
      double nearest = 1e300;
      for (const Vec3d& q : other.vertices) nearest = std::min(nearest, (p - q).norm());
      EXPECT_LT(nearest, 1e-12);
    }
  }
}

TEST(ScaleFirst, LeavesOtherSequencesAlone) {
  Json knife_first = Json::parse(kProfileThenScale);
  knife_first["operations"][0] = {{"op", "KnifeCut"}, {"params", {{"plane_co", {0, 0, 0.2}}, {"plane_no", {0, 0, 1}}}}};
  EXPECT_EQ(ScaleFirst(knife_first), knife_first);
  Json mirroring = Json::parse(kProfileThenScale);
  mirroring["operations"][5]["params"]["scale"] = {-2.5, 0.6, 0.3};
  EXPECT_EQ(ScaleFirst(mirroring), mirroring);
  Json scale_first = Json::parse(kProfileThenScale);
  for (int k = 0; k < 5; ++k) scale_first["operations"].erase(0);
  EXPECT_EQ(ScaleFirst(scale_first), scale_first);
}

}  // namespace
}  // namespace opgraph
