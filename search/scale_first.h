// Writes a sequence the way a modeller orders it: the whole-object scale first, then the loop
// cuts and loop scales that the controller fits on the unit cube.
#pragma once

#include "ops/params.h"

namespace opgraph {

// `document` with its first GlobalAffineScale moved to the front, when every op before it is a
// LoopCut, EdgeLoopAffineScale or EdgeLoopAffineTranslate. Those commute with a scale S
// (diagonal, about the origin) once their geometric arguments are mapped through it: LoopCut's
// `near` and the vertex boxes become S times themselves, a loop translation's offset becomes
// S times itself; a loop scale is diagonal about the loop's median, so it is unchanged.
// Returns `document` unchanged when the rule does not apply. The caller checks that the result
// evaluates to the same mesh (a seed-edge tie can resolve differently after the scale).
Json ScaleFirst(const Json& document);

}  // namespace opgraph
