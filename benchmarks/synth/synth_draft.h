// A sequence being sampled: the ops so far and the mesh they build, with the geometric queries
// the grammar uses to aim the next op (faces facing a direction, edge-loop levels, vertex
// boxes). Ops are applied one at a time with the engine; an op the engine refuses leaves the
// draft unchanged.
#pragma once

#include <vector>

#include "core/mesh.h"
#include "ops/box.h"
#include "ops/builders.h"

namespace opgraph {
namespace synth {

class Draft {
 public:
  Draft();

  // Appends `ops` if the engine applies every one of them to the current mesh; else leaves the
  // draft unchanged and returns false.
  bool TryAppend(const std::vector<Json>& ops);
  bool TryAppend(const Json& op) { return TryAppend(std::vector<Json>{op}); }

  const Mesh& mesh() const { return steps_.empty() ? start_ : steps_.back(); }
  const std::vector<Json>& ops() const { return ops_; }
  const std::vector<Mesh>& steps() const { return steps_; }
  int NumOps() const { return static_cast<int>(ops_.size()); }
  bool Has(const std::string& op_name) const;
  Json Document() const { return build::Document(ops_); }

  Vec3d Lo() const;
  Vec3d Hi() const;
  Vec3d Extent() const { return Hi() - Lo(); }
  double Diagonal() const { return Extent().norm(); }

  // Faces a selector can name (not slivers) whose unit normal . direction >= min_dot.
  std::vector<int> FacesFacing(const Vec3d& direction, double min_dot = 0.99) const;
  Vec3d FaceCenter(int face) const;  // median centre, as the selectors use
  Vec3d FaceNormal(int face) const;
  double FaceArea(int face) const;
  // The selector naming exactly `face`: its normal, nearest its centre.
  build::FaceTarget TargetOf(int face) const;
  // The extreme face along `direction` among those facing it (-1 when none).
  int ExtremeFace(const Vec3d& direction) const;

  // Coordinates along `axis` shared by several vertices strictly inside the bounding box (the
  // levels of edge loops across that axis), ascending.
  std::vector<double> LoopLevels(int axis) const;
  // The vertices with coordinate `level` along `axis` (within a quarter of the gap to the next
  // level), or an empty box when that would catch no vertex.
  build::VertexTarget LoopTarget(int axis, double level) const;
  // A box around `points` (margin 1e-3 of the diagonal) naming exactly the vertices inside.
  build::VertexTarget BoxAround(const std::vector<Vec3d>& points) const;
  int CountInside(const Box& box) const;

 private:
  Mesh start_;
  std::vector<Json> ops_;
  std::vector<Mesh> steps_;
};

}  // namespace synth
}  // namespace opgraph
