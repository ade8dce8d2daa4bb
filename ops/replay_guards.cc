#include "ops/replay_guards.h"

#include <set>

#include "core/surface_distance.h"

namespace opgraph {

bool HasCollapsedEdge(const std::vector<Mesh>& steps, double fraction) {
  for (const Mesh& mesh : steps) {
    const double min_length = fraction * BoundingBoxDiagonal(mesh);
    for (const Polygon& face : mesh.faces) {
      for (size_t i = 0; i < face.size(); ++i) {
        if ((mesh.vertices[face[i]] - mesh.vertices[face[(i + 1) % face.size()]]).norm() < min_length) return true;
      }
    }
  }
  return false;
}

bool SubdividesTwoEdgeVertex(const Json& document, const std::vector<Mesh>& steps) {
  const Json& ops = document.at("operations");
  for (size_t k = 1; k < ops.size() && k < steps.size(); ++k) {
    if (ops[k].at("op") != "Subdivision") continue;
    const Mesh& input = steps[k - 1];
    std::vector<std::set<int>> neighbours(input.vertices.size());
    for (const Polygon& face : input.faces) {
      for (size_t i = 0; i < face.size(); ++i) {
        const int a = face[i], b = face[(i + 1) % face.size()];
        neighbours[a].insert(b), neighbours[b].insert(a);
      }
    }
    for (const std::set<int>& n : neighbours) {
      if (n.size() == 2) return true;
    }
  }
  return false;
}

bool BreaksReplay(const Json& document, const std::vector<Mesh>& steps) {
  return HasCollapsedEdge(steps) || SubdividesTwoEdgeVertex(document, steps);
}

}  // namespace opgraph
