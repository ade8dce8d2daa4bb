// HalfedgeTopology against brute force over the face list, on manifold, open and non-manifold
// inputs (a third face on an edge, a flipped face, two closed fans at one vertex, a face that
// repeats a vertex), for both windings.
#include "ops/halfedge_topology.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

namespace opgraph {
namespace {

using Corner = HalfedgeTopology::Corner;
using Winding = HalfedgeTopology::Winding;

std::pair<int, int> Undirected(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

void ExpectMatchesBruteForce(const std::vector<Polygon>& faces, int num_vertices, Winding winding) {
  const HalfedgeTopology topology(faces, num_vertices, winding);
  // Edges in order of first appearance, directed as their first corner; corners per edge/vertex.
  std::map<std::pair<int, int>, int> first;
  std::vector<std::pair<int, int>> edges;
  std::map<std::pair<int, int>, std::vector<Corner>> edge_corners;
  std::vector<std::vector<Corner>> vertex_corners(num_vertices);
  for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
    const int n = static_cast<int>(faces[f].size());
    for (int c = 0; c < n; ++c) {
      const int a = faces[f][c], b = faces[f][(c + 1) % n];
      if (first.emplace(Undirected(a, b), static_cast<int>(edges.size())).second) edges.push_back({a, b});
      edge_corners[Undirected(a, b)].push_back({f, c});
      vertex_corners[a].push_back({f, c});
    }
  }
  ASSERT_EQ(topology.NumEdges(), static_cast<int>(edges.size()));
  auto same = [](const HalfedgeTopology::Corners& got, const std::vector<Corner>& want) {
    if (got.size() != want.size()) return false;
    for (size_t i = 0; i < want.size(); ++i) {
      if (got[i].face != want[i].face || got[i].corner != want[i].corner) return false;
    }
    return true;
  };
  for (const auto& [key, corners] : edge_corners) {
    const int e = topology.Edge(key.first, key.second);
    ASSERT_GE(e, 0);
    EXPECT_EQ(topology.Edge(key.second, key.first), e);
    EXPECT_TRUE(same(topology.EdgeCorners(e), corners)) << "edge " << key.first << "-" << key.second;
    for (const Corner& corner : corners) {
      EXPECT_EQ(topology.CornerEdge(corner.face, corner.corner), e);
      EXPECT_EQ(topology.CornerVertex(corner), faces[corner.face][corner.corner]);
    }
    if (winding == Winding::kAsGiven) {
      EXPECT_EQ(e, first.at(key));
      EXPECT_EQ(topology.EdgeVertices(e), edges[e]);
    }
  }
  for (int v = 0; v < num_vertices; ++v) {
    EXPECT_TRUE(same(topology.VertexCorners(v), vertex_corners[v])) << "vertex " << v;
    for (int w = 0; w < num_vertices; ++w) {
      if (!edge_corners.count(Undirected(v, w))) EXPECT_EQ(topology.Edge(v, w), -1);
    }
  }
  if (winding == Winding::kEither) return;
  // Region boundaries: every prefix of the faces as a region.
  for (size_t size = 1; size <= faces.size(); ++size) {
    std::vector<int> region;
    std::set<std::pair<int, int>> directed;
    for (int f = static_cast<int>(size) - 1; f >= 0; --f) region.push_back(f);  // any order
    for (int f : region) {
      for (size_t c = 0; c < faces[f].size(); ++c) directed.insert({faces[f][c], faces[f][(c + 1) % faces[f].size()]});
    }
    std::vector<Corner> want;
    for (int f : region) {
      const int n = static_cast<int>(faces[f].size());
      for (int c = 0; c < n; ++c) {
        if (!directed.count({faces[f][(c + 1) % n], faces[f][c]})) want.push_back({f, c});
      }
    }
    const std::vector<Corner> got = topology.RegionBoundary(region);
    ASSERT_EQ(got.size(), want.size());
    for (size_t i = 0; i < want.size(); ++i) EXPECT_TRUE(got[i].face == want[i].face && got[i].corner == want[i].corner);
  }
}

void ExpectMatchesBruteForce(const std::vector<Polygon>& faces, int num_vertices) {
  ExpectMatchesBruteForce(faces, num_vertices, Winding::kAsGiven);
  ExpectMatchesBruteForce(faces, num_vertices, Winding::kEither);
}

TEST(HalfedgeTopology, ClosedCube) {
  const Mesh cube = MakeCube(2);
  ExpectMatchesBruteForce(cube.faces, cube.NumVertices());
  EXPECT_TRUE(HalfedgeTopology(cube.faces, cube.NumVertices()).Manifold());
}

TEST(HalfedgeTopology, OpenGrid) {
  // 3 x 2 vertices, two quads.
  ExpectMatchesBruteForce({{0, 1, 4, 3}, {1, 2, 5, 4}}, 6);
}

TEST(HalfedgeTopology, ThirdFaceOnAnEdge) {
  const std::vector<Polygon> faces = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  ExpectMatchesBruteForce(faces, 5);
  EXPECT_FALSE(HalfedgeTopology(faces, 5).Manifold());
}

TEST(HalfedgeTopology, FlippedFace) {
  ExpectMatchesBruteForce({{0, 1, 2, 3}, {1, 4, 5, 2}, {2, 5, 6, 3}, {0, 3, 6, 7}}, 8);
  ExpectMatchesBruteForce({{0, 1, 2}, {0, 1, 3}}, 4);  // both run 0 -> 1
}

TEST(HalfedgeTopology, TwoClosedFansAtOneVertex) {
  // Two tetrahedra sharing vertex 0.
  ExpectMatchesBruteForce({{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 5, 4}, {0, 4, 6}, {0, 6, 5}, {4, 5, 6}}, 7);
}

TEST(HalfedgeTopology, FaceRepeatingAVertex) {
  ExpectMatchesBruteForce({{0, 1, 2, 3}, {1, 4, 1, 2}}, 5);
}

}  // namespace
}  // namespace opgraph
