// The largest run of a target where its section across an axis is one constant rectangle: a
// box body that the rest of the shape grows from (search/propose_body.cc).
#pragma once

#include <utility>
#include <vector>

#include "core/geometry.h"

namespace opgraph {

constexpr int kBodyBins = 50;

struct BoxBody {
  double volume = 0;
  Vec3d lo, hi;  // in the frame of the samples
};

// Along `axis`, binned in kBodyBins over the samples' box [lo, hi]: of the runs of bins whose
// section is one constant rectangle (the samples on its sides), spanning at least a fifth of
// the box and leaving at least a twentieth, the one with the largest box. False when there is
// none or a bin is empty (parts apart along the axis are not grown from one another).
// `local`: #samples points in the frame's coordinates.
bool FindBoxBody(const std::vector<Vec3d>& local, int axis, const Vec3d& lo, const Vec3d& hi, BoxBody* body);

// FindBoxBody along each axis that has a body, largest first (each with its axis).
std::vector<std::pair<int, BoxBody>> FindBoxBodies(const std::vector<Vec3d>& local, const Vec3d& lo, const Vec3d& hi);

}  // namespace opgraph
