// The paper's Boolean weight beta on an Extrude ("Generating Human-AI Collaborative Design
// Sequence for 3D Assets via Differentiable Operation Graph", arXiv 2508.17645): a logit block
// with beta = sigmoid(logit) lets an extrusion turn into a Boolean DIFFERENCE with the prism
// its cap sweeps, in our least-squares form (docs/fitting.md, "Boolean weight"):
//   - output-to-target residuals of samples on the faces the extrusion created (cap and side
//     quads) are scaled by sqrt(1 - beta);
//   - output-to-target residuals of samples on B's own faces (below) are scaled by sqrt(beta),
//     so both surfaces are also held to the target from their side;
//   - each target-to-output term is the mixture (1 - beta) d_E^2 + beta d_B^2 of the target
//     point's squared distance to the extruded surface E (the output) and to the Boolean
//     surface B, as two residuals scaled by sqrt(1 - beta) and sqrt(beta).
// B, for an inward extrusion (height < 0): the input surface with the region's face replaced
// by the rim left around the prism's top (quads between the region's boundary and the cap's
// boundary projected along the extrusion normal onto the region's plane), the prism's walls
// (from the cap's boundary up to that projection) and its floor (the cap). This is the exact
// difference's surface while the prism stays inside the solid; where it pierces the solid (a
// through hole) the walls below the solid and the floor are kept: they only shorten distances
// of target points near them. For an outward extrusion the prism is outside the solid and B
// is the input surface.
// Points of B that are not output vertices (the projected cap corners, the region's interior
// vertices at their input positions) are an output vertex plus an offset fixed at each
// correspondence update, like the correspondences themselves.
#pragma once

#include <string>
#include <vector>

#include "core/nearest.h"
#include "residuals/correspondence_cost.h"
#include "program/program.h"

namespace opgraph {

// A triangulated surface over the program's output vertices and extra points: point i is
// output vertex base[i] plus offset[i] (zero for i < #output vertices, which are themselves).
struct VirtualSurface {
  Positions<double> positions;
  std::vector<int> base;
  Positions<double> offset;
  std::vector<MeshTriangle> triangles;
  int first_own_face = 0;  // triangles of faces from here on are B's own (not the output's)
};

// B (above) for the Extrude at op `op`, the program's last op, at the program's current
// evaluation.
VirtualSurface BooleanSurface(const Program& program, int op);

// The correspondence of the point at `barycentric` in `triangle` of `surface` with a target
// point.
SurfaceCorrespondence CorrespondenceOnSurface(const VirtualSurface& surface, int triangle, const Vec3d& barycentric,
                                              const Vec3d& target_point, const Vec3d& target_normal);

// The sequence with the Extrude at op `op` (inward, region mode) replaced by the exact Boolean
// DIFFERENCE that beta -> 1 stands for: a cube spanning the cap's extent in its frame (u along
// the cap's first boundary edge turned by 0.01 degree about n, see the .cc; w = n x u, n the
// region's normal) and, along n, from the
// deepest cap vertex to a margin of 10 % of the depth above the region's plane (so no face of
// the cube is coplanar with the surface). Exact for a rectangular cap; another cap shape gets
// its bounding rectangle. Throws std::invalid_argument (one line) when op `op` is not such an
// Extrude, SequenceError when the sequence does not evaluate.
Json ExtrudeToBoolean(const Sequence& sequence, int op);

}  // namespace opgraph
