// Boolean: union or difference of the mesh with a primitive placed by a 9-dof affine map, as
// Blender 3.4's Boolean modifier with the EXACT solver (self intersection and hole tolerance
// off). Primitives, in a unit template scaled by `size`, rotated by `rotation_deg` (XYZ Euler)
// and then moved to `location`:
//   cube: bmesh create_cube(size=1) (#V = 8);
//   prism6, prism8, cylinder: bmesh create_cone(cap_ends, radius 0.5, depth 1, 6 / 8 / 32
//   segments): axis +Z, vertex 2k at angle 2 pi k / n from +Y towards +X on the bottom cap,
//   2k + 1 above it; so for a prism `size` is [2 radius, 2 radius, depth].
// The topology pass triangulates both operands as Blender's exact boolean does (quads along the
// 0-2 diagonal unless concave there, larger polygons by Blender's polyfill ear clipping), runs
// CGAL's exact corefinement once and records, for each output vertex, where it comes from: an
// input vertex, a primitive vertex, or the crossing of an edge of one operand's triangulation
// with the plane of a triangle of the other; the geometry pass recomputes all of them from the
// input positions and the 9 parameters.
// Output polygons follow Blender's exact boolean: the triangles left of each input or primitive
// face (made constrained Delaunay within each operand triangle, as Blender's are) are merged
// back into polygons across their shared edges, longest first, never merging two polygons that
// share a vertex besides the edge's ends (so a face with a hole is split into hole-free polygons
// along the shortest remaining edges); a face left whole keeps its loop; then a crossing with
// the same two neighbours in every polygon around it, in a straight line, is dissolved.
// Counts can differ from Blender's on exact ties; see docs/sequence-format.md.
// A crossing where the best-conditioned edge lies within kMinCrossingSine (sine of the angle)
// of the plane it crosses is refused (FieldError "operation"): its position would amplify the
// rounding of Blender's float32 coordinates past the parity tolerance.
// An input polygon the primitive cuts whose corners lie farther than kMaxCutFaceNonPlanarity (of
// the input's bounding-box diagonal) from its plane is refused (FieldError "operation"): Blender
// splits it along the diagonal its loop start gives, which the ops before need not reproduce
// (half of LoopCut's strips start one corner off Blender's), and the two diagonals are different
// surfaces (a twisted, loop-cut block cut by a prism: 104 vertices against Blender's 110).
//
// JSON: {"operation": "UNION"|"DIFFERENCE", "primitive": "cube"|"prism6"|"prism8"|"cylinder",
//        "size": [sx, sy, sz] (> 0, full extents), "rotation_deg": [3] (default 0),
//        "location": [3] (default 0)}
// Gate g: a hard switch. Below 0.5 the op is the identity (the input mesh and topology
// unchanged), from 0.5 on the full boolean; the gate's derivative is zero.
// Blender: the primitive built with bmesh as a hidden object, and a BOOLEAN modifier (EXACT)
// on the mesh left in the stack.
#pragma once

#include <array>

#include "ops/op.h"

namespace opgraph {

constexpr double kMinCrossingSine = 0.02;  // about 1.1 degrees
// The two diagonals of a quad whose corners lie within h of a plane are surfaces up to 2 h apart:
// 1e-7 of the bounding-box diagonal keeps that 5 times under the parity tolerance (1e-6), and
// far above the rounding of faces planar by construction (below 1e-16 in every parity case).
constexpr double kMaxCutFaceNonPlanarity = 1e-7;

// Empty when `mesh` (triangulated as Blender's exact boolean does) is a closed, manifold,
// non-self-intersecting surface bounding a volume, i.e. a valid Boolean operand; else why not.
std::string SolidProblem(const Mesh& mesh);

class BooleanOp : public OpBase<BooleanOp> {
 public:
  explicit BooleanOp(const Json& params);

  std::string Name() const override { return "Boolean"; }
  void Prepare(const Mesh& input) override;
  const std::vector<Polygon>& OutputFaces(double gate) const override;
  Json ParamsToJson() const override;
  std::string BlenderCode() const override;
  BlenderStage Stage() const override { return BlenderStage::kModifier; }
  // The faces this boolean cut (Blender's merge orders their loops by its own triangles), and
  // the input polygons of 4 or more corners it cuts a hole into (their triangulation, which
  // follows the loop start, decides where the hole's bridges run).
  std::vector<int> FacesOfUnknownLoopStart(double gate) const override;
  // An input polygon folded past a right angle (a quad along either diagonal): Blender's merge
  // keeps such a face as triangles split along the diagonal its loop start gives, cut or not (a
  // cap turned 42 degrees about two axes: 17 faces against 16). Also a vertex of either operand
  // within float32 rounding of the other's face but not on it (ops/boolean_contact.h): Blender
  // rounds it onto the face or to either side (a cylinder's cap 1e-8 outside a box's face: 42
  // faces against 40). Valid, but a replay guard.
  bool NearGeometricBranch(double gate, const Positions<double>& in) const override;
  std::vector<int> FacesWhoseLoopStartDecides(double gate) const override;

  template <typename T>
  void Apply(const T* p, const T& gate, const Positions<T>& in, Positions<T>* out) const;

  // Where an output vertex comes from. For a crossing, `edge` is an edge of the input mesh
  // (on_primitive false) or of the primitive, and `plane` a triangle of the other mesh.
  // (Public for the steps of Prepare in ops/boolean.cc.)
  struct Source {
    enum Kind : char { kInput, kPrimitive, kCrossing };
    Kind kind = kInput;
    int vertex = -1;  // kInput, kPrimitive
    bool edge_on_primitive = false;
    std::array<int, 2> edge = {-1, -1};
    std::array<int, 3> plane = {-1, -1, -1};
  };

 private:

  // The primitive at the op's parameters.
  Mesh PlacedPrimitive() const;

  // Primitive vertex v under the parameters p (rotation: the matrix of p[3..5]).
  template <typename T>
  Vec3<T> PrimitiveVertex(const T* p, const Eigen::Matrix<T, 3, 3>& rotation, int v) const;

  bool difference_ = false;
  std::string primitive_;
  Mesh template_;                     // the primitive at unit size, before the affine map
  std::vector<Source> sources_;       // one per output vertex
  std::vector<Polygon> input_faces_;  // the identity's topology (gate below 0.5)
  std::vector<int> cut_faces_;        // output faces that are not a whole input or primitive face
  std::vector<int> holed_faces_;      // input faces of 4 or more corners the result holes
};

}  // namespace opgraph
