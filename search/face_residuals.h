// Residual analysis per cage face: target samples, brought into the cube's frame, assigned to
// the cage face holding their closest cage point, split into those far outside and far inside
// along its normal.
#pragma once

#include <vector>

#include "core/mesh.h"
#include "search/layout.h"
#include "solver/target.h"

namespace opgraph {

struct FaceResiduals {
  Mesh cage;                     // the layout's mesh before Subdivision and the pose
  std::vector<Vec3d> centroids;  // #faces
  std::vector<Vec3d> normals;    // #faces, unit
  std::vector<double> areas;     // #faces, twice each face's area (|FaceAreaNormal|)
  // Per face: distances along the normal of the samples beyond the threshold outside and inside.
  std::vector<std::vector<double>> outside, inside;
  // Per face: mean squared distance of the outside samples from the face's normal line.
  std::vector<double> outside_spread;
  // Per face: the outside samples over the face's middle (within 0.3 of its side of the
  // centroid, across the normal): a protrusion standing on the face has its cap there, while
  // a protrusion beside it only lends the face the samples of its side wall, over an edge.
  std::vector<size_t> outside_middle;
  // Per face: an opening (a vessel's mouth, a recess): no target surface near the face's middle
  // and a floor under it. Depth of the floor along -normal (0: not an opening) and the width of
  // the rim around the opening (an Inset's thickness).
  std::vector<double> opening_depth, opening_rim;
  size_t num_samples = 0;  // about the number of samples analysed
};

// Samples beyond 4% of the posed cube's diagonal count (and within it, cover a face's middle).
// Throws what the sequence's evaluation throws.
FaceResiduals ComputeFaceResiduals(const Target& target, const Layout& layout);

}  // namespace opgraph
