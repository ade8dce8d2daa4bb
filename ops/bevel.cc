#include "ops/bevel.h"

#include <algorithm>
#include <cmath>

#include "core/geometry.h"
#include "ops/halfedge_topology.h"

namespace opgraph {

std::string BevelOp::Unsupported(int beveled, int vertex, const std::string& why) {
  return "Bevel: vertex with " + std::to_string(beveled) + " beveled edges not supported (vertex " +
         std::to_string(vertex) + ": " + why + ")";
}

BevelOp::BevelOp(const Json& params) {
  ParamReader reader(params);
  width_ = reader.Number("width", 1e-4, 1e3);
  segments_ = reader.Integer("segments", 1, 9, 1);
  angle_limit_ = reader.Word("limit_method", {"NONE", "ANGLE"}, "NONE") == "ANGLE";
  angle_limit_deg_ = reader.Number("angle_limit_deg", 0, 180, 30);
  reader.Finish();
  // A zero width is the identity but not differentiable (the bevel turns inside out below it).
  AddParam("width", 1e-4, 1e3, 0, width_);
  spacing_ = bevel::ProfileSpacing(segments_);
}

int BevelOp::Slot(const BevVert& bv, int i, int j, int k) const {
  const int n = static_cast<int>(bv.bounds.size()), ns = segments_;
  bevel::GridIndex g{i, j, k};
  if (bv.kind != Kind::kCubeCorner && bv.kind != Kind::kAdjacent && bv.kind != Kind::kPipe) {
    if (k == ns) {
      g = {(i + 1) % n, 0, 0};
    } else if ((bv.kind == Kind::kWeld || bv.kind == Kind::kTerminalEdge) && i == bv.weld2 && k > 0) {
      g = {bv.weld1, 0, ns - k};
    }
  } else {
    g = bevel::Canon(n, ns, i, j, k);
  }
  return (g.i * (ns / 2 + 1) + g.j) * (ns + 1) + g.k;
}

int BevelOp::OutputId(const BevVert& bv, int i, int j, int k) const { return bv.ids[Slot(bv, i, j, k)]; }

void BevelOp::Prepare(const Mesh& input) {
  const int num_vertices = input.NumVertices();
  input_faces_ = input.faces;
  const auto topology = HalfedgeTopology::Of(input);
  std::vector<Vec3d> normals(input.NumFaces());
  for (int f = 0; f < input.NumFaces(); ++f) normals[f] = SafeNormalized(FaceAreaNormal(input.vertices, input.faces[f]));
  std::vector<bool> touched(num_vertices, false);
  const std::vector<bool> beveled = TagBeveledEdges(*topology, normals, &touched);
  // Vertices with beveled edges: edges in CCW order seen from outside (a face's outgoing edge
  // at v, the face, then its incoming edge, which is the next face's outgoing edge).
  bev_verts_.clear();
  vertex_to_bev_.assign(num_vertices, -1);
  for (int v = 0; v < num_vertices; ++v) {
    if (touched[v]) AddBevVert(input, *topology, normals, beveled, v);
  }
  LinkLoopSlideChains();
  KeepEqualWidthCubeCorners(input);
  NumberOutputVertices(num_vertices);
  BuildFaces(input, *topology, beveled);
}

std::vector<bool> BevelOp::TagBeveledEdges(const HalfedgeTopology& topology, const std::vector<Vec3d>& normals,
                                         std::vector<bool>* touched) {
  // Beveled edges, as the modifier tags them (angle test in float, as Blender).
  const double threshold = std::cos(static_cast<float>(DegToRad(angle_limit_deg_)) + 0.000000175f);
  std::vector<bool> beveled(topology.NumEdges(), false);
  bool any = false;
  prepare_angle_margin_ = prepare_dot_margin_ = 1e300;
  order_dependent_corner_ = false;
  for (int e = 0; e < topology.NumEdges(); ++e) {
    const HalfedgeTopology::Corners faces = topology.EdgeCorners(e);
    if (faces.size() != 2) continue;
    const double dot = normals[faces[0].face].dot(normals[faces[1].face]);
    beveled[e] = !angle_limit_ || dot < threshold;
    if (angle_limit_) prepare_dot_margin_ = std::min(prepare_dot_margin_, std::abs(dot - threshold));
    const auto [a, b] = topology.EdgeVertices(e);
    if (beveled[e]) (*touched)[a] = (*touched)[b] = any = true;
  }
  if (!any) throw FieldError("limit_method", "no edge of the input is beveled");
  return beveled;
}

void BevelOp::AddBevVert(const Mesh& input, const HalfedgeTopology& topology, const std::vector<Vec3d>& normals,
                         const std::vector<bool>& beveled, int v) {
  auto is_beveled = [&](int f, int c) { return beveled[topology.CornerEdge(f, c)]; };
  auto vertex_normal = [&](int u, const HalfedgeTopology::Corners& corners) {
    Vec3d n(0, 0, 0);
    for (const auto& [f, c] : corners) {
      const Polygon& face = input.faces[f];
      const int k = static_cast<int>(face.size());
      n += normals[f] * bevel::Angle<double>(input.vertices[face[(c + k - 1) % k]] - input.vertices[u],
                                             input.vertices[face[(c + 1) % k]] - input.vertices[u]);
    }
    return SafeNormalized(n);
  };

  BevVert bv;
  bv.vertex = v;
  const HalfedgeTopology::Corners corners = topology.VertexCorners(v);
  int beveled_here = 0;  // for messages before the fan is known
  for (const auto& [f0, c0] : corners) beveled_here += is_beveled(f0, c0);
  int f = corners[0].face, c = corners[0].corner;
  for (size_t step = 0; step < corners.size(); ++step) {
    const Polygon& face = input.faces[f];
    const int k = static_cast<int>(face.size());
    const int b = face[(c + 1) % k], a = face[(c + k - 1) % k];
    EdgeHalf half;
    half.other = b;
    half.fnext = f;
    half.beveled = is_beveled(f, c);
    bv.edges.push_back(half);
    // Across the incoming edge a -> v to the next face of the fan.
    const auto users = topology.EdgeCorners(topology.CornerEdge(f, (c + k - 1) % k));
    if (users.size() != 2) throw FieldError("limit_method", Unsupported(beveled_here, v, "on an open or non-manifold edge"));
    const auto& other = users[0].face == f ? users[1] : users[0];
    if (other.face == f) throw FieldError("limit_method", Unsupported(beveled_here, v, "an edge used twice by one face"));
    const Polygon& g = input.faces[other.face];
    const int kg = static_cast<int>(g.size());
    const int cg = g[other.corner] == v ? other.corner : (other.corner + 1) % kg;
    if (g[(cg + 1) % kg] != a) throw FieldError("limit_method", Unsupported(beveled_here, v, "inconsistent face winding"));
    f = other.face;
    c = cg;
    if (f == corners[0].face && c == corners[0].corner && step + 1 != corners.size()) {
      throw FieldError("limit_method", Unsupported(beveled_here, v, "more than one fan of faces"));
    }
  }
  const int n = static_cast<int>(bv.edges.size());
  for (int h = 0; h < n; ++h) bv.edges[(h + 1) % n].fprev = bv.edges[h].fnext;
  for (const EdgeHalf& e : bv.edges) bv.selcount += e.beveled;
  if (bv.selcount == 1 && n < 3) throw FieldError("limit_method", Unsupported(1, v, "a beveled edge ends at a vertex of valence 2"));

  // Boundary vertices (build_boundary), with the placement rule decided on the input.
  const Vec3d& p = input.vertices[v];
  const Vec3d vno = vertex_normal(v, corners);
  auto on_plane = [&](int h) {
    const double dot = normals[bv.edges[h].fprev].dot(normals[bv.edges[h].fnext]);
    prepare_dot_margin_ = std::min({prepare_dot_margin_, std::abs(std::abs(dot + 1) - bevel::kEpsilonBig),
                                    std::abs(std::abs(dot - 1) - bevel::kEpsilonBig)});
    return std::abs(dot + 1) <= bevel::kEpsilonBig || std::abs(dot - 1) <= bevel::kEpsilonBig;
  };
  auto meets_edge = [&](int h1, int h2) {  // offset_meet_edge's success test
    const Vec3d d1 = (input.vertices[bv.edges[h1].other] - p).normalized();
    const Vec3d d2 = (input.vertices[bv.edges[h2].other] - p).normalized();
    const double ang = bevel::AngleNormalized<double>(d1, d2);
    prepare_angle_margin_ = std::min({prepare_angle_margin_, std::abs(std::abs(ang) - bevel::kGoodAngle),
                                      std::abs(std::abs(ang - kPi) - bevel::kGoodAngle)});
    if (std::abs(ang) < bevel::kGoodAngle) return false;
    if (d1.cross(d2).dot(vno) < 0) return false;
    return std::abs(ang - kPi) >= bevel::kGoodAngle;
  };
  int efirst = 0;
  while (!bv.edges[efirst].beveled) ++efirst;
  int e = efirst;
  if (bv.selcount == 1) {
    // build_boundary_terminal_edge: meet points on the neighbouring edges, then points slid
    // the width along every other edge.
    const int prev = (efirst + n - 1) % n, next = (efirst + 1) % n;
    BoundVert b0, b1;
    b0.efirst = prev;
    b0.elast = b0.ebev = efirst;
    b1.efirst = efirst;
    b1.elast = next;
    bv.bounds = {b0, b1};
    bv.edges[efirst].leftv = bv.edges[prev].leftv = bv.edges[prev].rightv = 0;
    bv.edges[efirst].rightv = bv.edges[next].leftv = bv.edges[next].rightv = 1;
    for (int h = (next + 1) % n; h != prev; h = (h + 1) % n) {
      BoundVert slide;
      slide.efirst = slide.elast = h;
      slide.meet = Meet::kSlide;
      bv.edges[h].leftv = bv.edges[h].rightv = static_cast<int>(bv.bounds.size());
      bv.bounds.push_back(slide);
    }
    bv.kind = n == 3 ? Kind::kTerminalEdge : n == 4 ? Kind::kTriangleFan : Kind::kTerminalPolygon;
    bv.weld1 = 0;
    bv.weld2 = 1;
    vertex_to_bev_[v] = static_cast<int>(bev_verts_.size());
    bev_verts_.push_back(std::move(bv));
    return;
  }
  do {
    int e2 = (e + 1) % n, in_plane = 0, not_in_plane = 0, eip = -1, enip = -1;
    for (; !bv.edges[e2].beveled; e2 = (e2 + 1) % n) {
      if (on_plane(e2)) {
        ++in_plane;
        eip = e2;
      } else {
        ++not_in_plane;
        enip = e2;
      }
    }
    BoundVert bnd;
    bnd.efirst = e;
    bnd.elast = bnd.ebev = e2;
    if (in_plane + not_in_plane == 0) {
      bnd.meet = Meet::kAdjacent;
    } else {
      const int count = not_in_plane > 0 ? not_in_plane : in_plane;
      const int emid = not_in_plane > 0 ? enip : eip;
      if (count == 1 && meets_edge(e, emid) && meets_edge(emid, e2)) {
        bnd.meet = Meet::kOnEdgeBetween;
        bnd.eon = emid;
      } else {
        bnd.meet = not_in_plane > 0 ? Meet::kBetweenNoFace : Meet::kBetweenFace;
        bnd.e_in_plane = eip;
      }
    }
    const int index = static_cast<int>(bv.bounds.size());
    bv.bounds.push_back(bnd);
    bv.edges[e].rightv = index;
    bv.edges[e2].leftv = index;
    for (int e3 = (e + 1) % n; e3 != e2; e3 = (e3 + 1) % n) bv.edges[e3].leftv = bv.edges[e3].rightv = index;
    e = e2;
  } while (e != efirst);

  // Vertex mesh kind (build_boundary's mesh_kind, bevel_build_rings' choice).
  ChooseVertexMeshKind(input, normals, &bv);
  vertex_to_bev_[v] = static_cast<int>(bev_verts_.size());
  bev_verts_.push_back(std::move(bv));
}

Json BevelOp::ParamsToJson() const {
  return {{"width", params_[0]},
          {"segments", segments_},
          {"limit_method", angle_limit_ ? "ANGLE" : "NONE"},
          {"angle_limit_deg", angle_limit_deg_}};
}

std::string BevelOp::BlenderCode() const {
  return "m = obj.modifiers.new(" + PyWord("Bevel") + ", " + PyWord("BEVEL") + ")\n" +
         "m.affect = " + PyWord("EDGES") + "\n" +
         "m.offset_type = " + PyWord("OFFSET") + "\n" +
         "m.width = " + Py(params_[0]) + "\n" +
         "m.segments = " + std::to_string(segments_) + "\n" +
         "m.limit_method = " + PyWord(angle_limit_ ? "ANGLE" : "NONE") + "\n" +
         "m.angle_limit = " + Py(DegToRad(angle_limit_deg_)) + "\n" +
         "m.profile_type = " + PyWord("SUPERELLIPSE") + "\n" +
         "m.profile = 0.5\n" +
         "m.use_clamp_overlap = " + PyBool(true) + "\n" +
         "m.loop_slide = " + PyBool(true) + "\n" +
         "m.miter_outer = " + PyWord("MITER_SHARP") + "\n" +
         "m.miter_inner = " + PyWord("MITER_SHARP") + "\n" +
         "m.vmesh_method = " + PyWord("ADJ") + "\n" +
         "m.harden_normals = " + PyBool(false) + "\n";
}

}  // namespace opgraph
