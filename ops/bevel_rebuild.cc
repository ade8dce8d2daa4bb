// Bevel's output topology (ops/bevel.h): the output vertices' numbering (kept vertices, then
// each beveled vertex's grid) and the faces (the input's rebuilt, the edges' strips, the vertex
// meshes), oriented against their neighbours.
#include "ops/bevel.h"
#include "ops/halfedge_topology.h"
#include "ops/orient_against_neighbours.h"

namespace opgraph {

void BevelOp::NumberOutputVertices(int num_vertices) {
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
}

void BevelOp::BuildFaces(const Mesh& input, const HalfedgeTopology& topology, const std::vector<bool>& beveled) {
  auto is_beveled = [&](int f, int c) { return beveled[topology.CornerEdge(f, c)]; };
  const int ns = segments_, ns2 = ns / 2;
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

}  // namespace opgraph
