#include "benchmarks/synth/synth_checks.h"

#include <numeric>

#include "core/surface_distance.h"
#include "ops/boolean.h"
#include "ops/replay_guards.h"
#include "ops/sequence.h"

namespace opgraph {
namespace synth {
namespace {

// True when leaving out one op builds the same surface.
bool HasRedundantOp(const Json& document, const Mesh& result, double tolerance) {
  const Json& ops = document.at("operations");
  for (size_t skip = 0; skip < ops.size(); ++skip) {
    Json shorter = document;
    shorter["operations"].erase(skip);
    try {
      Sequence sequence = ParseSequence(shorter);
      const std::vector<Mesh> steps = EvaluateSequence(&sequence);
      const Mesh& other = steps.empty() ? MakeCube(2.0) : steps.back();
      if (SymmetricSurfaceDistanceRelative(result, other) < tolerance) return true;
    } catch (const std::exception&) {  // a later op's target vanished: not the same build
    }
  }
  return false;
}

}  // namespace

std::string DegenerateProblem(const Json& document, const std::vector<Mesh>& steps, const CheckLimits& limits) {
  if (steps.empty()) return "empty";
  const Mesh& result = steps.back();
  if (HasCollapsedEdge(steps, limits.min_edge_fraction)) return "collapsed edge";
  if (SubdividesTwoEdgeVertex(document, steps)) return "two-edge vertex before Subdivision";
  Vec3d lo = result.vertices[0], hi = lo;
  for (const Vec3d& v : result.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  const Vec3d extent = hi - lo;
  if (extent.maxCoeff() > limits.max_aspect * extent.minCoeff()) return "too thin";
  // The result, and each cage a Subdivision smooths, must be clean solids.
  const Json& ops = document.at("operations");
  for (size_t k = 0; k < steps.size(); ++k) {
    const bool cage = k + 1 < steps.size() && ops[k + 1].at("op") == "Subdivision";
    if ((cage || k + 1 == steps.size()) && !SolidProblem(steps[k]).empty()) return "not a clean solid";
  }
  if (HasRedundantOp(document, result, limits.same_surface)) return "redundant op";
  return "";
}

int NumParts(const Mesh& mesh) {
  std::vector<int> parent(mesh.vertices.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const Polygon& face : mesh.faces) {
    for (int v : face) parent[find(v)] = find(face[0]);
  }
  int parts = 0;
  for (int v = 0; v < mesh.NumVertices(); ++v) parts += find(v) == v;
  return parts;
}

int Genus(const Mesh& mesh) {
  const int euler = mesh.NumVertices() - mesh.NumEdges() + mesh.NumFaces();
  return (2 * NumParts(mesh) - euler) / 2;
}

}  // namespace synth
}  // namespace opgraph
