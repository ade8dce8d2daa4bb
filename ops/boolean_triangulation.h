// The triangulations of Boolean's topology pass (ops/boolean.cc): its operands', as Blender's
// exact boolean triangulates them, and the constrained Delaunay flips it makes within each
// operand triangle; the two-sided edges both walk, in the order they are tried.
#pragma once

#include <array>
#include <vector>

#include "core/mesh.h"

namespace opgraph {

// One triangle of a mesh's triangulation and the polygon it belongs to.
struct SourceTriangle {
  std::array<int, 3> corners;
  int face;
};

// The coordinate axis along which triangle abc is largest in projection.
int DominantAxis(const Vec3d& a, const Vec3d& b, const Vec3d& c);

// An edge of a triangle list with a triangle on each side: `left` runs from -> to, `right`
// to -> from (from < to).
struct TwoSidedEdge {
  int from, to;
  int left, right;
};

// The two-sided edges of `triangles`, by (from, to): the order the flips and merges try them in
// (where a flip or a merge blocks the next one, the order decides the result).
std::vector<TwoSidedEdge> TwoSidedEdges(const std::vector<std::array<int, 3>>& triangles, int num_vertices);

// Flips edges between triangles of the same group (>= 0) until each is locally Delaunay in the
// projection of triangle t along coordinate axis[t]: the constrained Delaunay triangulation of
// each group, with the group's outline as constraints. A cocircular tie is never flipped.
void DelaunayFlips(const Positions<double>& vertices, const std::vector<int>& group, const std::vector<int>& axis,
                   std::vector<std::array<int, 3>>* triangles);

// Blender's triangulation of the boolean's operands (mesh_boolean's triangulate_poly), each
// triangle with its polygon; see ops/boolean_triangulation.cc.
std::vector<SourceTriangle> Triangulate(const Mesh& mesh);

}  // namespace opgraph
