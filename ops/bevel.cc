#include "ops/bevel.h"

#include <Eigen/Dense>
#include <algorithm>
#include <limits>

#include "core/geometry.h"
#include "ops/halfedge_topology.h"
#include "ops/orient_against_neighbours.h"

namespace opgraph {

using bevel::V3;

namespace {

std::string Unsupported(int beveled, int vertex, const std::string& why) {
  return "Bevel: vertex with " + std::to_string(beveled) + " beveled edges not supported (vertex " +
         std::to_string(vertex) + ": " + why + ")";
}

}  // namespace

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

  // Beveled edges, as the modifier tags them (angle test in float, as Blender).
  const double threshold = std::cos(static_cast<float>(DegToRad(angle_limit_deg_)) + 0.000000175f);
  std::vector<bool> beveled(topology->NumEdges(), false);
  std::vector<bool> touched(num_vertices, false);
  bool any = false;
  prepare_angle_margin_ = prepare_dot_margin_ = 1e300;
  order_dependent_corner_ = false;
  for (int e = 0; e < topology->NumEdges(); ++e) {
    const HalfedgeTopology::Corners faces = topology->EdgeCorners(e);
    if (faces.size() != 2) continue;
    const double dot = normals[faces[0].face].dot(normals[faces[1].face]);
    beveled[e] = !angle_limit_ || dot < threshold;
    if (angle_limit_) prepare_dot_margin_ = std::min(prepare_dot_margin_, std::abs(dot - threshold));
    const auto [a, b] = topology->EdgeVertices(e);
    if (beveled[e]) touched[a] = touched[b] = any = true;
  }
  if (!any) throw FieldError("limit_method", "no edge of the input is beveled");
  auto is_beveled = [&](int f, int c) { return beveled[topology->CornerEdge(f, c)]; };

  auto vertex_normal = [&](int v, const HalfedgeTopology::Corners& corners) {
    Vec3d n(0, 0, 0);
    for (const auto& [f, c] : corners) {
      const Polygon& face = input.faces[f];
      const int k = static_cast<int>(face.size());
      n += normals[f] * bevel::Angle<double>(input.vertices[face[(c + k - 1) % k]] - input.vertices[v],
                                             input.vertices[face[(c + 1) % k]] - input.vertices[v]);
    }
    return SafeNormalized(n);
  };

  // Vertices with beveled edges: edges in CCW order seen from outside (a face's outgoing edge
  // at v, the face, then its incoming edge, which is the next face's outgoing edge).
  bev_verts_.clear();
  vertex_to_bev_.assign(num_vertices, -1);
  for (int v = 0; v < num_vertices; ++v) {
    if (!touched[v]) continue;
    BevVert bv;
    bv.vertex = v;
    const HalfedgeTopology::Corners corners = topology->VertexCorners(v);
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
      const auto users = topology->EdgeCorners(topology->CornerEdge(f, (c + k - 1) % k));
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
      continue;
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
    const int count = static_cast<int>(bv.bounds.size());
    if (count == 2) {
      bv.kind = Kind::kWeld;
      bv.weld1 = 0;
      bv.weld2 = 1;
    } else if (segments_ == 1) {
      bv.kind = Kind::kPolygon;
    } else {
      // pipe_test: two collinear beveled edges with faces parallel to them.
      if (count <= 4 && bv.selcount <= 4) {
        for (int i = 0; i < count; ++i) {
          const BoundVert& b1 = bv.bounds[i];
          const BoundVert& b3 = bv.bounds[(i + 2) % count];
          const Vec3d d1 = (p - input.vertices[bv.edges[b1.ebev].other]).normalized();
          const Vec3d d3 = (input.vertices[bv.edges[b3.ebev].other] - p).normalized();
          if (bevel::AngleNormalized<double>(d1, d3) < bevel::kEpsilonAng) {
            bool parallel = true;
            for (const EdgeHalf& eh : bv.edges) parallel = parallel && std::abs(d1.dot(normals[eh.fnext])) <= bevel::kEpsilonBig;
            if (parallel) bv.pipe = i;
            break;
          }
        }
      }
      // tri_corner_test: 3 boundary vertices, the other edges nearly flat, angles summing to ~270.
      int test = 0;
      if (count == 3) {
        int in_plane_edges = 0;
        double total = 0;
        for (const EdgeHalf& eh : bv.edges) {
          const Vec3d& n1 = normals[eh.fprev];
          const Vec3d& n2 = normals[eh.fnext];
          double ang = bevel::AngleNormalized<double>(n1, n2);
          // Concave when the next face bends toward the previous face's outside.
          const Vec3d centre = FaceCentroid(input.vertices, input.faces[eh.fnext]);
          if (n1.dot(centre - p) > 0) ang = -ang;
          if (std::abs(ang) <= kPi / 4) {
            ++in_plane_edges;
          } else if (std::abs(ang) >= 3 * kPi / 4) {
            test = -1;
          }
          total += ang;
        }
        if (in_plane_edges != n - 3) test = -1;
        if (std::abs(std::abs(total) - 3 * kPi / 2) > kPi / 4) test = -1;
        if (test == 0 && n == 3 && bv.selcount == 3) test = 1;
      }
      bv.kind = test != -1 && count == 3 ? Kind::kCubeCorner : Kind::kAdjacent;
      if (bv.kind == Kind::kCubeCorner && bv.selcount < n) order_dependent_corner_ = true;
      if (bv.pipe >= 0) {
        if (bv.kind == Kind::kCubeCorner) {
          throw FieldError("limit_method", Unsupported(bv.selcount, v, "a pipe on a cube-like corner"));
        }
        bv.kind = Kind::kPipe;
      }
    }
    vertex_to_bev_[v] = static_cast<int>(bev_verts_.size());
    bev_verts_.push_back(std::move(bv));
  }

  // Loop-slide width adjustment (adjust_offsets): chains or cycles of boundary vertices that
  // slide on un-beveled edges, linked across beveled edges (right side here, left side there).
  chains_.clear();
  {
    auto other_end = [&](int b, int h, int* half) {  // find_other_end_edge_half
      const BevVert& bv = bev_verts_[b];
      const int ob = vertex_to_bev_[bv.edges[h].other];
      int oh = 0;
      while (bev_verts_[ob].edges[oh].other != bv.vertex) ++oh;
      *half = oh;
      return ob;
    };
    std::vector<std::vector<bool>> visited(bev_verts_.size());
    std::vector<std::vector<ChainLink>> adjchain(bev_verts_.size());
    for (size_t b = 0; b < bev_verts_.size(); ++b) {
      visited[b].assign(bev_verts_[b].bounds.size(), false);
      adjchain[b].assign(bev_verts_[b].bounds.size(), {-1, -1});
    }
    auto eon = [&](const ChainLink& l) { return bev_verts_[l.bv].bounds[l.bnd].eon >= 0; };
    auto walk = [&](ChainLink start, bool cycle) {
      Chain chain;
      chain.cycle = cycle;
      ChainLink l = start;
      do {
        chain.links.push_back(l);
        l = adjchain[l.bv][l.bnd];
      } while (l.bv >= 0 && !(l.bv == start.bv && l.bnd == start.bnd));
      chains_.push_back(chain);
    };
    for (int b = 0; b < static_cast<int>(bev_verts_.size()); ++b) {
      for (int anchor = 0; anchor < static_cast<int>(bev_verts_[b].bounds.size()); ++anchor) {
        if (visited[b][anchor] || bev_verts_[b].bounds[anchor].eon < 0) continue;
        ChainLink v{b, anchor}, chain_start = v, chain_end = v;
        bool cycle = false;
        int length = 1;
        while (eon(v) && !visited[v.bv][v.bnd] && !cycle) {
          visited[v.bv][v.bnd] = true;
          int half;
          const int ob = other_end(v.bv, bev_verts_[v.bv].bounds[v.bnd].efirst, &half);
          const ChainLink next{ob, bev_verts_[ob].edges[half].leftv};
          adjchain[v.bv][v.bnd] = next;
          chain_end = next;
          ++length;
          if (visited[next.bv][next.bnd]) {
            if (!(next.bv == chain_start.bv && next.bnd == chain_start.bnd)) break;
            walk(chain_start, true);
            cycle = true;
          }
          v = next;
        }
        if (cycle) continue;
        adjchain[v.bv][v.bnd] = {-1, -1};
        v = chain_start;
        do {
          visited[v.bv][v.bnd] = true;
          int half;
          const int ob = other_end(v.bv, bev_verts_[v.bv].bounds[v.bnd].elast, &half);
          const ChainLink next{ob, bev_verts_[ob].edges[half].rightv};
          adjchain[next.bv][next.bnd] = v;
          ++length;
          chain_start = next;
          v = next;
        } while (!visited[v.bv][v.bnd] && eon(v));
        if (length >= 3 && !eon(chain_start) && !eon(chain_end)) walk(chain_start, false);
      }
    }
  }

  // clamp_overlap: widths beyond the collision limit are shrunk to it, as Blender does.
  const double clamped_width = std::min(width_, ClampLimit<double>(input.vertices));

  // Blender takes the cube-corner vertex mesh only when the (adjusted) widths of the corner's
  // beveled edges agree (tri_corner_test).
  if (!chains_.empty()) {
    std::vector<std::vector<double>> off_l;
    std::vector<std::vector<Vec3d>> bounds;
    Boundaries<double>(input.vertices, clamped_width, &off_l, &bounds);
    for (size_t b = 0; b < bev_verts_.size(); ++b) {
      BevVert& bv = bev_verts_[b];
      if (bv.kind != Kind::kCubeCorner) continue;
      double lo = 1e300, hi = -1e300;
      for (size_t h = 0; h < bv.edges.size(); ++h) {
        if (!bv.edges[h].beveled) continue;
        lo = std::min(lo, off_l[b][h]);
        hi = std::max(hi, off_l[b][h]);
      }
      if (hi - lo > bevel::kEpsilon) bv.kind = Kind::kAdjacent;
    }
  }

  // Output vertices: kept input vertices first, then each beveled vertex's grid.
  kept_vertex_id_.assign(num_vertices, -1);
  int next_id = 0;
  for (int v = 0; v < num_vertices; ++v) {
    if (vertex_to_bev_[v] < 0) kept_vertex_id_[v] = next_id++;
  }
  const int ns = segments_, ns2 = ns / 2;
  bool need_octant = false;
  for (BevVert& bv : bev_verts_) {
    const int n = static_cast<int>(bv.bounds.size());
    bv.ids.assign(n * (ns2 + 1) * (ns + 1), -1);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j <= ns2; ++j) {
        for (int k = 0; k <= ns; ++k) {
          const bool used = bv.kind == Kind::kCubeCorner || bv.kind == Kind::kAdjacent || bv.kind == Kind::kPipe
                                ? bevel::IsCanon(ns, i, j, k)
                                : j == 0 && (k == 0 || (bv.kind != Kind::kPolygon && i == 0 && k < ns));
          if (used) bv.ids[(i * (ns2 + 1) + j) * (ns + 1) + k] = next_id++;
        }
      }
    }
    need_octant = need_octant || bv.kind == Kind::kCubeCorner;
  }
  num_output_vertices_ = next_id;
  if (need_octant) octant_ = bevel::CubeCornerOctant(spacing_);

  // Faces: the original faces rebuilt on the boundary vertices, then the beveled edges' strips,
  // then the vertex meshes. Strips and vertex meshes are oriented afterwards.
  output_faces_.clear();
  for (const Polygon& face : input.faces) {
    Polygon rebuilt;
    const int k = static_cast<int>(face.size());
    for (int c = 0; c < k; ++c) {
      const int v = face[c];
      if (vertex_to_bev_[v] < 0) {
        rebuilt.push_back(kept_vertex_id_[v]);
        continue;
      }
      const BevVert& bv = bev_verts_[vertex_to_bev_[v]];
      const int n = static_cast<int>(bv.edges.size());
      int h = 0;
      while (bv.edges[h].other != face[(c + 1) % k]) ++h;
      // The corner becomes the boundary vertices from the incoming edge's side back to the
      // outgoing edge's, with the profile points between them (bev_rebuild_polygon).
      const int count = static_cast<int>(bv.bounds.size());
      const int first = bv.edges[(h + 1) % n].leftv, last = bv.edges[h].rightv;
      rebuilt.push_back(OutputId(bv, first, 0, 0));
      for (int j = first; j != last;) {
        const int prev = (j + count - 1) % count;
        for (int s = ns - 1; s >= 1; --s) {
          if (bv.ids[Slot(bv, prev, 0, s)] >= 0 && bv.kind != Kind::kCubeCorner && bv.kind != Kind::kAdjacent && bv.kind != Kind::kPipe) {
            rebuilt.push_back(OutputId(bv, prev, 0, s));
          }
        }
        j = prev;
        rebuilt.push_back(OutputId(bv, j, 0, 0));
      }
    }
    output_faces_.push_back(rebuilt);
  }
  const size_t num_rebuilt = output_faces_.size();
  for (int f = 0; f < input.NumFaces(); ++f) {
    const Polygon& face = input.faces[f];
    for (int c = 0; c < static_cast<int>(face.size()); ++c) {
      const int a = face[c], b = face[(c + 1) % face.size()];
      if (a > b || !is_beveled(f, c)) continue;  // each beveled edge once
      const BevVert& bva = bev_verts_[vertex_to_bev_[a]];
      const BevVert& bvb = bev_verts_[vertex_to_bev_[b]];
      int ha = 0, hb = 0;
      while (bva.edges[ha].other != b) ++ha;
      while (bvb.edges[hb].other != a) ++hb;
      for (int s = 0; s < ns; ++s) {
        output_faces_.push_back({OutputId(bva, bva.edges[ha].leftv, 0, s), OutputId(bva, bva.edges[ha].leftv, 0, s + 1),
                                 OutputId(bvb, bvb.edges[hb].leftv, 0, ns - s - 1),
                                 OutputId(bvb, bvb.edges[hb].leftv, 0, ns - s)});
      }
    }
  }
  for (const BevVert& bv : bev_verts_) {
    const int n = static_cast<int>(bv.bounds.size());
    if (bv.kind == Kind::kPolygon || bv.kind == Kind::kTriangleFan || bv.kind == Kind::kTerminalPolygon) {
      Polygon poly;
      for (int i = 0; i < n; ++i) {
        poly.push_back(OutputId(bv, i, 0, 0));
        for (int k = 1; i == 0 && bv.kind != Kind::kPolygon && k < ns; ++k) poly.push_back(OutputId(bv, 0, 0, k));
      }
      if (bv.kind == Kind::kTriangleFan) {
        // bevel_build_trifan: a fan from the polygon's last vertex.
        const int m = static_cast<int>(poly.size());
        for (int i = 0; i + 2 < m; ++i) output_faces_.push_back({poly[m - 1], poly[i], poly[i + 1]});
      } else {
        output_faces_.push_back(poly);
      }
    } else if (bv.kind == Kind::kCubeCorner || bv.kind == Kind::kAdjacent || bv.kind == Kind::kPipe) {
      const int odd = ns % 2;
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < ns2; ++j) {
          for (int k = 0; k < ns2 + odd; ++k) {
            output_faces_.push_back({OutputId(bv, i, j, k), OutputId(bv, i, j, k + 1), OutputId(bv, i, j + 1, k + 1),
                                     OutputId(bv, i, j + 1, k)});
          }
        }
      }
      if (odd) {
        Polygon center;
        for (int i = 0; i < n; ++i) center.push_back(OutputId(bv, i, ns2, ns2));
        output_faces_.push_back(center);
      }
    }
  }
  // Orient new faces against their already oriented neighbours (breadth first from the
  // rebuilt originals, whose winding is the input's).
  OrientAgainstNeighbours(static_cast<int>(num_rebuilt), &output_faces_);
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
