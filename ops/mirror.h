// Mirror: Blender 3.4's Mirror modifier about the object origin, for one or more axes (applied
// X, then Y, then Z, each doubling the mesh), with merge on (threshold 0.001: a vertex closer
// than that to its own mirror image is welded to it, at their midpoint), no clipping, no bisect.
// Mirrored faces get reversed winding; a mirrored face whose vertices are all welded (it lies
// on the plane) is dropped as a duplicate.
//
// JSON: {"axes": ["X", ...]}  (at least one, each once)
// Gate g: a mirrored copy sits at p + g (mirror(p) - p), a welded vertex at the midpoint of p
// and that, so at g = 0 the copies coincide with the original surface.
// Blender: a MIRROR modifier left in the stack.
#pragma once

#include <array>

#include "ops/op.h"

namespace opgraph {

class MirrorOp : public OpBase<MirrorOp> {
 public:
  explicit MirrorOp(const Json& params);

  std::string Name() const override { return "Mirror"; }
  void Prepare(const Mesh& input) override;
  Json ParamsToJson() const override;
  std::string BlenderCode() const override;
  BlenderStage Stage() const override { return BlenderStage::kModifier; }

  template <typename T>
  void Apply(const T* p, const T& gate, const Positions<T>& in, Positions<T>* out) const;

 private:
  enum Role : char { kKeep, kMirrored, kWelded };
  struct Source {
    int vertex;                 // input vertex
    std::array<Role, 3> role;  // what each axis did to it
  };
  std::array<bool, 3> axes_ = {false, false, false};
  std::vector<Source> sources_;  // one per output vertex
};

}  // namespace opgraph
