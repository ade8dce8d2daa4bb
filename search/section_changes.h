// Where the target's section changes on all sides at once: the mark of a loop's scale.
#pragma once

#include <vector>

#include "core/geometry.h"

namespace opgraph {

constexpr int kSectionBins = 24;

// For each axis of a frame, how far the section across it grows or shrinks on all four sides
// at once, as a loop's scale does (an Extrude or a boss moves one or two sides): along the axis
// in kSectionBins bins (the end bins left out: end faces and rims), each side's half-width
// from the box's centre relative to that side's median over the bins; a bin's change is the
// smallest of its four relative changes when all four have one sign, else 0; the axis's value
// is the largest over its bins (0.3: a loop 30% wider or narrower than the usual section).
// `local`: #samples points in the frame's coordinates.
Vec3d SectionChanges(const std::vector<Vec3d>& local);

}  // namespace opgraph
