// A design sequence: the start primitive and the ordered operations, with their gates.
// File format: docs/sequence-format.md.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/mesh.h"
#include "ops/op.h"

namespace opgraph {

constexpr int kSequenceFormatVersion = 1;

struct Sequence {
  std::string name;  // optional: what it builds (the input's name); names the Blender object
  double start_size = 2.0;  // Blender's default cube
  std::vector<std::unique_ptr<Op>> ops;
  std::vector<double> gates;  // one per op, in [0, 1]
  // One per op (or none): a pinned op keeps its parameters and gate when the fitter refits the
  // others (the editing workflow: fix one step by hand, let the rest adapt).
  std::vector<bool> pinned;
  // The most faces a step's output may have (the tools' --max-faces; not part of the file):
  // EvaluateSequence refuses a larger step, and steps that add up to 4 times as many.
  int64_t max_faces = kDefaultMaxFaces;

  bool IsPinned(size_t op) const { return op < pinned.size() && pinned[op]; }

  Mesh StartMesh() const { return MakeCube(start_size); }
};

// Parses a sequence document. Throws SequenceError with a one-line message naming the
// operation index and field.
Sequence ParseSequence(const Json& document);
Sequence LoadSequence(const std::string& path);
Json SequenceToJson(const Sequence& sequence);

// One step: `op`'s topology pass on `input`, then its geometry pass at `gate`. Throws FieldError
// when a target does not exist; the result is not validated (Mesh::Validate).
Mesh ApplyOp(Op* op, double gate, const Mesh& input);

// Runs every op's topology and geometry pass with doubles. Returns the mesh after each step
// (#ops entries). Throws SequenceError when a target does not exist at its step, the result
// is not finite, or a step is larger than sequence->max_faces allows.
std::vector<Mesh> EvaluateSequence(Sequence* sequence);

}  // namespace opgraph
