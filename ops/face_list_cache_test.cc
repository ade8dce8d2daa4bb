// FaceListCache: a value is built once per (face list, vertex count, key) and shared; any of
// the three differing builds anew; a build that throws is not kept; the oldest entry goes when
// the cache is full. And Subdivision, which keeps its refinement in one, still refines each
// level and topology as OpenSubdiv does when the same faces come back at another level.
#include "ops/face_list_cache.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "ops/builders.h"
#include "ops/sequence.h"

namespace opgraph {
namespace {

Mesh Quad(int extra_vertices = 0) {
  Mesh mesh;
  mesh.vertices.assign(4 + extra_vertices, Vec3d::Zero());
  mesh.faces = {{0, 1, 2, 3}};
  return mesh;
}

TEST(FaceListCache, BuildsOncePerFacesVertexCountAndKey) {
  FaceListCache<int> cache(8);
  int builds = 0;
  auto make = [&] { return std::make_shared<const int>(++builds); };
  EXPECT_EQ(*cache.Get(Quad(), 1, make), 1);
  EXPECT_EQ(*cache.Get(Quad(), 1, make), 1);  // shared, not rebuilt
  EXPECT_EQ(*cache.Get(Quad(), 2, make), 2);  // another key
  EXPECT_EQ(*cache.Get(Quad(1), 1, make), 3);  // another vertex count
  Mesh flipped = Quad();
  flipped.faces = {{0, 3, 2, 1}};
  EXPECT_EQ(*cache.Get(flipped, 1, make), 4);  // other faces
  EXPECT_EQ(builds, 4);
}

TEST(FaceListCache, KeepsNoFailedBuildAndDropsTheOldest) {
  FaceListCache<int> cache(2);
  EXPECT_THROW(cache.Get(Quad(), 0, []() -> std::shared_ptr<const int> { throw std::runtime_error("bad"); }),
               std::runtime_error);
  int builds = 0;
  auto make = [&] { return std::make_shared<const int>(++builds); };
  EXPECT_EQ(*cache.Get(Quad(), 0, make), 1);  // the failure was not kept
  cache.Get(Quad(), 1, make);
  cache.Get(Quad(), 2, make);  // full: key 0 goes
  EXPECT_EQ(*cache.Get(Quad(), 2, make), 3);
  EXPECT_EQ(*cache.Get(Quad(), 0, make), 4);
}

// Level 2 then level 1 on the cube, then level 2 again: 96, 24 and 96 faces, and the second
// level-2 result equals the first exactly.
TEST(FaceListCache, SubdivisionRefinesEachLevelOfTheSameFaces) {
  auto subdivide = [](int levels) {
    Sequence sequence = ParseSequence(build::Document({build::Subdivision(levels)}));
    return EvaluateSequence(&sequence).back();
  };
  const Mesh two = subdivide(2), one = subdivide(1), again = subdivide(2);
  EXPECT_EQ(two.faces.size(), 96u);
  EXPECT_EQ(one.faces.size(), 24u);
  EXPECT_EQ(one.vertices.size(), 26u);
  EXPECT_EQ(again.faces, two.faces);
  EXPECT_EQ(again.vertices, two.vertices);
}

}  // namespace
}  // namespace opgraph
