// KnifeCut: splits one face in two by joining the midpoints of two of its edges (Blender:
// bisect the two edges, then connect the new vertices). The neighbours across those edges get
// the midpoint inserted into their loops. The surface never changes; there are no continuous
// parameters, so the gate has no effect.
//
// JSON: {"face": <face selector, one face>, "edge_points": [[x, y, z], [x, y, z]]}: each edge is
// the edge of that face whose midpoint is nearest the point (named by geometry so edits of
// earlier ops don't retarget it; the two must differ).
// Blender: bmesh.ops.bisect_edges(cuts=1) on the two edges, then bmesh.ops.connect_vert_pair.
#pragma once

#include "ops/face_selector.h"
#include "ops/op.h"

namespace opgraph {

class KnifeCutOp : public OpBase<KnifeCutOp> {
 public:
  explicit KnifeCutOp(const Json& params);

  std::string Name() const override { return "KnifeCut"; }
  void Prepare(const Mesh& input) override;
  Json ParamsToJson() const override;
  std::string BlenderCode() const override;

  template <typename T>
  void Apply(const T* p, const T& gate, const Positions<T>& in, Positions<T>* out) const;

 private:
  FaceSelector selector_;
  Vec3d points_[2];
  std::pair<int, int> cut_edges_[2];  // after Prepare: the two edges' end vertices
};

}  // namespace opgraph
