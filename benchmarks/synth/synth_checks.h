// Degeneracy checks of a sampled sequence, with the engine's own tools: a model is rejected when
// it is not a clean solid (self-intersecting extrusions, open or non-manifold), has collapsed
// edges, would not rebuild the same in Blender (ops/replay_guards.h), or when a shorter
// sequence builds the same surface (an op that does nothing: a Boolean that misses, a knife cut
// nothing uses).
#pragma once

#include <string>
#include <vector>

#include "core/mesh.h"
#include "ops/params.h"

namespace opgraph {
namespace synth {

struct CheckLimits {
  double min_edge_fraction = 5e-4;  // of the bounding-box diagonal, at every step
  double max_aspect = 15;           // longest over shortest bounding-box side
  double same_surface = 1e-5;       // of the diagonal: an op whose removal stays within it is redundant
};

// Empty when `document` (whose evaluated steps are `steps`) is a proper model, else the reason,
// as a short key ("redundant op", "self-intersecting", ...) for the rejection statistics.
std::string DegenerateProblem(const Json& document, const std::vector<Mesh>& steps, const CheckLimits& limits = {});

// Genus of a closed surface, summed over its parts: (2 parts - (V - E + F)) / 2.
int Genus(const Mesh& mesh);
int NumParts(const Mesh& mesh);

}  // namespace synth
}  // namespace opgraph
