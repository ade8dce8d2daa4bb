// GlobalAffineRotate / GlobalAffineScale / GlobalAffineTranslate: a transform of the whole mesh
// about the origin (Blender's object-origin pivot, transform baked into the mesh).
//
// JSON:  {"op": "GlobalAffineRotate", "params": {"rotation_deg": [rx, ry, rz]}}  (XYZ Euler)
//        {"op": "GlobalAffineScale", "params": {"scale": [sx, sy, sz]}}
//        {"op": "GlobalAffineTranslate", "params": {"offset": [tx, ty, tz]}}
// Gate g: rotation angles * g, scale 1 + g (s - 1), offset * g.
// Blender: mesh.transform(matrix) on the mesh data (after applying pending modifiers).
#pragma once

#include "ops/op.h"

namespace opgraph {

class GlobalAffineOp : public OpBase<GlobalAffineOp> {
 public:
  enum class Kind { kRotate, kScale, kTranslate };
  GlobalAffineOp(Kind kind, const Json& params);

  std::string Name() const override;
  void Prepare(const Mesh& input) override { KeepTopology(input); }
  Json ParamsToJson() const override;
  std::string BlenderCode() const override;
  BlenderStage Stage() const override { return BlenderStage::kTransform; }
  // The transform as a Python mathutils 4x4 Matrix expression.
  std::string PyMatrix() const;
  bool rigid() const { return kind_ != Kind::kScale; }

  template <typename T>
  void Apply(const T* p, const T& gate, const Positions<T>& in, Positions<T>* out) const;

 private:
  Kind kind_;
};

}  // namespace opgraph
