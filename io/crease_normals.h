// Unoriented normals of a point cloud that stay sharp beside creases.
#pragma once

#include "core/mesh.h"

namespace opgraph {

// Each point's normal is the plane of the flattest `k`-neighbourhood among its own and its
// neighbours' that it lies on (a shifted neighbourhood, after Boulch and Marlet's robust normal
// estimation): a point beside a box's edge takes its face's plane from a neighbourhood that
// stays on that face, where its own neighbourhood's plane (PCA) averages the two faces and
// tilts up to 45 degrees. On smooth parts every neighbourhood is about as flat and the point
// keeps its own. `points` #P; returns #P unit normals, signs arbitrary.
Positions<double> CreasePreservingNormals(const Positions<double>& points, int k);

}  // namespace opgraph
