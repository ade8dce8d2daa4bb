#include "ops/replay_guards.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <map>
#include <set>

#include "core/surface_distance.h"
#include "ops/sequence_op_names.h"

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
  return SubdividesTwoEdgeVertexIn(SequenceOpNames(document), steps);
}

bool NearGeometricBranch(const Sequence& evaluated, const std::vector<Mesh>& steps) {
  for (size_t k = 0; k < evaluated.ops.size() && k < steps.size(); ++k) {
    const Positions<double>& input = k == 0 ? evaluated.StartMesh().vertices : steps[k - 1].vertices;
    if (evaluated.ops[k]->NearGeometricBranch(evaluated.gates[k], input)) return true;
  }
  return false;
}

namespace {

// The output of `op` (a fresh copy at its parameters and `gate`) on `input`, as a sorted list of
// faces, each the sorted corner positions on a grid of 1e-9 of the diagonal: equal for the same
// polygons whatever their numbering and loop starts.
std::vector<std::vector<std::array<long long, 3>>> OutputPolygons(const Op& op, double gate, const Mesh& input) {
  const std::unique_ptr<Op> copy = CreateOp(op.Name(), op.ParamsToJson());
  copy->Prepare(input);
  Positions<double> positions;
  copy->Evaluate(copy->params().data(), gate, input.vertices, &positions);
  const double cell = 1e-9 * std::max(BoundingBoxDiagonal(input), 1e-300);
  std::vector<std::vector<std::array<long long, 3>>> polygons;
  for (const Polygon& face : copy->OutputFaces(gate)) {
    std::vector<std::array<long long, 3>> corners;
    for (int v : face) {
      const Vec3d& p = positions[v];
      corners.push_back({std::llround(p.x() / cell), std::llround(p.y() / cell), std::llround(p.z() / cell)});
    }
    std::sort(corners.begin(), corners.end());
    polygons.push_back(corners);
  }
  std::sort(polygons.begin(), polygons.end());
  return polygons;
}

// Whether `op`'s output polygons on `input` change when face f starts its loop at another corner.
bool OutputFollowsLoopStart(const Op& op, double gate, const Mesh& input, int f) {
  try {
    const auto polygons = OutputPolygons(op, gate, input);
    Mesh turned = input;
    Polygon& face = turned.faces[f];
    for (size_t turn = 1; turn < face.size(); ++turn) {
      std::rotate(face.begin(), face.begin() + 1, face.end());
      if (OutputPolygons(op, gate, turned) != polygons) return true;
    }
    return false;
  } catch (const FieldError&) {
    return true;  // refused at some loop start
  }
}

}  // namespace

bool HolesAFaceOfUnknownLoopStart(const Sequence& evaluated, const std::vector<Mesh>& steps) {
  const Mesh start = evaluated.StartMesh();
  std::vector<bool> unknown(start.faces.size(), false);  // per face of the op's input
  for (size_t k = 0; k < evaluated.ops.size() && k < steps.size(); ++k) {
    const Op& op = *evaluated.ops[k];
    const double gate = evaluated.gates[k];
    const Mesh& input_mesh = k == 0 ? start : steps[k - 1];
    for (int f : op.FacesWhoseLoopStartDecides(gate)) {
      if (unknown[f] && OutputFollowsLoopStart(op, gate, input_mesh, f)) return true;
    }
    const std::vector<Polygon>& input = input_mesh.faces;
    const std::vector<Polygon>& output = op.OutputFaces(gate);
    const bool any_unknown = std::find(unknown.begin(), unknown.end(), true) != unknown.end();
    std::vector<bool> next;
    if (!any_unknown) {
      next.assign(output.size(), false);
    } else if (output == input) {
      next = unknown;
    } else {
      std::map<Polygon, int> input_index;
      for (size_t f = 0; f < input.size(); ++f) input_index.emplace(input[f], static_cast<int>(f));
      for (const Polygon& face : output) {
        const auto kept = input_index.find(face);
        next.push_back(kept == input_index.end() || unknown[kept->second]);
      }
    }
    for (int f : op.FacesOfUnknownLoopStart(gate)) next[f] = true;
    unknown = std::move(next);
  }
  return false;
}

bool BreaksReplay(const Sequence& evaluated, const std::vector<Mesh>& steps) {
  std::vector<std::string> names;
  for (const auto& op : evaluated.ops) names.push_back(op->Name());
  return HasCollapsedEdge(steps) || SubdividesTwoEdgeVertexIn(names, steps) || NearGeometricBranch(evaluated, steps) ||
         HolesAFaceOfUnknownLoopStart(evaluated, steps);
}

}  // namespace opgraph
