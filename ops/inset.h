// Inset: Blender's inset of a face region (bmesh inset_region, use_even_offset, not relative,
// no edge rail, boundary kept): the region's boundary vertices get copies moved inward inside
// the region's faces so that each boundary edge is offset by `thickness` (even offset: at a
// corner the copy sits where the two offset edges meet: v + t (t1 + t2) / (1 + t1.t2), with t1,
// t2 the inward unit normals of the two boundary edges in their faces); then every vertex of
// the inset faces moves by `depth` along the region's area-weighted normal. A ring of quads
// joins the old boundary to the new one.
// Exact against Blender for regions whose boundary faces are coplanar at each boundary corner
// (the common case); across a fold Blender's even-offset factor differs.
//
// JSON: {"faces": <face selector>, "thickness": t (>= 0), "depth": d (default 0)}
// Gate g: thickness x g, depth x g (at g = 0 the ring is degenerate: surface unchanged).
// Blender: bmesh.ops.inset_region with the same settings.
#pragma once

#include "ops/face_selector.h"
#include "ops/op.h"
#include "ops/region_topology.h"

namespace opgraph {

class InsetOp : public OpBase<InsetOp> {
 public:
  explicit InsetOp(const Json& params);

  std::string Name() const override { return "Inset"; }
  void Prepare(const Mesh& input) override;
  Json ParamsToJson() const override;
  std::string BlenderCode() const override;

  template <typename T>
  void Apply(const T* p, const T& gate, const Positions<T>& in, Positions<T>* out) const;

 private:
  struct Corner {
    int target, source;
    int in_edge, out_edge;  // boundary edges (x -> v) and (v -> y), indices into region_.boundary
  };
  FaceSelector selector_;
  std::vector<Polygon> input_faces_;
  RegionCopy region_;
  std::vector<Corner> corners_;
};

}  // namespace opgraph
