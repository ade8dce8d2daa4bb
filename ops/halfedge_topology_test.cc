// HalfedgeTopology against brute force over the face list, on manifold, open and non-manifold
// inputs (a third face on an edge, a flipped face, two closed fans at one vertex, a face that
// repeats a vertex), and over triangle lists.
#include "ops/halfedge_topology.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

namespace opgraph {
namespace {

using Corner = HalfedgeTopology::Corner;

std::pair<int, int> Undirected(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

void ExpectMatchesBruteForce(const std::vector<Polygon>& faces, int num_vertices) {
  const HalfedgeTopology topology(faces, num_vertices);
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
    EXPECT_EQ(e, first.at(key));
    EXPECT_EQ(topology.EdgeVertices(e), edges[e]);
  }
  for (int v = 0; v < num_vertices; ++v) {
    EXPECT_TRUE(same(topology.VertexCorners(v), vertex_corners[v])) << "vertex " << v;
    for (int w = 0; w < num_vertices; ++w) {
      if (!edge_corners.count(Undirected(v, w))) EXPECT_EQ(topology.Edge(v, w), -1);
    }
  }
  // Directed edge -> face (the last face running it) and closedness (each directed edge once,
  // and its reverse once), as Boolean's maps had them.
  std::map<std::pair<int, int>, int> face_of_directed, directed_count;
  for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
    const int n = static_cast<int>(faces[f].size());
    for (int c = 0; c < n; ++c) {
      face_of_directed[{faces[f][c], faces[f][(c + 1) % n]}] = f;
      ++directed_count[{faces[f][c], faces[f][(c + 1) % n]}];
    }
  }
  bool closed = true;
  for (const auto& [key, count] : directed_count) {
    const auto reverse = directed_count.find({key.second, key.first});
    closed = closed && key.first != key.second && count == 1 && reverse != directed_count.end() && reverse->second == 1;
  }
  EXPECT_EQ(topology.Closed(), closed);
  for (int v = 0; v < num_vertices; ++v) {
    for (int w = 0; w < num_vertices; ++w) {
      const auto it = face_of_directed.find({v, w});
      EXPECT_EQ(topology.EdgeFace(v, w), it == face_of_directed.end() ? -1 : it->second) << v << " -> " << w;
    }
  }
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

TEST(HalfedgeTopology, ClosedCube) {
  const Mesh cube = MakeCube(2);
  ExpectMatchesBruteForce(cube.faces, cube.NumVertices());
  EXPECT_TRUE(HalfedgeTopology(cube.faces, cube.NumVertices()).Manifold());
  EXPECT_TRUE(HalfedgeTopology(cube.faces, cube.NumVertices()).Closed());
}

TEST(HalfedgeTopology, TriangleList) {
  // The cube split along its 0-2 diagonals, with one triangle repeated (a third face on edges).
  const Mesh cube = MakeCube(2);
  std::vector<std::array<int, 3>> triangles;
  for (const Polygon& f : cube.faces) {
    triangles.push_back({f[0], f[1], f[2]});
    triangles.push_back({f[0], f[2], f[3]});
  }
  for (const bool repeat : {false, true}) {
    if (repeat) triangles.push_back(triangles[3]);
    std::vector<Polygon> polygons;
    for (const auto& t : triangles) polygons.push_back({t[0], t[1], t[2]});
    ExpectMatchesBruteForce(polygons, cube.NumVertices());
    const HalfedgeTopology from_triangles(triangles, cube.NumVertices());
    const HalfedgeTopology from_polygons(polygons, cube.NumVertices());
    ASSERT_EQ(from_triangles.NumEdges(), from_polygons.NumEdges());
    for (int e = 0; e < from_polygons.NumEdges(); ++e) {
      EXPECT_EQ(from_triangles.EdgeVertices(e), from_polygons.EdgeVertices(e));
    }
    EXPECT_EQ(from_triangles.Closed(), !repeat);
    EXPECT_EQ(from_triangles.EdgeFace(triangles[3][0], triangles[3][1]), repeat ? 12 : 3);
  }
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
