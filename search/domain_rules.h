// Domain rules of a modeller's sequence, as soft parameter ranges for the fits.
#pragma once

#include "ops/params.h"
#include "solver/fitter.h"

namespace opgraph {

// `options` with the rules for the ops of `document` added: an extrusion tilts by at most 45
// degrees (beyond that its side walls fold over the cap: a shear, not an extrusion) and scales
// its cap by 0.1 to 10 (a fit once shrank a face to a speck with an inset and blew it up 370
// times, which multiplies Blender's float32 rounding into the replay); an inset keeps a rim of
// at least 1% of the posed cube's smallest half extent (a zero rim is a degenerate ring);
// when the posed box is a sheet (under 1% as thick as it is long), the cube's global scale keeps
// every side at least 1e-3 of its largest `half_extent` (a flat target would squash it until its
// edges collapse); and a Boolean's primitive spans at most kMaxBooleanSize times the largest
// half extent along each of its axes (so its float32 corners in Blender stay precise).
constexpr double kMaxBooleanSize = 8.0;
FitterOptions WithDomainRules(FitterOptions options, const Json& document, const Vec3d& half_extent);

}  // namespace opgraph
