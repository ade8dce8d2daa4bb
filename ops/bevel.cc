#include "ops/bevel.h"

#include <Eigen/Dense>
#include <algorithm>
#include <deque>
#include <limits>
#include <unordered_map>

#include "core/geometry.h"

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
  std::unordered_map<long long, std::vector<std::pair<int, int>>> edge_faces;  // edge -> (face, corner)
  std::vector<std::vector<std::pair<int, int>>> corners(num_vertices);
  for (int f = 0; f < input.NumFaces(); ++f) {
    const Polygon& face = input.faces[f];
    for (size_t c = 0; c < face.size(); ++c) {
      edge_faces[EdgeKey(face[c], face[(c + 1) % face.size()])].push_back({f, static_cast<int>(c)});
      corners[face[c]].push_back({f, static_cast<int>(c)});
    }
  }
  std::vector<Vec3d> normals(input.NumFaces());
  for (int f = 0; f < input.NumFaces(); ++f) normals[f] = SafeNormalized(FaceAreaNormal(input.vertices, input.faces[f]));

  // Beveled edges, as the modifier tags them (angle test in float, as Blender).
  const double threshold = std::cos(static_cast<float>(DegToRad(angle_limit_deg_)) + 0.000000175f);
  auto is_beveled = [&](int a, int b) {
    const auto it = edge_faces.find(EdgeKey(a, b));
    if (it == edge_faces.end() || it->second.size() != 2) return false;
    return !angle_limit_ || normals[it->second[0].first].dot(normals[it->second[1].first]) < threshold;
  };
  std::vector<bool> touched(num_vertices, false);
  bool any = false;
  for (const auto& [key, faces] : edge_faces) {
    const Polygon& face = input.faces[faces[0].first];
    const int a = face[faces[0].second], b = face[(faces[0].second + 1) % face.size()];
    if (is_beveled(a, b)) touched[a] = touched[b] = any = true;
  }
  if (!any) throw FieldError("limit_method", "no edge of the input is beveled");

  auto vertex_normal = [&](int v) {
    Vec3d n(0, 0, 0);
    for (const auto& [f, c] : corners[v]) {
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
    int beveled_here = 0;  // for messages before the fan is known
    for (const auto& [f0, c0] : corners[v]) {
      const Polygon& face = input.faces[f0];
      beveled_here += is_beveled(v, face[(c0 + 1) % face.size()]);
    }
    int f = corners[v][0].first, c = corners[v][0].second;
    for (size_t step = 0; step < corners[v].size(); ++step) {
      const Polygon& face = input.faces[f];
      const int k = static_cast<int>(face.size());
      const int b = face[(c + 1) % k], a = face[(c + k - 1) % k];
      EdgeHalf half;
      half.other = b;
      half.fnext = f;
      half.beveled = is_beveled(v, b);
      bv.edges.push_back(half);
      const auto& users = edge_faces[EdgeKey(v, a)];
      if (users.size() != 2) throw FieldError("limit_method", Unsupported(beveled_here, v, "on an open or non-manifold edge"));
      const auto& other = users[0].first == f ? users[1] : users[0];
      if (other.first == f) throw FieldError("limit_method", Unsupported(beveled_here, v, "an edge used twice by one face"));
      const Polygon& g = input.faces[other.first];
      const int kg = static_cast<int>(g.size());
      const int cg = g[other.second] == v ? other.second : (other.second + 1) % kg;
      if (g[(cg + 1) % kg] != a) throw FieldError("limit_method", Unsupported(beveled_here, v, "inconsistent face winding"));
      f = other.first;
      c = cg;
      if (f == corners[v][0].first && c == corners[v][0].second && step + 1 != corners[v].size()) {
        throw FieldError("limit_method", Unsupported(beveled_here, v, "more than one fan of faces"));
      }
    }
    const int n = static_cast<int>(bv.edges.size());
    for (int h = 0; h < n; ++h) bv.edges[(h + 1) % n].fprev = bv.edges[h].fnext;
    for (const EdgeHalf& e : bv.edges) bv.selcount += e.beveled;
    if (bv.selcount == 1 && n < 3) throw FieldError("limit_method", Unsupported(1, v, "a beveled edge ends at a vertex of valence 2"));

    // Boundary vertices (build_boundary), with the placement rule decided on the input.
    const Vec3d& p = input.vertices[v];
    const Vec3d vno = vertex_normal(v);
    auto on_plane = [&](int h) {
      const double dot = normals[bv.edges[h].fprev].dot(normals[bv.edges[h].fnext]);
      return std::abs(dot + 1) <= bevel::kEpsilonBig || std::abs(dot - 1) <= bevel::kEpsilonBig;
    };
    auto meets_edge = [&](int h1, int h2) {  // offset_meet_edge's success test
      const Vec3d d1 = (input.vertices[bv.edges[h1].other] - p).normalized();
      const Vec3d d2 = (input.vertices[bv.edges[h2].other] - p).normalized();
      const double ang = bevel::AngleNormalized<double>(d1, d2);
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
  for (const Polygon& face : input.faces) {
    for (size_t c = 0; c < face.size(); ++c) {
      const int a = face[c], b = face[(c + 1) % face.size()];
      if (a > b || !is_beveled(a, b)) continue;  // each beveled edge once
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
  std::unordered_map<long long, std::vector<int>> users;
  for (size_t f = 0; f < output_faces_.size(); ++f) {
    const Polygon& face = output_faces_[f];
    for (size_t c = 0; c < face.size(); ++c) users[EdgeKey(face[c], face[(c + 1) % face.size()])].push_back(static_cast<int>(f));
  }
  std::vector<bool> oriented(output_faces_.size(), false);
  std::deque<int> queue;
  for (size_t f = 0; f < num_rebuilt; ++f) {
    oriented[f] = true;
    queue.push_back(static_cast<int>(f));
  }
  while (!queue.empty()) {
    const int f = queue.front();
    queue.pop_front();
    const Polygon face = output_faces_[f];
    for (size_t c = 0; c < face.size(); ++c) {
      const int a = face[c], b = face[(c + 1) % face.size()];
      for (int g : users[EdgeKey(a, b)]) {
        if (oriented[g]) continue;
        Polygon& other = output_faces_[g];
        for (size_t d = 0; d < other.size(); ++d) {
          if (other[d] == a && other[(d + 1) % other.size()] == b) {
            std::reverse(other.begin(), other.end());
            break;
          }
        }
        oriented[g] = true;
        queue.push_back(g);
      }
    }
  }
}

namespace {

// The geometry pass of one bevel: all of Blender's per-vertex constructions on scalar T.
template <typename T>
class BevelGeometry {
 public:
  using BevVert = BevelOp::BevVert;
  using EdgeHalf = BevelOp::EdgeHalf;

  BevelGeometry(const Positions<T>& in, const std::vector<Polygon>& faces) : p_(in) {
    face_normals_.reserve(faces.size());
    for (const Polygon& f : faces) face_normals_.push_back(SafeNormalized(FaceAreaNormal(in, f)));
  }

  V3<T> VertexNormal(const BevVert& bv) const {
    const int n = static_cast<int>(bv.edges.size());
    V3<T> sum = bevel::Zero3<T>();
    for (int h = 0; h < n; ++h) {
      const V3<T>& v = p_[bv.vertex];
      sum += face_normals_[bv.edges[h].fnext] *
             bevel::Angle<T>(p_[bv.edges[h].other] - v, p_[bv.edges[(h + 1) % n].other] - v);
    }
    return SafeNormalized(sum);
  }

  V3<T> SlideDist(const BevVert& bv, int h, T d) const {
    const V3<T> dir = p_[bv.edges[h].other] - p_[bv.vertex];
    const T len = Norm(dir);
    if (Scalar(d) > Scalar(len)) d = len - T(50 * bevel::kEpsilon);
    return p_[bv.vertex] + dir * (d / len);
  }

  // Is co between edges h1 and h2 (CCW) in face f? (point_between_edges)
  bool PointBetweenEdges(const V3<T>& co, const BevVert& bv, int f, int h1, int h2) const {
    const V3<T>& v = p_[bv.vertex];
    const V3<T> dir1 = SafeNormalized<T>(v - p_[bv.edges[h1].other]);
    const V3<T> dir2 = SafeNormalized<T>(v - p_[bv.edges[h2].other]);
    const V3<T> dirco = SafeNormalized<T>(v - co);
    double ang11 = Scalar(bevel::AngleNormalized(dir1, dir2));
    double ang1co = Scalar(bevel::AngleNormalized(dir1, dirco));
    if (Scalar(dir1.cross(dir2).dot(face_normals_[f])) < 0) ang11 = 2 * kPi - ang11;
    if (Scalar(dir1.cross(dirco).dot(face_normals_[f])) < 0) ang1co = 2 * kPi - ang1co;
    return ang11 - ang1co > -bevel::kEpsilonAng;
  }

  // Meeting point of the offset lines of h1 (its right side) and h2 (its left side) (offset_meet).
  V3<T> OffsetMeet(const BevVert& bv, int h1, int h2, int f, bool edges_between, int e_in_plane, const T& off1,
                   const T& off2, const V3<T>& vno) const {
    const int n = static_cast<int>(bv.edges.size());
    const V3<T>& v = p_[bv.vertex];
    V3<T> dir1 = v - p_[bv.edges[h1].other];
    const V3<T> dir2 = p_[bv.edges[h2].other] - v;
    V3<T> dir1n = bevel::Zero3<T>(), dir2p = bevel::Zero3<T>();
    if (edges_between) {
      dir1n = p_[bv.edges[(h1 + 1) % n].other] - v;
      dir2p = v - p_[bv.edges[(h2 + n - 1) % n].other];
    }
    using std::cos;
    const T ang = bevel::Angle(dir1, dir2);
    if (Scalar(ang) < bevel::kEpsilonAng) {
      const V3<T> norm_v = f >= 0 ? face_normals_[f] : vno;
      dir1 += dir2;
      const V3<T> perp = SafeNormalized<T>(dir1.cross(norm_v));
      const T d = (Scalar(off1) >= Scalar(off2) ? off1 : off2) / cos(ang / T(2));
      return v + perp * d;
    }
    if (std::abs(Scalar(ang) - kPi) < bevel::kEpsilonAng) {
      return SlideDist(bv, h2, Scalar(off1) >= Scalar(off2) ? off1 : off2);
    }
    V3<T> norm_v1, norm_v2;
    if (f >= 0 && Scalar(ang) < bevel::kSmallAng) {
      norm_v1 = norm_v2 = face_normals_[f];
    } else if (!edges_between) {
      norm_v1 = SafeNormalized<T>(dir2.cross(dir1));
      if (Scalar(norm_v1.dot(f >= 0 ? face_normals_[f] : vno)) < 0) norm_v1 = -norm_v1;
      norm_v2 = norm_v1;
    } else {
      norm_v1 = SafeNormalized<T>(dir1n.cross(dir1));
      const int f1 = bv.edges[h1].fnext;
      if (Scalar(norm_v1.dot(f1 >= 0 ? face_normals_[f1] : vno)) < 0) norm_v1 = -norm_v1;
      norm_v2 = SafeNormalized<T>(dir2.cross(dir2p));
      const int f2 = bv.edges[h2].fprev;
      if (Scalar(norm_v2.dot(f2 >= 0 ? face_normals_[f2] : vno)) < 0) norm_v2 = -norm_v2;
    }
    const V3<T> perp1 = SafeNormalized<T>(dir1.cross(norm_v1));
    const V3<T> perp2 = SafeNormalized<T>(dir2.cross(norm_v2));
    const V3<T> off1a = v + perp1 * off1, off1b = off1a + dir1;
    const V3<T> off2a = v + perp2 * off2, off2b = off2a + dir2;
    V3<T> meet, isect2;
    const int kind = bevel::IsectLineLine(off1a, off1b, off2a, off2b, &meet, &isect2);
    if (kind == 0) return off1a;
    if (edges_between && Scalar(off1) > 0 && Scalar(off2) > 0) {
      if (kind == 2) meet = (meet + isect2) * T(0.5);
      for (int h = h1; h != h2; h = (h + 1) % n) {
        const int fn = bv.edges[h].fnext;
        const V3<T>& no = face_normals_[fn];
        const V3<T> drop = meet - no * no.dot(meet - v);
        if (e_in_plane >= 0) {
          const double a = Scalar(bevel::Angle(no, face_normals_[bv.edges[e_in_plane].fnext]));
          if (std::abs(a) < bevel::kSmallAng || std::abs(a - kPi) < bevel::kSmallAng) continue;
        }
        if (PointBetweenEdges(drop, bv, fn, h, (h + 1) % n)) {
          meet = drop;
          break;
        }
      }
    }
    return meet;
  }

  // offset_meet_edge: where the offset line of the beveled one of (h1, h2) meets the other.
  bool OffsetMeetEdge(const BevVert& bv, int h1, int h2, const T& off1_r, const T& off2_l, const V3<T>& vno,
                      V3<T>* meet, T* angle) const {
    const V3<T>& v = p_[bv.vertex];
    const V3<T> dir1 = SafeNormalized<T>(p_[bv.edges[h1].other] - v);
    const V3<T> dir2 = SafeNormalized<T>(p_[bv.edges[h2].other] - v);
    T ang = bevel::AngleNormalized(dir1, dir2);
    *angle = T(0);
    if (std::abs(Scalar(ang)) < bevel::kGoodAngle) return false;
    if (Scalar(dir1.cross(dir2).dot(vno)) < 0) {
      *angle = T(2 * kPi) - ang;
      return false;
    }
    *angle = ang;
    if (std::abs(Scalar(ang) - kPi) < bevel::kGoodAngle) return false;
    using std::sin;
    const T s = sin(ang);
    *meet = Scalar(off1_r) == 0 ? v + dir1 * (off2_l / s) : v + dir2 * (off1_r / s);
    return true;
  }

  const Positions<T>& p_;
  std::vector<V3<T>> face_normals_;
};

}  // namespace

// clamp_overlap (bevel_limit_offset / geometry_collide_offset): the smallest width at which the
// clone of an edge collapses (the offset lines of it and its two neighbours in a face meet), or
// a boundary vertex slides past the far end of an un-beveled edge.
template <typename T>
T BevelOp::ClampLimit(const Positions<T>& in) const {
  using std::sin;
  T limit(std::numeric_limits<double>::max());
  for (const BevVert& bv : bev_verts_) {
    const int n = static_cast<int>(bv.edges.size());
    const V3<T>& vb = in[bv.vertex];
    for (int h = 0; h < n; ++h) {
      const EdgeHalf& eb = bv.edges[h];
      const EdgeHalf& ea = bv.edges[(h + 1) % n];
      const int c = eb.other;
      const double kb = eb.beveled, ka = ea.beveled;
      double kc = 0;
      int d = -1;
      if (vertex_to_bev_[c] >= 0) {
        const BevVert& bvc = bev_verts_[vertex_to_bev_[c]];
        const int nc = static_cast<int>(bvc.edges.size());
        int hc = 0;
        while (bvc.edges[hc].other != bv.vertex) ++hc;
        const EdgeHalf& ec = bvc.edges[(hc + nc - 1) % nc];
        kc = ec.beveled;
        d = ec.other;
      } else {
        const Polygon& face = input_faces_[eb.fnext];
        const int k = static_cast<int>(face.size());
        for (int i = 0; i < k; ++i) {
          if (face[i] == c) d = face[(i + 1) % k] == bv.vertex ? face[(i + k - 1) % k] : face[(i + 1) % k];
        }
      }
      if (d < 0 || ea.other == c || d == bv.vertex) continue;
      const V3<T>& va = in[ea.other];
      const V3<T>& vc = in[c];
      const V3<T>& vd = in[d];
      const T th1 = bevel::Angle<T>(va - vb, vc - vb), th2 = bevel::Angle<T>(vb - vc, vd - vc);
      const T sin1 = sin(th1), sin2 = sin(th2);
      if ((ka > 0) + (kb > 0) + (kc > 0) >= 2) {
        // Blender's len * g h / (g (ka sin2 + kc sin1) + kb h (tan1 + tan2)), g = tan1 tan2,
        // h = sin1 sin2, divided through by g (stable at right angles, where tan is huge).
        const double g = std::tan(Scalar(th1)) * std::tan(Scalar(th2));
        const T den = ka * sin2 + kc * sin1 + kb * sin(th1 + th2);
        if (g != 0 && Scalar(den) != 0) {
          const T t = Norm<T>(vc - vb) * sin1 * sin2 / den;
          if (Scalar(t) >= 0 && Scalar(t) < Scalar(limit)) limit = t;
        }
      }
      if (kb > 0 && ka == 0) {
        const T t = Norm<T>(va - vb) * sin1 / kb;
        if (Scalar(t) >= 0 && Scalar(t) < Scalar(limit)) limit = t;
      }
      if (kb > 0 && kc == 0) {
        const T t = Norm<T>(vd - vc) * sin2 / kb;
        if (Scalar(t) >= 0 && Scalar(t) < Scalar(limit)) limit = t;
      }
    }
  }
  return limit;
}

// Boundary vertices of every beveled vertex (build_boundary), with the loop-slide width
// adjustment (adjust_offsets); *off_l gets the final left offsets of every edge half.
template <typename T>
void BevelOp::Boundaries(const Positions<T>& in, const T& width, std::vector<std::vector<T>>* off_l_out,
                         std::vector<std::vector<V3<T>>>* bounds_out) const {
  const BevelGeometry<T> geo(in, input_faces_);
  // Offsets: per bev vert and edge half, left and right (un-beveled edges: 0).
  off_l_out->assign(bev_verts_.size(), {});
  std::vector<std::vector<T>>& off_l = *off_l_out;
  std::vector<std::vector<T>> off_r(bev_verts_.size());
  for (size_t b = 0; b < bev_verts_.size(); ++b) {
    for (const EdgeHalf& e : bev_verts_[b].edges) {
      off_l[b].push_back(e.beveled ? width : T(0));
      off_r[b].push_back(e.beveled ? width : T(0));
    }
  }
  std::vector<V3<T>> vertex_normals;
  for (const BevVert& bv : bev_verts_) vertex_normals.push_back(geo.VertexNormal(bv));

  // Boundary vertices.
  auto bound_position = [&](size_t b, int i, T* sinratio) {
    const BevVert& bv = bev_verts_[b];
    const BoundVert& bnd = bv.bounds[i];
    const int e = bnd.efirst, e2 = bnd.elast;
    const V3<T>& vno = vertex_normals[b];
    *sinratio = T(1);
    switch (bnd.meet) {
      case Meet::kAdjacent:
        return geo.OffsetMeet(bv, e, e2, bv.edges[e].fnext, false, -1, off_r[b][e], off_l[b][e2], vno);
      case Meet::kBetweenNoFace:
        return geo.OffsetMeet(bv, e, e2, -1, true, bnd.e_in_plane, off_r[b][e], off_l[b][e2], vno);
      case Meet::kBetweenFace:
        return geo.OffsetMeet(bv, e, e2, bv.edges[e].fnext, true, bnd.e_in_plane, off_r[b][e], off_l[b][e2], vno);
      case Meet::kSlide:
        return geo.SlideDist(bv, e, width);
      case Meet::kOnEdgeBetween:
      default: {
        V3<T> meet1, meet2;
        T ang1, ang2;
        const int mid = bnd.eon;
        const bool ok1 = geo.OffsetMeetEdge(bv, e, mid, off_r[b][e], off_l[b][mid], vno, &meet1, &ang1);
        const bool ok2 = geo.OffsetMeetEdge(bv, mid, e2, off_r[b][mid], off_l[b][e2], vno, &meet2, &ang2);
        using std::sin;
        if (ok1 && ok2) {
          *sinratio = Scalar(ang1) == 0 ? T(1) : sin(ang2) / sin(ang1);
          return V3<T>((meet1 + meet2) * T(0.5));
        }
        if (ok1) return meet1;
        if (ok2) return meet2;
        return geo.SlideDist(bv, mid, off_r[b][e]);
      }
    }
  };

  bounds_out->assign(bev_verts_.size(), {});
  std::vector<std::vector<V3<T>>>& bounds = *bounds_out;
  std::vector<std::vector<T>> sinratios(bev_verts_.size());
  for (size_t b = 0; b < bev_verts_.size(); ++b) {
    for (size_t i = 0; i < bev_verts_[b].bounds.size(); ++i) {
      T r;
      bounds[b].push_back(bound_position(b, static_cast<int>(i), &r));
      sinratios[b].push_back(r);
    }
  }
  // Loop slide: make the widths at both ends of the beveled edges agree (adjust_offsets).
  if (!chains_.empty()) {
    for (const Chain& chain : chains_) {
      const int np = static_cast<int>(chain.links.size());
      const int nrows = chain.cycle ? 3 * np : 3 * np - 3;
      using Matrix = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
      using Vector = Eigen::Matrix<T, Eigen::Dynamic, 1>;
      Matrix a = Matrix::Constant(nrows, np, T(0));
      Vector rhs = Vector::Constant(nrows, T(0));
      const T weight(0.2);
      for (int i = 0; i < np; ++i) {
        const ChainLink& link = chain.links[i];
        const BoundVert& v = bev_verts_[link.bv].bounds[link.bnd];
        const T& sinratio = sinratios[link.bv][link.bnd];
        if (chain.cycle || i < np - 1) {
          const ChainLink& next = chain.links[(i + 1) % np];
          const BoundVert& vnext = bev_verts_[next.bv].bounds[next.bnd];
          a(i, i) += T(1);
          if (chain.cycle) {
            a(i > 0 ? i - 1 : np - 1, i) -= sinratio;
          } else if (i > 0) {
            a(i - 1, i) -= sinratio;
          }
          const int row = chain.cycle ? np + 2 * i : np - 1 + 2 * i;
          a(row, i) += weight;
          rhs(row) += weight * off_r[link.bv][v.efirst];
          a(row + 1, i == np - 1 ? 0 : i + 1) += weight * sinratios[next.bv][next.bnd];
          rhs(row + 1) += weight * off_l[next.bv][vnext.elast];
        } else {
          a(i - 1, i) -= T(1);
        }
      }
      const Vector x = (a.transpose() * a).ldlt().solve(a.transpose() * rhs);
      for (int i = 0; i < np; ++i) {
        const ChainLink& link = chain.links[i];
        const BoundVert& v = bev_verts_[link.bv].bounds[link.bnd];
        if (chain.cycle || i < np - 1) {
          off_r[link.bv][v.efirst] = x(i);
          if (chain.cycle || i > 0) off_l[link.bv][v.elast] = sinratios[link.bv][link.bnd] * x(i);
        } else {
          off_l[link.bv][v.elast] = x(i);
        }
      }
    }
    // Rebuild the boundaries with the adjusted widths.
    for (size_t b = 0; b < bev_verts_.size(); ++b) {
      for (size_t i = 0; i < bev_verts_[b].bounds.size(); ++i) {
        T r;
        bounds[b][i] = bound_position(b, static_cast<int>(i), &r);
      }
    }
  }
}

template <typename T>
void BevelOp::Apply(const T* p, const T& gate, const Positions<T>& in, Positions<T>* out) const {
  out->assign(num_output_vertices_, bevel::Zero3<T>());
  for (size_t v = 0; v < in.size(); ++v) {
    if (kept_vertex_id_[v] >= 0) (*out)[kept_vertex_id_[v]] = in[v];
  }
  T width = gate * p[0];
  const T limit = ClampLimit(in);
  if (Scalar(limit) < Scalar(width)) width = limit;
  const int ns = segments_;

  std::vector<std::vector<T>> off_l;
  std::vector<std::vector<V3<T>>> bounds;
  Boundaries(in, width, &off_l, &bounds);

  for (size_t b = 0; b < bev_verts_.size(); ++b) {
    const BevVert& bv = bev_verts_[b];
    const int n = static_cast<int>(bv.bounds.size());
    const V3<T>& v = in[bv.vertex];
    // Profiles (set_profile_params + calculate_profile).
    std::vector<bevel::Profile<T>> profiles(n);
    for (int i = 0; i < n; ++i) {
      bevel::Profile<T>& pro = profiles[i];
      const V3<T>& start = bounds[b][i];
      const V3<T>& end = bounds[b][(i + 1) % n];
      const int h = bv.bounds[i].ebev;
      const int ne = static_cast<int>(bv.edges.size());
      bool linear = false;
      pro.start = start;
      pro.end = end;
      if (h < 0) {  // no beveled edge starts here: a straight segment
        pro.line = true;
        pro.middle = (start + end) * T(0.5);
        continue;
      }
      pro.proj_dir = SafeNormalized<T>(v - in[bv.edges[h].other]);
      V3<T> other_point;
      if (bevel::IsectLineLine(v, in[bv.edges[h].other], start, end, &pro.middle, &other_point) == 0) pro.middle = v;
      V3<T> d1 = SafeNormalized<T>(pro.middle - start), d2 = SafeNormalized<T>(pro.middle - end);
      pro.plane_no = SafeNormalized<T>(d1.cross(d2));
      if (bevel::NearlyParallel(d1, d2)) {
        pro.middle = v;
        const EdgeHalf& eprev = bv.edges[(h + ne - 1) % ne];
        const EdgeHalf& enext = bv.edges[(h + 1) % ne];
        if (eprev.beveled && enext.beveled && bv.selcount >= 3) {
          const V3<T> d3 = SafeNormalized<T>(in[eprev.other] - v), d4 = SafeNormalized<T>(in[enext.other] - v);
          V3<T> meet, meet2;
          if (bevel::NearlyParallel(d3, d4) || bevel::IsectLineLine<T>(start, start + d3, end, end + d4, &meet, &meet2) == 0) {
            linear = true;
          } else {
            pro.middle = meet;
          }
        }
        d1 = SafeNormalized<T>(pro.middle - start);
        d2 = SafeNormalized<T>(pro.middle - end);
        pro.plane_no = SafeNormalized<T>(d1.cross(d2));
        if (bevel::NearlyParallel(d1, d2)) {
          linear = true;
        } else {
          pro.proj_dir = pro.plane_no;
        }
      }
      pro.plane_co = start;
      if (linear) {
        pro.line = true;
        pro.middle = (start + end) * T(0.5);
        pro.plane_co = pro.plane_no = pro.proj_dir = bevel::Zero3<T>();
      } else {
        pro.line = false;
      }
    }
    if (bv.selcount == 1 && !profiles[0].line) {
      // move_profile_plane: the terminal profile onto the plane through v and its two ends.
      bevel::Profile<T>& pro = profiles[0];
      const V3<T> d1 = SafeNormalized<T>(v - pro.start), d2 = SafeNormalized<T>(v - pro.end);
      V3<T> no = d1.cross(d2), no2 = d1.cross(pro.proj_dir), no3 = d2.cross(pro.proj_dir);
      const double eps = bevel::kEpsilonBig;
      if (Scalar(Norm(no)) > eps && Scalar(Norm(no2)) > eps && Scalar(Norm(no3)) > eps) {
        no = SafeNormalized(no);
        no2 = SafeNormalized(no2);
        no3 = SafeNormalized(no3);
        if (std::abs(Scalar(no.dot(no2))) < 1 - eps && std::abs(Scalar(no.dot(no3))) < 1 - eps) pro.plane_no = no;
      }
    }
    if (bv.kind == Kind::kWeld) {
      // move_weld_profile_planes: both profiles onto the plane through v and the two bound verts.
      bevel::Profile<T>& p1 = profiles[bv.weld1];
      bevel::Profile<T>& p2 = profiles[bv.weld2];
      if (!bevel::IsZero(p1.proj_dir) && !bevel::IsZero(p2.proj_dir)) {
        const V3<T> d1 = v - bounds[b][bv.weld1], d2 = v - bounds[b][bv.weld2];
        V3<T> no = d1.cross(d2), no2 = d1.cross(p1.proj_dir), no3 = d2.cross(p2.proj_dir);
        const double l1 = Scalar(no.squaredNorm()), l2 = Scalar(no2.squaredNorm()), l3 = Scalar(no3.squaredNorm());
        no = SafeNormalized(no);
        no2 = SafeNormalized(no2);
        no3 = SafeNormalized(no3);
        const double eps2 = bevel::kEpsilon * bevel::kEpsilon;
        if (l1 > eps2 && (l2 > eps2 || l3 > eps2)) {
          if (std::abs(std::abs(Scalar(no.dot(no2))) - 1) > bevel::kEpsilon) p1.plane_no = no;
          if (std::abs(std::abs(Scalar(no.dot(no3))) - 1) > bevel::kEpsilon) p2.plane_no = no;
        }
      }
    }
    for (bevel::Profile<T>& pro : profiles) pro.Calculate(spacing_);

    // The vertex mesh.
    bevel::VGrid<T> grid(n, ns);
    for (int i = 0; i < n; ++i) grid.at(i, 0, 0) = bounds[b][i];
    if (bv.kind == Kind::kWeld) {
      const bevel::Profile<T>& p1 = profiles[bv.weld1];
      const bevel::Profile<T>& p2 = profiles[bv.weld2];
      for (int k = 1; k < ns; ++k) {
        const V3<T> va = p1.Point(spacing_, k, ns), vb = p2.Point(spacing_, ns - k, ns);
        if (p1.line && !p2.line) {
          grid.at(bv.weld1, 0, k) = vb;
        } else if (p2.line && !p1.line) {
          grid.at(bv.weld1, 0, k) = va;
        } else {
          grid.at(bv.weld1, 0, k) = (va + vb) * T(0.5);
        }
      }
    } else if (bv.selcount == 1) {
      for (int k = 1; k < ns; ++k) grid.at(0, 0, k) = profiles[0].Point(spacing_, k, ns);
    } else if (bv.kind == Kind::kCubeCorner) {
      // make_unit_cube_map: (1,0,0), (0,1,0), (0,0,1), (1,1,1) -> bound verts 0, 1, 2 and v.
      const V3<T>& va = bounds[b][0];
      const V3<T>& vb = bounds[b][1];
      const V3<T>& vc = bounds[b][2];
      const V3<T> c0 = (va - vb - vc + v) * T(0.5), c1 = (vb - va - vc + v) * T(0.5);
      const V3<T> c2 = (vc - va - vb + v) * T(0.5), c3 = (va + vb + vc - v) * T(0.5);
      for (size_t s = 0; s < grid.co.size(); ++s) {
        const Vec3d& q = octant_.co[s];
        grid.co[s] = c0 * T(q[0]) + c1 * T(q[1]) + c2 * T(q[2]) + c3;
      }
      for (int i = 0; i < n; ++i) grid.at(i, 0, 0) = bounds[b][i];
    } else if (bv.kind == Kind::kAdjacent || bv.kind == Kind::kPipe) {
      // adj_vmesh: a 2-segment control mesh with its centre pulled toward v by the profile's
      // fullness, refined by cubic subdivision and resampled to the segment count.
      bevel::VGrid<T> vm0(n, 2);
      V3<T> center = bevel::Zero3<T>();
      for (int i = 0; i < n; ++i) {
        vm0.at(i, 0, 0) = bounds[b][i];
        vm0.at(i, 0, 1) = profiles[i].Point(spacing_, 1, 2);
        center += bounds[b][i];
      }
      center /= T(static_cast<double>(n));
      const V3<T> direction = v - center;
      vm0.at(0, 1, 1) = Scalar(direction.squaredNorm()) > 1e-12 ? V3<T>(center + direction * T(spacing_.fullness)) : center;
      vm0.CopyEquiv();
      const bevel::ProfilePointFn<T> profile_point = [&](int i, int k, int nseg) {
        return profiles[i].Point(spacing_, k, nseg);
      };
      grid = bevel::SubdivideToSegments(vm0, ns, profile_point, true);
      if (bv.kind == Kind::kPipe) {
        // pipe_adj_vmesh: snap the interior onto the pipe's profile, in the plane through each
        // point perpendicular to the pipe (snap_to_pipe_profile, r = 2).
        const bevel::Profile<T>& pro = profiles[bv.pipe];
        const V3<T> edir = SafeNormalized<T>(v - in[bv.edges[bv.bounds[bv.pipe].ebev].other]);
        for (int i = 0; i < n; ++i) {
          for (int j = 1; j <= ns / 2; ++j) {
            for (int k = 0; k <= ns / 2; ++k) {
              if (!bevel::IsCanon(ns, i, j, k)) continue;
              V3<T>& co = grid.at(i, j, k);
              if (Scalar((pro.start - pro.end).cwiseAbs().maxCoeff()) <= bevel::kEpsilon) {
                co = pro.start;
                continue;
              }
              auto to_plane = [&](const V3<T>& q) { return V3<T>(q - edir * edir.dot(q - co)); };
              bevel::Profile<T> flat;
              flat.start = to_plane(pro.start);
              flat.middle = to_plane(pro.middle);
              flat.end = to_plane(pro.end);
              V3<T> c0, c1, c3;
              if (flat.UnitSquareMap(&c0, &c1, &c3)) {
                Eigen::Matrix<T, 3, 3> m;
                m.col(0) = c0;
                m.col(1) = c1;
                m.col(2) = SafeNormalized<T>(c1.cross(c0));
                const V3<T> q = SafeNormalized<T>(V3<T>(m.inverse() * (co - c3)));
                co = m * q + c3;
              } else {
                const V3<T> ab = flat.end - flat.start;
                T t = ab.dot(co - flat.start) / ab.dot(ab);
                if (Scalar(t) < 0) t = T(0);
                if (Scalar(t) > 1) t = T(1);
                co = flat.start + ab * t;
              }
            }
          }
        }
        grid.CopyEquiv();
      }
      for (int i = 0; i < n; ++i) grid.at(i, 0, 0) = bounds[b][i];
    }
    for (size_t s = 0; s < bv.ids.size(); ++s) {
      if (bv.ids[s] >= 0) (*out)[bv.ids[s]] = grid.co[s];
    }
  }
}

template void BevelOp::Apply<double>(const double*, const double&, const Positions<double>&,
                                     Positions<double>*) const;
template void BevelOp::Apply<JetT>(const JetT*, const JetT&, const Positions<JetT>&, Positions<JetT>*) const;

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
