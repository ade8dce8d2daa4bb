// Consistent orientation of a point cloud's unoriented normals (CGAL's mst_orient_normals,
// Hoppe et al. 1992): the orientation is propagated along a minimum spanning tree of the
// neighbour graph, weighted by how far neighbouring normals are from parallel, from the highest
// point, whose normal is turned to +Z. So the normals of a concave part (a table top's underside,
// a bowl's inside) point out of the surface, where "away from the centroid" turns them inwards.
#pragma once

#include "core/mesh.h"

namespace opgraph {

// `points` #P, `normals` #P unit normals (any signs), flipped in place where the propagation
// reaches them (points off the neighbour graph's main component keep theirs). `k` neighbours
// per point. Deterministic for a given input.
void OrientNormalsConsistently(const Positions<double>& points, int k, Positions<double>* normals);

}  // namespace opgraph
