// Bevel: Blender 3.4's Bevel modifier with affect EDGES, offset_type OFFSET (the width is the
// perpendicular distance of the new edges from the old edge, in each adjacent face), profile
// 0.5 (superellipse r = 2: elliptical arcs, chords even in angle), `segments` 1..9,
// loop_slide on, miter_outer SHARP, clamp_overlap on, harden normals off. Beveled edges:
// limit_method NONE (every manifold edge) or ANGLE (edges whose faces' normals differ by more
// than `angle_limit_deg`). The geometry follows bmesh_bevel.c: boundary vertices by offset_meet
// / offset_on_edge_between (with the loop-slide width adjustment; a lone un-beveled edge between
// two beveled ones is slid on unless it is within bevel::kGoodAngle = 1e-3 rad of collinear with
// either: real Blender 3.4 switches between 9.90e-4 and 1.003e-3, parity case
// bevel_slide_within_good_angle; edges between that all lie in one plane are met as if there
// were none, parity case bevel_table_bent_loops), profiles, and vertex meshes
// (two beveled edges: welded profiles; three or more: the cube-corner octant map when Blender
// uses it, else its cubic-subdivision vertex mesh; one segment: a polygon).
//
// Exact cases: vertices with 1 beveled edge (Blender's terminal-edge rule: the profile ends on
// the opposite face, a triangle fan or a polygon), with 2 (welded profiles, including un-beveled
// edges between them and the loop-slide width adjustment) and with 3 or more, for 1 to 9
// segments, including "pipe" vertices (two collinear beveled edges plus others, all faces
// parallel to the pipe, e.g. loop cuts with limit NONE: interior snapped to the pipe profile).
// Not supported (the topology pass raises "Bevel: vertex with N beveled edges not supported:
// ..."): a beveled edge ending at a vertex of valence 2, a pipe through a 3-edge cube-like
// corner, non-manifold or open-boundary vertices. clamp_overlap as Blender: the width is
// limited to the smallest width at which an edge's clone collapses or a boundary vertex slides
// off an un-beveled edge (geometry_collide_offset).
//
// JSON: {"width": w (>= 1e-4), "segments": 1..9 (default 1), "limit_method": "NONE"|"ANGLE"
//        (default "NONE"), "angle_limit_deg": a (0..180, default 30)}
// Continuous parameter: width. Gate g: effective width min(g * w, clamp limit); at g = 0 every new vertex sits
// on its original vertex, so the bevel faces are degenerate and the surface is unchanged.
// Blender: a BEVEL modifier left in the stack, with the settings above.
#pragma once

#include <vector>

#include "ops/bevel_vmesh.h"
#include "ops/op.h"

namespace opgraph {

class HalfedgeTopology;

class BevelOp : public OpBase<BevelOp> {
 public:
  explicit BevelOp(const Json& params);

  std::string Name() const override { return "Bevel"; }
  void Prepare(const Mesh& input) override;
  Json ParamsToJson() const override;
  std::string BlenderCode() const override;
  BlenderStage Stage() const override { return BlenderStage::kModifier; }
  // Widths and the angle limit are kept by rotations and translations.
  bool CommutesWithTransform(bool rigid) const override { return rigid; }

  template <typename T>
  void Apply(const T* p, const T& gate, const Positions<T>& in, Positions<T>* out) const {
    ApplyNoting(p, gate, in, out, nullptr);
  }
  // Near a switch the input decides: a lone un-beveled edge's slide (bevel::kGoodAngle), an
  // edge on a plane (bevel::kEpsilonBig), a profile's ends and middle in line
  // (bevel::kEpsilonAng): the synthetic table whose profile sat 2.00001 degrees from in line
  // rebuilt 3.6e-3 of the diagonal off, Blender's float32 bound vertices on the other side.
  bool NearGeometricBranch(double gate, const Positions<double>& in) const override;

  // How a boundary vertex between beveled edges e and e2 is placed (decided on the input).
  enum class Meet : char { kAdjacent, kOnEdgeBetween, kBetweenNoFace, kBetweenFace, kSlide };
  // kTerminal*: one beveled edge ends here (build_boundary_terminal_edge): its profile ends on
  // the opposite face (3 edges), a triangle fan (4 edges) or a polygon (more).
  enum class Kind : char { kWeld, kPolygon, kCubeCorner, kAdjacent, kPipe, kTerminalEdge, kTriangleFan, kTerminalPolygon };

  struct EdgeHalf {
    int other = -1;      // vertex at the other end
    int fnext = -1;      // face between this edge and the next (CCW)
    int fprev = -1;
    bool beveled = false;
    int leftv = -1, rightv = -1;  // boundary vertices
  };
  struct BoundVert {
    int efirst = -1, elast = -1;  // edge halves attached here (CCW from efirst to elast)
    int ebev = -1;                // beveled edge whose profile starts here
    int eon = -1;                 // the un-beveled edge it slides on (loop slide)
    Meet meet = Meet::kAdjacent;
    int e_in_plane = -1;          // representative in-plane edge between, for offset_meet
  };
  struct BevVert {
    int vertex = -1;
    int selcount = 0;
    std::vector<EdgeHalf> edges;   // CCW seen from outside
    std::vector<BoundVert> bounds; // CCW
    Kind kind = Kind::kPolygon;
    int weld1 = -1, weld2 = -1;
    int pipe = -1;                 // kPipe: boundary vertex whose profile is the pipe's
    std::vector<int> ids;          // grid slot (i, j, k) -> output vertex, -1 unused
  };

 private:
  template <typename T>
  T ClampLimit(const Positions<T>& in) const;
  template <typename T>
  void Boundaries(const Positions<T>& in, const T& width, std::vector<std::vector<T>>* off_l,
                  std::vector<std::vector<Vec3<T>>>* bounds) const;
  // Apply, lowering `*margin` (when given) to the distance of a profile's in-line test from its
  // switch (radians).
  template <typename T>
  void ApplyNoting(const T* p, const T& gate, const Positions<T>& in, Positions<T>* out, double* margin) const;
  int Slot(const BevVert& bv, int i, int j, int k) const;
  int OutputId(const BevVert& bv, int i, int j, int k) const;
  // The one-line error for a vertex the port does not support.
  static std::string Unsupported(int beveled, int vertex, const std::string& why);

  // Prepare's steps, in order (Blender's bevel: edge tagging, build_boundary with the vertex
  // mesh kinds, adjust_offsets' chains, tri_corner_test on the adjusted widths, the rebuilt and
  // new faces). Returns the beveled edges (by HalfedgeTopology edge); `touched` their vertices.
  std::vector<bool> TagBeveledEdges(const HalfedgeTopology& topology, const std::vector<Vec3d>& normals,
                                    std::vector<bool>* touched);
  // Input vertex v's fan of edge halves and its boundary vertices, appended to bev_verts_.
  void AddBevVert(const Mesh& input, const HalfedgeTopology& topology, const std::vector<Vec3d>& normals,
                  const std::vector<bool>& beveled, int v);
  void ChooseVertexMeshKind(const Mesh& input, const std::vector<Vec3d>& normals, BevVert* bv);
  void LinkLoopSlideChains();
  void KeepEqualWidthCubeCorners(const Mesh& input);
  void NumberOutputVertices(int num_vertices);
  void BuildFaces(const Mesh& input, const HalfedgeTopology& topology, const std::vector<bool>& beveled);

  double width_ = 0;
  int segments_ = 1;
  bool angle_limit_ = false;
  double angle_limit_deg_ = 30;

  bevel::ProfileSpacing spacing_{1};
  // How close Prepare's tests on the input came to their switches: angles (radians) and the
  // dot products of on-plane edges' face normals.
  double prepare_angle_margin_ = 1e300;
  double prepare_dot_margin_ = 1e300;
  // A corner that Blender builds as a cube corner or as a grid by the numbering of its edges
  // (tri_corner_test compares every beveled edge's offset with the first edge's, beveled or
  // not): three boundary vertices with an un-beveled edge among the beveled ones. The two
  // differ from 2 segments on (at a square corner from 3); our edges have no Blender numbering
  // to tell which.
  bool order_dependent_corner_ = false;
  bevel::VGrid<double> octant_{3, 2};
  std::vector<Polygon> input_faces_;
  std::vector<int> vertex_to_bev_;      // input vertex -> index in bev_verts_ or -1
  std::vector<int> kept_vertex_id_;     // input vertex -> output id when not beveled
  std::vector<BevVert> bev_verts_;
  // Offset-adjustment chains (loop slide): sequences of (bev vert, bound vert) pairs.
  struct ChainLink {
    int bv, bnd;
  };
  struct Chain {
    std::vector<ChainLink> links;
    bool cycle = false;
  };
  std::vector<Chain> chains_;
};

}  // namespace opgraph
