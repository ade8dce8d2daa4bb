// The largest run of a target where its section across an axis is one constant rectangle: a
// box body that the rest of the shape grows from (search/propose_body.cc).
#pragma once

#include <utility>
#include <vector>

#include "core/geometry.h"

namespace opgraph {

struct BoxBody {
  double volume = 0;
  Vec3d lo, hi;  // in the frame of the samples
};

// Along each axis, the largest run of bins (50 over the samples' box [lo, hi]) whose section is
// one constant rectangle (the samples on its sides), spanning at least a fifth of the box and
// leaving at least a twentieth; none along an axis where a bin is empty (parts apart along it
// are not grown from one another). Largest body first, each with its axis.
// `local`: #samples points in the frame's coordinates.
std::vector<std::pair<int, BoxBody>> FindBoxBodies(const std::vector<Vec3d>& local, const Vec3d& lo, const Vec3d& hi);

}  // namespace opgraph
