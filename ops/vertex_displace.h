// VertexDisplace: moves groups of vertices by per-group offsets (topology unchanged).
//
// JSON: {"groups": [{"verts": <vertex selector>, "offset": [dx, dy, dz]}, ...]}
//       (selector: ops/vertex_selector.h). A vertex in several groups gets the sum.
// Parameters: 3 per group (offset_<g>_x/y/z), each group a separate block of 3 so a fitter can
// keep per-vertex displacements sparse. Gate g: offsets times g.
// Blender: vertex coordinates edited on the mesh data (after applying pending modifiers).
#pragma once

#include "ops/op.h"
#include "ops/vertex_selector.h"

namespace opgraph {

class VertexDisplaceOp : public OpBase<VertexDisplaceOp> {
 public:
  explicit VertexDisplaceOp(const Json& params);

  std::string Name() const override { return "VertexDisplace"; }
  void Prepare(const Mesh& input) override;
  Json ParamsToJson() const override;
  std::string BlenderCode() const override;

  template <typename T>
  void Apply(const T* p, const T& gate, const Positions<T>& in, Positions<T>* out) const;

 private:
  std::vector<VertexSelector> selectors_;
  std::vector<std::vector<int>> resolved_;  // per group, after Prepare
};

}  // namespace opgraph
