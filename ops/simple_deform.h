// SimpleDeformTwist / SimpleDeformBend / SimpleDeformTaper / SimpleDeformStretch: Blender 3.4's
// Simple Deform modifier (MOD_simpledeform), origin = object origin, no vertex group, no lock.
//
// Semantics (as Blender): the limit axis is the deform axis, except for Bend where deform axis
// X or Y limits along Z and Z limits along X. lower/upper = the mesh's extent along the limit
// axis; limits [l0, l1] are fractions of it; the effective factor is factor / (L1 - L0) with
// L = lower + (upper - lower) * l. Coordinates outside the limits are clamped before the
// deform and the overshoot re-added (Blender's dcut). For Twist/Taper/Stretch the coordinates
// are permuted so the deform axis is z; then
//   twist:   rotate (x, y) by z * k
//   taper:   (x, y) *= 1 + z * k
//   stretch: (x, y) *= z^2 k - k + 1, z *= 1 + k
//   bend:    arc of curvature k in the plane of the limit axis (Blender's simpleDeform_bend).
// JSON: {"axis": "X"|"Y"|"Z", "angle_deg": a (Twist, Bend) | "factor": f (Taper, Stretch),
//        "limits": [l0, l1] (default [0, 1])}
// Gate g: the factor (angle) times g.
// Blender: a SIMPLE_DEFORM modifier left in the stack.
#pragma once

#include "ops/op.h"

namespace opgraph {

class SimpleDeformOp : public OpBase<SimpleDeformOp> {
 public:
  enum class Mode { kTwist, kBend, kTaper, kStretch };
  SimpleDeformOp(Mode mode, const Json& params);

  std::string Name() const override;
  void Prepare(const Mesh& input) override { KeepTopology(input); }
  Json ParamsToJson() const override;
  std::string BlenderCode() const override;
  BlenderStage Stage() const override { return BlenderStage::kModifier; }

  template <typename T>
  void Apply(const T* p, const T& gate, const Positions<T>& in, Positions<T>* out) const;

 private:
  bool UsesAngle() const { return mode_ == Mode::kTwist || mode_ == Mode::kBend; }
  Mode mode_;
  int axis_ = 2;
  double limits_[2] = {0, 1};
};

}  // namespace opgraph
