// The cube placed on the target: the first state of the search.
#pragma once

#include "search/layout.h"
#include "solver/target.h"

namespace opgraph {

// The cube scaled to the target's box in the frame `world_from_local` (columns: the box's axes
// in world coordinates), rotated and translated onto it; along `slab_axis` (when >= 0) on
// [slab_lo, slab_hi] instead of the box. Sets the layout's frame.
Layout PoseLayout(const Target& target, const Eigen::Matrix3d& world_from_local, int slab_axis = -1,
                  double slab_lo = 0, double slab_hi = 0);

// The target's box in the frame `world_from_local` (coordinates along its columns).
void LocalBox(const Target& target, const Eigen::Matrix3d& world_from_local, Vec3d* lo, Vec3d* hi);

// The target's samples in the frame `world_from_local`, at most about 20,000 (every k-th).
std::vector<Vec3d> LocalSamples(const Target& target, const Eigen::Matrix3d& world_from_local);

// Which of `bins` equal bins over [lo, hi] holds `x` (values outside go to the end bins).
int BinOf(double x, double lo, double hi, int bins);

// The cube on the box [lo, hi] of the frame `world_from_local` (coordinates along its columns).
Layout PoseLayoutOnBox(const Eigen::Matrix3d& world_from_local, const Vec3d& lo, const Vec3d& hi);

// A frame of principal axes of the target's samples (columns, right-handed). Axes of (near)
// equal variance are arbitrary (a plus sign, a square plate, a cylinder): when two are, the
// pair is turned about the third axis to the smallest bounding rectangle (a plus sign's arms,
// a plate's sides); when all three are, the coordinate axes are used.
Eigen::Matrix3d PrincipalFrame(const Target& target);

// The axis along which the layout's cube is longest.
int LongAxis(const Layout& layout);

}  // namespace opgraph
