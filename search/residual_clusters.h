// Residual analysis as 3-D clusters: where the target lies beyond the cage (material to add) and
// where the cage lies beyond the target (material to remove), each cluster with a box along
// its principal axes. The Boolean proposals fit primitives to these boxes.
#pragma once

#include <vector>

#include "search/layout.h"
#include "solver/target.h"

namespace opgraph {

struct ResidualCluster {
  bool excess = false;        // the cage lies beyond the target here (remove), else the target (add)
  int num_samples = 0;
  Vec3d centre;               // of the box, in the cage's frame
  Eigen::Matrix3d axes;       // principal axes (columns, right-handed), in the cage's frame
  Vec3d extents;              // the box's full extents along the axes
};

// Clusters of target samples outside the cage and of cage samples outside the target, beyond 3%
// of the posed cube's diagonal, joined over a grid of 5% of it; clusters of under 1% of the
// samples are dropped. Each box reaches to the other surface (a union's primitive overlaps the
// cage, a difference's cuts through its surface) with a margin of 3% of the diagonal. Largest
// first. With `interior`, also the clusters of target samples inside the cage beyond 3% of
// the diagonal (a hole's or a notch's walls under the cage: material to remove, whose box is
// the target's own surface there), largest first. Throws what the sequence's evaluation throws.
std::vector<ResidualCluster> FindResidualClusters(const Target& target, const Layout& layout,
                                                  std::vector<ResidualCluster>* interior = nullptr);

}  // namespace opgraph
