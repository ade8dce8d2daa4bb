// Domain rules of a modeller's sequence, as soft parameter ranges for the fits.
#pragma once

#include "ops/params.h"
#include "solver/fitter.h"

namespace opgraph {

// `options` with the rules for the ops of `document` added: an extrusion tilts by at most 45
// degrees (beyond that its side walls fold over the cap: a shear, not an extrusion) and scales
// its cap by 0.1 to 10 (a fit once shrank a face to a speck with an inset and blew it up 370
// times, which multiplies Blender's float32 rounding into the replay); an inset keeps a rim of
// at least 1% of `min_half_extent`, the posed cube's smallest half extent (a zero rim is a
// degenerate ring).
FitterOptions WithDomainRules(FitterOptions options, const Json& document, double min_half_extent);

}  // namespace opgraph
