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

namespace {

// `names`: the op names of the sequence `steps` came from.
bool SubdividesTwoEdgeVertexIn(const std::vector<std::string>& names, const std::vector<Mesh>& steps) {
  for (size_t k = 1; k < names.size() && k < steps.size(); ++k) {
    if (names[k] != "Subdivision") continue;
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

}  // namespace

bool SubdividesTwoEdgeVertex(const Json& document, const std::vector<Mesh>& steps) {
  std::vector<std::string> names;
  for (const Json& op : document.at("operations")) names.push_back(op.at("op"));
  return SubdividesTwoEdgeVertexIn(names, steps);
}

bool NearGeometricBranch(const Sequence& evaluated, const std::vector<Mesh>& steps) {
  for (size_t k = 0; k < evaluated.ops.size() && k < steps.size(); ++k) {
    const Positions<double>& input = k == 0 ? evaluated.StartMesh().vertices : steps[k - 1].vertices;
    if (evaluated.ops[k]->NearGeometricBranch(evaluated.gates[k], input)) return true;
  }
  return false;
}

bool BreaksReplay(const Sequence& evaluated, const std::vector<Mesh>& steps) {
  std::vector<std::string> names;
  for (const auto& op : evaluated.ops) names.push_back(op->Name());
  return HasCollapsedEdge(steps) || SubdividesTwoEdgeVertexIn(names, steps) || NearGeometricBranch(evaluated, steps);
}

}  // namespace opgraph
