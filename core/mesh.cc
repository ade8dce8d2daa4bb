#include "core/mesh.h"

#include <cmath>
#include <unordered_set>

namespace opgraph {

int Mesh::NumEdges() const {
  std::unordered_set<long long> edges;
  for (const Polygon& f : faces) {
    for (size_t i = 0; i < f.size(); ++i) edges.insert(EdgeKey(f[i], f[(i + 1) % f.size()]));
  }
  return static_cast<int>(edges.size());
}

std::string Mesh::Validate() const {
  for (size_t v = 0; v < vertices.size(); ++v) {
    if (!vertices[v].allFinite()) return "vertex " + std::to_string(v) + " has a non-finite coordinate";
  }
  for (size_t f = 0; f < faces.size(); ++f) {
    if (faces[f].size() < 3) return "face " + std::to_string(f) + " has fewer than 3 vertices";
    for (int v : faces[f]) {
      if (v < 0 || v >= NumVertices()) {
        return "face " + std::to_string(f) + " references missing vertex " + std::to_string(v);
      }
    }
  }
  return "";
}

Mesh MakeCube(double size) {
  // Vertex and face order of Blender's bmo_create_cube_exec.
  static const double kVerts[8][3] = {{-1, -1, -1}, {-1, -1, 1}, {-1, 1, -1}, {-1, 1, 1},
                                      {1, -1, -1},  {1, -1, 1},  {1, 1, -1},  {1, 1, 1}};
  static const int kFaces[6][4] = {{0, 1, 3, 2}, {2, 3, 7, 6}, {6, 7, 5, 4},
                                   {4, 5, 1, 0}, {2, 6, 4, 0}, {7, 3, 1, 5}};
  Mesh mesh;
  const double half = size / 2;
  for (const auto& v : kVerts) mesh.vertices.emplace_back(v[0] * half, v[1] * half, v[2] * half);
  for (const auto& f : kFaces) mesh.faces.push_back({f[0], f[1], f[2], f[3]});
  return mesh;
}

}  // namespace opgraph
