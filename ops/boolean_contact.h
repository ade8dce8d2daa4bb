// A replay guard of BooleanOp (ops/boolean.h): operands that touch within Blender's float32
// rounding.
#pragma once

#include "core/mesh.h"

namespace opgraph {

// Off a plane by less than this fraction of the largest coordinate (of either operand), a vertex
// is on the plane, in front of it or behind it in Blender by how float32 rounds both: its single
// precision resolves 6e-8 of a coordinate, and a primitive's vertices carry the rounding of its
// object matrix too.
constexpr double kFloat32Contact = 1e-6;

// How the vertices of each operand sit against the triangles (as Blender's exact boolean
// triangulates them) of the other, over a triangle: `near` counts vertices off such a
// triangle's plane by less than kFloat32Contact of the coordinates' scale but not exactly on
// it, `exact` the others exactly on one.
struct OperandContacts {
  int exact = 0;
  int near = 0;
};
OperandContacts CountOperandContacts(const Mesh& input, const Mesh& primitive);

}  // namespace opgraph
