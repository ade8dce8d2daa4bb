// Names a set of vertices so that it survives edits of the sequence: by an axis-aligned box on
// the vertex coordinates (any bound may be null = unbounded), or by explicit indices, with an
// optional required count.
//
// JSON: {"box": [[xmin, ymin, zmin], [xmax, ymax, zmax]], "expect": n}  or  {"indices": [..]}
// Blender: the same rule in Python (kVertexSelectorPython, put into every rebuild script), so
// Blender selects on its own mesh.
#pragma once

#include <optional>
#include <vector>

#include "core/mesh.h"
#include "ops/box.h"
#include "ops/params.h"

namespace opgraph {

class VertexSelector {
 public:
  // Throws FieldError naming `field` (and the sub-field) on bad JSON.
  VertexSelector(const Json& json, const std::string& field);

  // Indices of the selected vertices of `mesh`. Throws FieldError(field) when the selection is
  // empty, an index is out of range, or the count differs from `expect`.
  std::vector<int> Resolve(const Mesh& mesh) const;
  Json ToJson() const;
  // Python expression evaluating to the list of selected vertex indices of mesh `me`.
  std::string PythonExpr(const std::string& mesh_var) const;

 private:
  std::string field_;
  Box box_;
  std::vector<int> indices_;
  int expect_ = -1;
};

extern const char* kVertexSelectorPython;

}  // namespace opgraph
