// The files a sequence run produces (apply_sequence's, fit_sequence's, and any program's that
// links opgraph::io): everything is computed first, so bad input leaves nothing written, then
// each file is written atomically.
#pragma once

#include <string>
#include <vector>

#include "ops/blender_script.h"
#include "ops/sequence.h"

namespace opgraph {

struct SequenceOutputs {
  // The mesh after each op, as Blender shows the object then: with the transforms that become
  // the object's (ops/blender_script.h), so every step sits where the result does.
  std::vector<Mesh> steps;
  std::vector<std::string> step_names; // op names
  Mesh result;                         // the final mesh (the start cube for an empty sequence)
  std::string blender_script;          // rebuild_blender.py
  std::string sequence_json;           // sequence.json
  std::string steps_glb;               // result.glb: one node per step (the start cube when none)
};

// "NN_<op>": the name of step `index` (its file under steps/, its node in result.glb).
std::string StepFileStem(size_t index, const std::string& op_name);
// StepFileStem of every entry of `op_names`, in order.
std::vector<std::string> StepFileStems(const std::vector<std::string>& op_names);

// Evaluates `sequence` and renders its outputs. Throws SequenceError (nothing is written).
SequenceOutputs RenderSequenceOutputs(Sequence* sequence, const BlenderScriptOptions& blender = {});

// Writes DIR/result.obj, DIR/result.glb, DIR/rebuild_blender.py, DIR/sequence.json and, with `write_steps`,
// DIR/steps/NN_<op>.obj, creating DIR. Throws std::exception on an I/O failure.
void WriteSequenceOutputs(const SequenceOutputs& outputs, const std::string& out_dir, bool write_steps,
                          const std::string& result_comment);

}  // namespace opgraph
