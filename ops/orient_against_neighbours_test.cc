// OrientAgainstNeighbours against the breadth-first pass over an edge map Bevel had before it.
#include "ops/orient_against_neighbours.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

namespace opgraph {
namespace {

std::pair<int, int> Undirected(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

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
