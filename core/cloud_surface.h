// The surface a point cloud with normals stands for, as a distance: from a query p to the cloud
// point q nearest it (normal n, local spacing s),
//   d(p) = sqrt((n . (p - q))^2 + max(0, |t| - s)^2),   t = (p - q) - (n . (p - q)) n,
// the distance to q's tangent plane plus whatever of the offset along the plane exceeds the
// spacing. So a point of the sampled surface between cloud points is at ~0 (the nearest-point
// distance would be ~half the spacing everywhere: a floor larger than a good fit's error), and a
// point past the cloud's edge is still as far as it is. s is the distance from q to its
// kSpacingNeighbours-th nearest other point: for evenly spread samples, a point of the surface
// lies farther than that from its nearest sample with probability ~exp(-4).
#pragma once

#include <memory>
#include <vector>

#include "core/mesh.h"

namespace opgraph {

class PointTree;

class CloudSurface {
 public:
  static constexpr int kSpacingNeighbours = 4;
  // `points` #N by 3, `normals` #N by 3 (unit; the sign does not matter). Keeps references.
  CloudSurface(const Positions<double>& points, const Positions<double>& normals);
  ~CloudSurface();
  CloudSurface(const CloudSurface&) = delete;
  CloudSurface& operator=(const CloudSurface&) = delete;

  double Distance(const Vec3d& query) const;

 private:
  const Positions<double>& points_;
  const Positions<double>& normals_;
  std::unique_ptr<PointTree> tree_;
  std::vector<double> spacing_;
};

}  // namespace opgraph
