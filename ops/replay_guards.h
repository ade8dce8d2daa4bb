// Checks on an evaluated sequence for geometry that real Blender would not rebuild the same,
// shared by every producer of sequences (the zero-shot search, the synthetic corpus).
#pragma once

#include <vector>

#include "core/mesh.h"
#include "ops/params.h"
#include "ops/sequence.h"

namespace opgraph {

// True when a step has an edge shorter than `fraction` of its bounding-box diagonal: an op at a
// degenerate setting (an inset of zero thickness, a cap folded onto its base). Blender's
// float32 coordinates turn such slivers' normals into noise that later ops (a bevel) amplify.
bool HasCollapsedEdge(const std::vector<Mesh>& steps, double fraction = 1e-5);

// True when a Subdivision's input has a vertex with only two edges (a Boolean leaves them where
// a cut bends across a face): our Subdivision and Blender's disagree there
// (docs/sequence-format.md). `steps[k]` is the mesh after operation k of `document`.
bool SubdividesTwoEdgeVertex(const Json& document, const std::vector<Mesh>& steps);

// True when an op of `evaluated` (after EvaluateSequence, whose result is `steps`) takes a
// branch on its input's geometry within float32 noise of the switch (Op::NearGeometricBranch).
bool NearGeometricBranch(const Sequence& evaluated, const std::vector<Mesh>& steps);

// True when an op's output polygons change with the loop start of an input face (a Boolean
// cutting a hole into a polygon: Op::FacesWhoseLoopStartDecides, then tried from each of the
// face's corners) that an earlier op may have
// started elsewhere than Blender does (Op::FacesOfUnknownLoopStart: a Boolean's cut faces, whose
// loops Blender's merge starts by its own triangles' order). Through an op that changes the
// topology, a face it keeps as it was (the same corners from the same first one) keeps its
// standing, and its new faces are unknown when any input face was.
bool HolesAFaceOfUnknownLoopStart(const Sequence& evaluated, const std::vector<Mesh>& steps);

// Any of the four above (at the default fraction), for `evaluated` after EvaluateSequence.
bool BreaksReplay(const Sequence& evaluated, const std::vector<Mesh>& steps);

}  // namespace opgraph
