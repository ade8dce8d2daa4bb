// HalfedgeTopology against brute force over the face list, on manifold, open and non-manifold
// inputs (a third face on an edge, a flipped face, two closed fans at one vertex, a face that
// repeats a vertex); OrientAgainstNeighbours against a breadth-first pass over an edge map.
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

// The orientation pass Bevel had before OrientAgainstNeighbours: an edge -> faces map.
std::vector<Polygon> OrientedByEdgeMap(int num_oriented, std::vector<Polygon> faces) {
  std::map<std::pair<int, int>, std::vector<int>> users;
  for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
    for (size_t c = 0; c < faces[f].size(); ++c) users[Undirected(faces[f][c], faces[f][(c + 1) % faces[f].size()])].push_back(f);
  }
  std::vector<bool> oriented(faces.size(), false);
  std::vector<int> queue;
  for (int f = 0; f < num_oriented; ++f) {
    oriented[f] = true;
    queue.push_back(f);
  }
  for (size_t next = 0; next < queue.size(); ++next) {
    const Polygon face = faces[queue[next]];
    for (size_t c = 0; c < face.size(); ++c) {
      const int a = face[c], b = face[(c + 1) % face.size()];
      for (int g : users[Undirected(a, b)]) {
        if (oriented[g]) continue;
        for (size_t d = 0; d < faces[g].size(); ++d) {
          if (faces[g][d] == a && faces[g][(d + 1) % faces[g].size()] == b) {
            std::reverse(faces[g].begin(), faces[g].end());
            break;
          }
        }
        oriented[g] = true;
        queue.push_back(g);
      }
    }
  }
  return faces;
}

void ExpectOrientedAsByEdgeMap(int num_oriented, const std::vector<Polygon>& faces) {
  std::vector<Polygon> got = faces;
  OrientAgainstNeighbours(num_oriented, &got);
  EXPECT_EQ(got, OrientedByEdgeMap(num_oriented, faces));
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

TEST(OrientAgainstNeighbours, MatchesAnEdgeMapPass) {
  // A 3 x 1 strip of quads, the first oriented, the others wound either way.
  ExpectOrientedAsByEdgeMap(1, {{0, 1, 5, 4}, {1, 2, 6, 5}, {6, 7, 3, 2}});
  ExpectOrientedAsByEdgeMap(1, {{0, 1, 5, 4}, {5, 6, 2, 1}, {2, 3, 7, 6}});
  // A third face on an edge, a face reached from two sides, and a face nothing reaches.
  ExpectOrientedAsByEdgeMap(1, {{0, 1, 2}, {0, 1, 3}, {1, 0, 4}, {3, 1, 4}, {5, 6, 7}});
  // Two oriented faces; a fan of triangles between them.
  ExpectOrientedAsByEdgeMap(2, {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 4, 1}, {5, 1, 4}, {1, 5, 2}, {6, 2, 5}});
  // The cube with its faces' windings mixed, from one face.
  Mesh cube = MakeCube(2);
  for (size_t f = 1; f < cube.faces.size(); f += 2) std::reverse(cube.faces[f].begin(), cube.faces[f].end());
  ExpectOrientedAsByEdgeMap(1, cube.faces);
  // ... comes out consistent: every edge run once each way.
  OrientAgainstNeighbours(1, &cube.faces);
  std::set<std::pair<int, int>> directed;
  for (const Polygon& face : cube.faces) {
    for (size_t c = 0; c < face.size(); ++c) EXPECT_TRUE(directed.insert({face[c], face[(c + 1) % face.size()]}).second);
  }
}

}  // namespace
}  // namespace opgraph
