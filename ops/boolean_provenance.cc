#include "ops/boolean_provenance.h"

#include <algorithm>
#include <map>

#include "ops/halfedge_topology.h"

namespace opgraph {
namespace {

using Source = BooleanOp::Source;

double SegmentDistance(const Vec3d& p, const Vec3d& a, const Vec3d& b) {
  const Vec3d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
  return (a + t * ab - p).norm();
}

// Whether p lies on triangle abc (within `tolerance`); sets *unit_normal.
bool OnTriangle(const Vec3d& p, const Vec3d& a, const Vec3d& b, const Vec3d& c, double tolerance,
                Vec3d* unit_normal) {
  const Vec3d n = (b - a).cross(c - a);
  if (n.norm() <= 1e-300) return false;
  *unit_normal = n.normalized();
  if (std::abs(unit_normal->dot(p - a)) > tolerance) return false;
  const Vec3d corners[3] = {a, b, c};
  for (int i = 0; i < 3; ++i) {
    const Vec3d& u = corners[i];
    const Vec3d& v = corners[(i + 1) % 3];
    if ((v - u).cross(p - u).dot(*unit_normal) / (v - u).norm() < -tolerance) return false;
  }
  return true;
}

}  // namespace

// CGAL can return one point twice, a rounding apart (a primitive's edge through the diagonal of a
// triangulated input face, met from both triangles), where Blender's exact boolean has one
// vertex: triangles are remapped to the first of points within `tolerance` of each other, and
// those that collapse are dropped (the unused duplicates stay, unreferenced).
void WeldCoincidentPoints(double tolerance, TriangleSoup* soup) {
  const int n = static_cast<int>(soup->vertices.size());
  std::vector<int> order(n), same(n);
  for (int v = 0; v < n; ++v) order[v] = same[v] = v;
  std::sort(order.begin(), order.end(), [soup](int x, int y) { return soup->vertices[x].x() < soup->vertices[y].x(); });
  bool welded = false;
  for (int i = 0; i < n; ++i) {
    const int u = order[i];
    if (same[u] != u) continue;
    for (int j = i + 1; j < n && soup->vertices[order[j]].x() - soup->vertices[u].x() <= tolerance; ++j) {
      const int w = order[j];
      if (same[w] == w && (soup->vertices[w] - soup->vertices[u]).norm() <= tolerance) same[w] = u, welded = true;
    }
  }
  if (!welded) return;
  std::vector<std::array<int, 3>> triangles;
  for (const auto& t : soup->triangles) {
    const std::array<int, 3> w = {same[t[0]], same[t[1]], same[t[2]]};
    if (w[0] != w[1] && w[1] != w[2] && w[0] != w[2]) triangles.push_back(w);
  }
  soup->triangles = std::move(triangles);
}

// Provenance of CGAL's vertices, recovered geometrically (CGAL's points are its exact ones
// rounded to double): an operand vertex at the same coordinates, else the best conditioned
// crossing of an edge of one operand with a triangle of the other through the point.
std::vector<Source> VertexSources(const Operands& ops, const TriangleSoup& result) {
  // The triangulation edges near the other operand (lower vertex first, as crossings record them).
  std::vector<std::pair<int, int>> edges[2];
  std::vector<std::array<int, 3>> near_triangles[2];
  std::map<std::array<double, 3>, int> vertex_at[2];  // exact coordinates -> operand vertex
  for (int m = 0; m < 2; ++m) {
    const TriangleSoup& soup = *ops.soups[m];
    const HalfedgeTopology topology(soup.triangles, static_cast<int>(soup.vertices.size()));
    for (int e = 0; e < topology.NumEdges(); ++e) {
      const auto [from, to] = topology.EdgeVertices(e);
      if (ops.NearOther(m, {from, to})) edges[m].push_back({std::min(from, to), std::max(from, to)});
    }
    for (const auto& t : soup.triangles) {
      if (ops.NearOther(m, {t[0], t[1], t[2]})) near_triangles[m].push_back(t);
    }
    for (size_t v = 0; v < soup.vertices.size(); ++v) {
      const Vec3d& q = soup.vertices[v];
      vertex_at[m].insert({{q.x(), q.y(), q.z()}, static_cast<int>(v)});
    }
  }
  std::vector<Source> sources(result.vertices.size());
  double worst = 1.0;  // the sine of the worst conditioned crossing
  for (size_t r = 0; r < result.vertices.size(); ++r) {
    const Vec3d& p = result.vertices[r];
    Source& s = sources[r];
    s.vertex = -1;
    for (int m = 0; m < 2 && s.vertex < 0; ++m) {
      const auto it = vertex_at[m].find({p.x(), p.y(), p.z()});
      if (it != vertex_at[m].end()) {
        s.kind = m == 0 ? Source::kInput : Source::kPrimitive;
        s.vertex = it->second;
      }
    }
    if (s.vertex >= 0) continue;
    // A crossing: the best conditioned (edge of one operand, triangle of the other) through p.
    double best = 1e-6;
    for (int m = 0; m < 2; ++m) {
      const TriangleSoup& mine = *ops.soups[m];
      const TriangleSoup& other = *ops.soups[1 - m];
      for (const auto& e : edges[m]) {
        const Vec3d& from = mine.vertices[e.first];
        const Vec3d& to = mine.vertices[e.second];
        if (SegmentDistance(p, from, to) > ops.tolerance) continue;
        const Vec3d direction = (to - from).normalized();
        for (const auto& t : near_triangles[1 - m]) {
          Vec3d n;
          if (!OnTriangle(p, other.vertices[t[0]], other.vertices[t[1]], other.vertices[t[2]], ops.tolerance, &n)) continue;
          const double conditioning = std::abs(n.dot(direction));
          if (conditioning > best) {
            best = conditioning;
            s.kind = Source::kCrossing;
            s.edge_on_primitive = m == 1;
            s.edge = {e.first, e.second};
            s.plane = t;
          }
        }
      }
    }
    if (best <= 1e-6) throw FieldError("operation", "internal: an intersection point of the boolean has no source");
    worst = std::min(worst, best);
  }
  // A grazing crossing (an edge within a few degrees of the plane it crosses) moves along the
  // edge by the plane's rounding error over the sine: Blender's float32 coordinates would put it
  // elsewhere, so the sequence would not rebuild the same mesh there. The worst is named, so the
  // message does not depend on the order of CGAL's points.
  if (worst < kMinCrossingSine) {
    throw FieldError("operation", "the primitive crosses the mesh at a grazing angle (" +
                                      std::to_string(std::asin(worst) * 180 / kPi).substr(0, 4) +
                                      " degrees): the intersection is ill-conditioned");
  }
  return sources;
}

// The source polygon (input's, then primitive's) and operand triangle (likewise) of each result
// triangle: the operand triangle it is (uncut), else the one its centroid lies on, parallel to
// it; the input mesh wins where both operands overlap.
void TriangleSources(const Operands& ops, int num_input_faces, const TriangleSoup& result,
                     const std::vector<Source>& sources, std::vector<int>* source_face,
                     std::vector<int>* source_triangle) {
  const int num_result_triangles = static_cast<int>(result.triangles.size());
  source_face->assign(num_result_triangles, -1);
  source_triangle->assign(num_result_triangles, -1);
  std::map<std::array<int, 3>, int> triangle_with_corners[2];  // sorted corners -> triangle
  std::vector<bool> near[2];
  for (int m = 0; m < 2; ++m) {
    const std::vector<SourceTriangle>& triangles = *ops.triangles[m];
    for (size_t k = 0; k < triangles.size(); ++k) {
      std::array<int, 3> c = triangles[k].corners;
      near[m].push_back(ops.NearOther(m, {c[0], c[1], c[2]}));
      std::sort(c.begin(), c.end());
      triangle_with_corners[m][c] = static_cast<int>(k);
    }
  }
  for (int r = 0; r < num_result_triangles; ++r) {
    const auto& t = result.triangles[r];
    for (int m = 0; m < 2 && (*source_face)[r] < 0; ++m) {
      const Source::Kind kind = m == 0 ? Source::kInput : Source::kPrimitive;
      std::array<int, 3> corners;
      bool all_original = true;
      for (int i = 0; i < 3; ++i) {
        all_original = all_original && sources[t[i]].kind == kind;
        corners[i] = sources[t[i]].vertex;
      }
      if (!all_original) continue;
      std::sort(corners.begin(), corners.end());
      const auto it = triangle_with_corners[m].find(corners);
      if (it == triangle_with_corners[m].end()) continue;
      const std::vector<SourceTriangle>& triangles = *ops.triangles[m];
      (*source_face)[r] = (m == 0 ? 0 : num_input_faces) + triangles[it->second].face;
      (*source_triangle)[r] = (m == 0 ? 0 : static_cast<int>(ops.triangles[0]->size())) + it->second;
    }
    if ((*source_face)[r] >= 0) continue;
    const Vec3d& p0 = result.vertices[t[0]];
    const Vec3d& p1 = result.vertices[t[1]];
    const Vec3d& p2 = result.vertices[t[2]];
    const Vec3d centroid = (p0 + p1 + p2) / 3;
    const Vec3d normal = (p1 - p0).cross(p2 - p0).normalized();
    double best = 1 - 1e-6;
    for (int m = 0; m < 2 && (*source_face)[r] < 0; ++m) {
      const TriangleSoup& operand = *ops.soups[m];
      const std::vector<SourceTriangle>& triangles = *ops.triangles[m];
      for (size_t k = 0; k < triangles.size(); ++k) {
        if (!near[m][k]) continue;
        const auto& c = triangles[k].corners;
        Vec3d n;
        const Vec3d& c0 = operand.vertices[c[0]];
        if (!OnTriangle(centroid, c0, operand.vertices[c[1]], operand.vertices[c[2]], ops.tolerance, &n)) continue;
        if (std::abs(n.dot(normal)) > best) {
          best = std::abs(n.dot(normal));
          (*source_face)[r] = (m == 0 ? 0 : num_input_faces) + triangles[k].face;
          (*source_triangle)[r] = (m == 0 ? 0 : static_cast<int>(ops.triangles[0]->size())) + static_cast<int>(k);
        }
      }
    }
    if ((*source_face)[r] < 0) throw FieldError("operation", "internal: a face of the boolean has no source");
  }
}

}  // namespace opgraph
