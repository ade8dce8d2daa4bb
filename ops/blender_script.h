// rebuild_blender.py: the Python script that rebuilds a sequence with Blender's own operators and
// modifiers, safe to run in a user's scene (contract: docs/sequence-format.md).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "ops/sequence.h"

namespace opgraph {

struct BlenderScriptOptions {
  // The object, its mesh and its new collection are named after this (Blender adds ".001" when
  // the name is taken).
  std::string name = "opgraph";
  // Blender's world from the sequence's frame: the axis conversion Blender's importer applies to
  // the input's format, so the rebuilt object sits on the imported source. A signed permutation.
  Eigen::Matrix3d blender_from_sequence = Eigen::Matrix3d::Identity();

  // Empty when valid, else what is wrong.
  std::string Check() const;
};

// `text` (a file name, say) as an object name: letters, digits, ' ', '_', '-' and '.' kept, anything
// else '_', at most 48 characters; "opgraph" when nothing is left.
std::string BlenderObjectName(const std::string& text);

// How each op of a sequence is realised in Blender.
struct BlenderStepPlan {
  // A global transform followed only by modifiers it commutes with: it becomes (part of) the
  // object's transform, so those modifiers stay live.
  bool object_transform = false;
  // A modifier that stays on the stack (no mesh edit follows it).
  bool live_modifier = false;
  // The modifiers (op indices) this mesh edit applies first, because it edits the mesh they make.
  std::vector<size_t> applies;
};

// #ops entries.
std::vector<BlenderStepPlan> PlanBlenderSteps(const Sequence& sequence);

// Names of the modifiers the rebuilt object keeps, in stack order.
std::vector<std::string> LiveModifierNames(const Sequence& sequence);

// The script. Throws SequenceError when an op's gate is not 1.
std::string BlenderScript(const Sequence& sequence, const BlenderScriptOptions& options = {});

}  // namespace opgraph
