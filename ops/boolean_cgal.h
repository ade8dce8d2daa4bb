// Exact mesh boolean of two closed triangle meshes through CGAL's corefinement. This is the
// only translation unit that includes CGAL (it takes ~70 s and 1.7 GB to compile), so the
// interface is plain: triangle soups in, a triangle soup out.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/mesh.h"

namespace opgraph {

struct TriangleSoup {
  Positions<double> vertices;              // #V
  std::vector<std::array<int, 3>> triangles;  // #T, counter-clockwise seen from outside
};

enum class BooleanKind { kUnion, kDifference };

// out = a (kind) b, outward oriented. Returns an empty string on success, else a one-line
// description of why the inputs cannot be combined (not closed, not manifold, self-intersecting,
// not bounding a volume, or CGAL's own refusal).
std::string CgalBoolean(const TriangleSoup& a, const TriangleSoup& b, BooleanKind kind, TriangleSoup* out);

// Empty when `soup` is a closed, manifold, non-self-intersecting surface bounding a volume,
// else a one-line description of why not (`name` names it in the message).
std::string CgalSolidProblem(const TriangleSoup& soup, const std::string& name);

}  // namespace opgraph
