// Bevel's topology pass after the boundaries (ops/bevel.h): each beveled vertex's mesh kind,
// the loop-slide chains adjust_offsets links, and tri_corner_test on the adjusted widths.
#include <algorithm>
#include <cmath>

#include "core/geometry.h"
#include "ops/bevel.h"

namespace opgraph {

void BevelOp::ChooseVertexMeshKind(const Mesh& input, const std::vector<Vec3d>& normals, BevVert* vertex) {
  BevVert& bv = *vertex;
  const int v = bv.vertex, n = static_cast<int>(bv.edges.size());
  const Vec3d& p = input.vertices[v];
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
}

void BevelOp::LinkLoopSlideChains() {
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
}

void BevelOp::KeepEqualWidthCubeCorners(const Mesh& input) {
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
}

}  // namespace opgraph
