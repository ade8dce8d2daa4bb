// KnifeCut: cuts faces without changing the surface, in one of two modes.
//
// Edge mode, {"face": <face selector, one face>, "edge_points": [[x, y, z], [x, y, z]]}: splits
// that face in two by joining the midpoints of two of its edges; each edge is the face's edge
// whose midpoint is nearest the point (named by geometry so edits of earlier ops don't retarget
// it; the two must differ). The neighbours across those edges get the midpoint in their loops.
// Blender: bmesh.ops.bisect_edges(cuts=1) on the two edges, then bmesh.ops.connect_vert_pair.
//
// Plane mode, {"plane_co": [x, y, z], "plane_no": [x, y, z]}: Blender's Bisect (knife along a
// plane, nothing removed): every edge whose ends lie strictly on opposite sides of the plane is
// split where it crosses it, and every face with two non-adjacent vertices on the plane (new or
// existing within kPlaneEpsilon) is split between them. Faces the plane crosses more than twice
// (concave n-gons) are refused. Blender: bmesh.ops.bisect_plane(dist=kPlaneEpsilon).
//
// There are no continuous parameters, so the gate has no effect. New vertices follow the input
// positions differentiably (midpoints; plane crossings d_a / (d_a - d_b) along the edge).
#pragma once

#include <optional>

#include "ops/face_selector.h"
#include "ops/op.h"

namespace opgraph {

class KnifeCutOp : public OpBase<KnifeCutOp> {
 public:
  static constexpr double kPlaneEpsilon = 1e-5;

  explicit KnifeCutOp(const Json& params);

  std::string Name() const override { return "KnifeCut"; }
  void Prepare(const Mesh& input) override;
  Json ParamsToJson() const override;
  std::string BlenderCode() const override;

  template <typename T>
  void Apply(const T* p, const T& gate, const Positions<T>& in, Positions<T>* out) const;

 private:
  void PrepareEdgeMode(const Mesh& input);
  void PreparePlaneMode(const Mesh& input);

  // Edge mode.
  std::optional<FaceSelector> selector_;
  Vec3d points_[2];
  // Plane mode.
  Vec3d plane_co_ = Vec3d::Zero();
  Vec3d plane_no_ = Vec3d::UnitZ();  // unit length
  // After Prepare: the edges split, in order of the new vertices they create (new vertex k is
  // input vertex count + k). Edge mode splits at the midpoint; plane mode at the crossing.
  std::vector<std::pair<int, int>> split_edges_;
};

}  // namespace opgraph
