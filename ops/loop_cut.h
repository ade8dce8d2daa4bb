// LoopCut: Blender's loop cut with evenly spaced cuts (smoothness 0), as the gt-dev references
// build it: bmesh.ops.subdivide_edges(cuts, use_grid_fill=True) on an edge ring.
//
// Semantics: an edge is axis-parallel when |d . axis| >= 0.95 |d| (d its direction). The seed is
// the axis-parallel edge whose midpoint is nearest to `near`; on ties (within kLoopCutTie of the
// bounding-box diagonal) the one whose midpoint has the smallest x, then y, then z. The
// ring grows from the seed by walking across quads (BFS): in each quad adjacent to a ring edge,
// the opposite edge joins the ring if it is axis-parallel; non-quad faces stop the walk. Every
// ring edge is split into cuts + 1 equal parts; each quad with two opposite ring edges becomes
// cuts + 1 quads (corresponding cut vertices connected); any other face touching ring edges gets
// the new vertices inserted into its loop (like subdivide_edges without use_single_edge).
// Output topology: input vertices in order, then each ring edge's cut vertices (ring order);
// unchanged faces kept in place, split faces replaced by their strips.
// JSON: {"axis": "X"|"Y"|"Z", "cuts": 1..64, "near": [x, y, z] (default [0, 0, 0])}
// Throws FieldError("near") when no axis-parallel edge exists.
// No continuous parameters. Gate: no effect (a loop cut never changes the surface), so gate 0
// is the identity trivially.
// Blender: edit_mesh(obj), the same ring found in Python with bmesh, then
// bmesh.ops.subdivide_edges(bm, edges=ring, cuts=N, use_grid_fill=True).
#pragma once

#include <utility>
#include <vector>

#include "ops/op.h"

namespace opgraph {

// Relative tolerance (of the bounding-box diagonal) within which two seed edges tie; well above
// the rounding of Blender's float32 coordinates.
constexpr double kLoopCutTie = 1e-5;

class LoopCutOp : public OpBase<LoopCutOp> {
 public:
  explicit LoopCutOp(const Json& params);

  std::string Name() const override { return "LoopCut"; }
  void Prepare(const Mesh& input) override;
  Json ParamsToJson() const override;
  std::string BlenderCode() const override;

  template <typename T>
  void Apply(const T* p, const T& gate, const Positions<T>& in, Positions<T>* out) const;

 private:
  int axis_ = 0;
  int cuts_ = 1;
  Vec3d near_ = Vec3d::Zero();
  std::vector<std::pair<int, int>> ring_;  // oriented ring edges; cut k of edge e is vertex
                                           // num_input + e * cuts + k - 1 at t = k / (cuts + 1)
  int num_input_vertices_ = 0;
};

}  // namespace opgraph
