#include "ops/orient_against_neighbours.h"

#include <algorithm>

namespace opgraph {

void OrientAgainstNeighbours(int num_oriented, std::vector<Polygon>* faces) {
  // The edges of the faces to orient, listed at their lower vertex (a counting sort, so by face
  // there): a shared edge's faces are found among a vertex's handful of entries.
  struct EdgeUse {
    int high, face;
  };
  const int num_faces = static_cast<int>(faces->size());
  auto for_each_edge = [&](int f, auto visit) {
    const Polygon& face = (*faces)[f];
    for (size_t c = 0; c < face.size(); ++c) visit(face[c], face[(c + 1) % face.size()]);
  };
  int num_vertices = 0;
  for (int f = num_oriented; f < num_faces; ++f) {
    for (int v : (*faces)[f]) num_vertices = std::max(num_vertices, v + 1);
  }
  std::vector<int> first_use(num_vertices + 1, 0);  // vertex v's uses: first_use[v] ...
  for (int f = num_oriented; f < num_faces; ++f) {
    for_each_edge(f, [&](int a, int b) { ++first_use[std::min(a, b) + 1]; });
  }
  for (int v = 0; v < num_vertices; ++v) first_use[v + 1] += first_use[v];
  std::vector<EdgeUse> uses(first_use.back());
  std::vector<int> next_use(first_use.begin(), first_use.end() - 1);
  for (int f = num_oriented; f < num_faces; ++f) {
    for_each_edge(f, [&](int a, int b) { uses[next_use[std::min(a, b)]++] = {std::max(a, b), f}; });
  }
  std::vector<bool> oriented(num_faces, false);
  std::vector<int> queue;  // breadth first: faces in the order they were oriented
  for (int f = 0; f < num_oriented; ++f) {
    oriented[f] = true;
    queue.push_back(f);
  }
  for (size_t next = 0; next < queue.size(); ++next) {
    // Face queue[next] is never reversed again, so for_each_edge reads it while others change.
    for_each_edge(queue[next], [&](int a, int b) {
      const int low = std::min(a, b), high = std::max(a, b);
      if (low >= num_vertices) return;  // on no face to orient
      for (int k = first_use[low]; k < first_use[low + 1]; ++k) {
        const EdgeUse& use = uses[k];
        if (use.high != high || oriented[use.face]) continue;
        Polygon& other = (*faces)[use.face];
        for (size_t d = 0; d < other.size(); ++d) {
          if (other[d] == a && other[(d + 1) % other.size()] == b) {
            std::reverse(other.begin(), other.end());
            break;
          }
        }
        oriented[use.face] = true;
        queue.push_back(use.face);
      }
    });
  }
}

}  // namespace opgraph
