// A design sequence: the start primitive and the ordered operations, with their gates.
// File format: docs/sequence-format.md.
#pragma once

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
// (#ops entries). Throws SequenceError when a target does not exist at its step or the result
// is not finite.
std::vector<Mesh> EvaluateSequence(Sequence* sequence);

}  // namespace opgraph
