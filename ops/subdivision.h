// Subdivision: Blender 3.4's Subdivision Surface modifier (SUBSURF) with Catmull-Clark, quality
// 3, use_limit_surface, boundary_smooth 'ALL' and use_creases (no creases are ever set), i.e.
// OpenSubdiv Catmull-Clark (Sdc VTX_BOUNDARY_EDGE_ONLY) refined uniformly `levels` times, then
// every vertex of the last level pushed to the limit surface. Output topology: the last level's
// quads in OpenSubdiv's vertex order.
//
// JSON:  {"op": "Subdivision", "params": {"levels": N}}  (integer, 1..6)
// Continuous parameter: "level_blend" b in [0, 1] (1 from JSON, identity 0). With t = g * b the
// output is t * (Catmull-Clark limit) + (1 - t) * (bilinear midpoint subdivision of the input,
// same topology): both are exact sparse weight matrices (#out x #in) built in Prepare, so the
// op is linear in the input positions and in t, and t = 0 reproduces the input surface.
// Blender: a SUBSURF modifier with the settings above, levels = render_levels = N.
#pragma once

#include <memory>

#include "ops/op.h"

namespace opgraph {

class SubdivisionOp : public OpBase<SubdivisionOp> {
 public:
  explicit SubdivisionOp(const Json& params);

  std::string Name() const override { return "Subdivision"; }
  void Prepare(const Mesh& input) override;
  bool PredictOutputFaces(int64_t* faces, int64_t* corners) const override;
  Json ParamsToJson() const override;
  std::string BlenderCode() const override;
  BlenderStage Stage() const override { return BlenderStage::kModifier; }
  // Catmull-Clark refinement and its limit surface are affine invariant.
  bool CommutesWithTransform(bool) const override { return true; }

  template <typename T>
  void Apply(const T* p, const T& gate, const Positions<T>& in, Positions<T>* out) const;

 private:
  // One term of an output vertex: input index, bilinear weight, Catmull-Clark limit weight.
  struct Term {
    int index;
    double bilinear;
    double limit;
  };
  // What Prepare computes from the input's faces alone (shared through a FaceListCache).
  struct Refinement {
    std::vector<Polygon> faces;
    int num_vertices = 0;
    std::vector<std::vector<Term>> rows;  // #out
  };
  static std::shared_ptr<const Refinement> Refine(const Mesh& input, int levels);

  int levels_ = 1;
  std::shared_ptr<const Refinement> refinement_;
};

}  // namespace opgraph
