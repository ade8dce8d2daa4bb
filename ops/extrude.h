// Extrude: a face region (mode "region": one connected or disconnected set of faces moved
// together along its area-weighted mean normal, as bmesh extrude_face_region) or each face
// on its own (mode "individual": along its own normal, as bmesh extrude_discrete_faces).
// The cap moves by `height` along the normal, is then scaled by `width` about its median
// centre, then tilted by two angles about axes u, v perpendicular to the normal
// (u = normalize(n x e), e = X unless |n.x| >= 0.9, then Y; v = n x u; R = R_u(a) R_v(b)).
// Side quads join each boundary edge to its cap copy; the extruded faces become the cap.
//
// JSON: {"faces": <face selector>, "mode": "region"|"individual" (default region),
//        "height": h, "width": w (default 1, > 0), "tilt_deg": [a, b] (default [0, 0])}
// Gate g: height x g, width 1 + g (w - 1), tilt x g: at g = 0 the cap lies on the original
// faces and the side quads are degenerate, so the surface is unchanged.
// Blender: bmesh extrude_face_region (+ delete of the original faces) or
// extrude_discrete_faces, then the same move in Python.
#pragma once

#include "ops/face_selector.h"
#include "ops/op.h"
#include "ops/region_topology.h"

namespace opgraph {

class ExtrudeOp : public OpBase<ExtrudeOp> {
 public:
  explicit ExtrudeOp(const Json& params);

  std::string Name() const override { return "Extrude"; }
  void Prepare(const Mesh& input) override;
  Json ParamsToJson() const override;
  std::string BlenderCode() const override;
  // A tilted cap's rotation axes come from a frame that switches where |normal.x| is 0.9.
  bool NearGeometricBranch(double gate, const Positions<double>& in) const override;

  template <typename T>
  void Apply(const T* p, const T& gate, const Positions<T>& in, Positions<T>* out) const;

  // The topology pass's result (for the fitter's Boolean weight, solver/boolean_weight.h):
  // the extruded sets, the input faces, and the first output face the extrusion created (its
  // caps and side quads follow the unselected faces, set by set).
  const std::vector<RegionCopy>& regions() const { return regions_; }
  const std::vector<Polygon>& input_faces() const { return input_faces_; }
  int first_created_face() const;

 private:
  FaceSelector selector_;
  bool individual_ = false;
  std::vector<Polygon> input_faces_;
  std::vector<RegionCopy> regions_;
};

}  // namespace opgraph
