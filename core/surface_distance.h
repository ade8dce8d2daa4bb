// Point-to-surface distances between polygon meshes (a polygon's surface: the union of its fan
// triangulations from every corner, so it does not depend on where the loop starts), used for
// parity checks against Blender. Exact closest-point queries (core/nearest.h's bounding-volume
// hierarchy).
#pragma once

#include "core/mesh.h"

namespace opgraph {

// Largest distance from the sample points of `from` (vertices, edge midpoints, and the
// centroid and 4 seeded random points of each of those triangles) to the surface of `to`.
double MaxPointToSurfaceDistance(const Mesh& from, const Mesh& to);

// max(MaxPointToSurfaceDistance(a, b), MaxPointToSurfaceDistance(b, a)) divided by the
// bounding-box diagonal of `a`.
double SymmetricSurfaceDistanceRelative(const Mesh& a, const Mesh& b);

double BoundingBoxDiagonal(const Mesh& mesh);

}  // namespace opgraph
