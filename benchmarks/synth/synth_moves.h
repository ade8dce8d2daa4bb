// The moves of the synthetic corpus' grammar, as a modeller uses them: block out the main form,
// add structure, finish. Each move appends one to a few ops to the draft through the typed
// builders of ops/builders.h, aiming them with the draft's geometric queries, and returns false
// (the draft unchanged or partly extended, but valid) when the engine refuses what it tried.
#pragma once

#include "benchmarks/synth/synth_draft.h"
#include "benchmarks/synth/synth_random.h"

namespace opgraph {
namespace synth {

enum class Proportion { kAny, kColumn, kSlab, kLong };

// Block out (synth_block_out.cc).
bool ScaleBlock(Draft* draft, Random* random, Proportion proportion);
// LoopCut across `axis` and EdgeLoopAffine Scale / Translate / Rotate of some of its loops.
bool Profile(Draft* draft, Random* random, int axis);
// A SimpleDeform (Twist, Bend, Taper or Stretch), after a LoopCut giving it resolution.
bool Deform(Draft* draft, Random* random, int main_axis);
// A slab with a 3 x 3 grid whose loops sit near its rim (table tops, seats, cabinets).
bool SlabGrid(Draft* draft, Random* random);

// Structure (synth_structure.cc, synth_parts.cc).
bool ExtrudeFace(Draft* draft, Random* random);
// Inset a face, then Extrude its inner face out (a boss, a panel) or in (a cavity, a vessel).
bool InsetExtrude(Draft* draft, Random* random, bool deep_cavity);
// Extrude many faces each on its own (panels on every face, buttons on a grid).
bool Panels(Draft* draft, Random* random);
// A chain of 2 to 4 extrusions from one face with a loop scale at a joint (limbs, spouts).
bool Chain(Draft* draft, Random* random);
// Legs extruded down from the corner faces of a slab grid, and maybe a backrest.
bool Legs(Draft* draft, Random* random);
bool Backrest(Draft* draft, Random* random);
// A Boolean union or difference with one of the four primitives, placed off-centre on a face.
bool BooleanFeature(Draft* draft, Random* random, bool difference);
// KnifeCut then VertexDisplace of the new vertices (facets, a ridge on a face).
bool Facets(Draft* draft, Random* random);
// A gable: LoopCut and the top vertices of the loop raised.
bool Ridge(Draft* draft, Random* random);
// The part moved off a symmetry plane and mirrored (pairs, four of a kind), maybe joined by a
// Boolean union bar.
bool MirrorPair(Draft* draft, Random* random);

// Finish (synth_finish.cc).
bool BevelFinish(Draft* draft, Random* random);
bool SubdivisionFinish(Draft* draft, Random* random);
// Rotate and / or translate the object into a scene pose.
bool Pose(Draft* draft, Random* random);

}  // namespace synth
}  // namespace opgraph
