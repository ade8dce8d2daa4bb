// Shapes built by known sequences that several tests recover.
#pragma once

#include <vector>

#include "ops/builders.h"

namespace opgraph {

// A block with a slot cut through it along Z, off its centre and turned 9 degrees about the
// slot's axis: GlobalAffineScale, then one Boolean difference with a box.
inline std::vector<Json> SlottedBlock() {
  build::BooleanArgs slot;
  slot.difference = true;
  slot.size = Vec3d(0.45, 0.3, 3.0);
  slot.rotation_deg = Vec3d(0, 0, 9);
  slot.location = Vec3d(0.45, -0.35, 0.0);
  return {build::GlobalScale(Vec3d(1.0, 0.8, 0.6)), build::Boolean(slot)};
}

}  // namespace opgraph
