// EdgeLoopAffineRotate / EdgeLoopAffineScale / EdgeLoopAffineTranslate: rotates, scales or
// moves a set of vertices (an edge loop, or several) about their median (mean) point, the
// pivot Blender uses for "Median Point" transforms. Topology unchanged.
//
// JSON: {"verts": <vertex selector>, "rotation_deg": [3] (XYZ Euler) | "scale": [3] | "offset": [3]}
// Gate g: angles times g, scale 1 + g (s - 1), offset times g.
// Blender: the selected vertex coordinates transformed on the mesh data about their median.
#pragma once

#include "ops/op.h"
#include "ops/vertex_selector.h"

namespace opgraph {

class EdgeLoopAffineOp : public OpBase<EdgeLoopAffineOp> {
 public:
  enum class Kind { kRotate, kScale, kTranslate };
  EdgeLoopAffineOp(Kind kind, const Json& params);

  std::string Name() const override;
  void Prepare(const Mesh& input) override;
  Json ParamsToJson() const override;
  std::string BlenderCode() const override;

  template <typename T>
  void Apply(const T* p, const T& gate, const Positions<T>& in, Positions<T>* out) const;

 private:
  Kind kind_;
  VertexSelector selector_;
  std::vector<int> resolved_;
};

}  // namespace opgraph
