#include "ops/boolean_triangulation.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/geometry.h"
#include "ops/halfedge_topology.h"

namespace opgraph {
namespace {

// Sign of the turn a -> b -> c in 2D: 1 convex (counter-clockwise), -1 concave, 0 straight.
int TurnSign(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  const double area = (a.x() - c.x()) * (b.y() - c.y()) - (a.y() - c.y()) * (b.x() - c.x());
  return area > 0 ? 1 : (area < 0 ? -1 : 0);
}

// Blender's BLI_polyfill_calc on a counter-clockwise 2D polygon, as the exact boolean calls it:
// ear clipping from vertex 0 that skips to every other vertex after a cut and sweeps back and
// forth when the next candidate is not convex. Returns #P - 2 triangles of polygon positions.
std::vector<std::array<int, 3>> PolyFill(const std::vector<Eigen::Vector2d>& co) {
  const int n = static_cast<int>(co.size());
  std::vector<int> next(n), prev(n), sign(n);
  for (int i = 0; i < n; ++i) next[i] = (i + 1) % n, prev[i] = (i + n - 1) % n;
  int num_concave = 0;
  for (int i = 0; i < n; ++i) {
    sign[i] = TurnSign(co[prev[i]], co[i], co[next[i]]);
    num_concave += sign[i] != 1;
  }
  auto is_ear = [&](int tip) {
    if (num_concave == 0) return true;
    if (sign[tip] != 1) return false;
    const Eigen::Vector2d &v1 = co[prev[tip]], &v2 = co[tip], &v3 = co[next[tip]];
    for (int c = next[next[tip]]; c != prev[tip]; c = next[c]) {
      if (sign[c] == 1) continue;
      if (TurnSign(v1, v2, co[c]) != -1 && TurnSign(v2, v3, co[c]) != -1 && TurnSign(v3, v1, co[c]) != -1) {
        return false;
      }
    }
    return true;
  };
  std::vector<std::array<int, 3>> triangles;
  int remaining = n, init = 0;
  bool reverse = false;
  while (remaining > 3) {
    int ear = init;
    bool found = false;
    for (int i = 0; i < remaining && !found; ++i) {
      if (is_ear(ear)) found = true;
      else ear = reverse ? prev[ear] : next[ear];
    }
    if (!found) ear = init;  // a degenerate polygon; the caller falls back on exact triangulation
    const int p = prev[ear], q = next[ear];
    triangles.push_back({p, ear, q});
    next[p] = q;
    prev[q] = p;
    --remaining;
    for (int v : {p, q}) {
      if (sign[v] == 1) continue;
      sign[v] = TurnSign(co[prev[v]], co[v], co[next[v]]);
      if (sign[v] == 1) --num_concave;
    }
    init = reverse ? prev[p] : next[q];
    if (sign[init] != 1) {
      init = reverse ? prev[init] : next[init];
      reverse = !reverse;
    }
  }
  triangles.push_back({prev[init], init, next[init]});
  return triangles;
}

// Ear clipping of a counter-clockwise 2D polygon that only cuts strictly convex ears with no
// other vertex inside or on them (no degenerate triangles where the polygon has straight
// corners), trying tips from vertex 1 on. Falls back on any tip for a polygon it cannot cut.
std::vector<std::array<int, 3>> EarClip(const std::vector<Eigen::Vector2d>& co) {
  std::vector<int> loop(co.size());
  std::iota(loop.begin(), loop.end(), 0);
  std::vector<std::array<int, 3>> triangles;
  while (loop.size() > 3) {
    const int k = static_cast<int>(loop.size());
    int ear = 1;
    for (int i = 1; i <= k; ++i) {
      const int c = i % k;
      const int a = loop[(c + k - 1) % k], b = loop[c], d = loop[(c + 1) % k];
      if (TurnSign(co[a], co[b], co[d]) != 1) continue;
      bool empty = true;
      for (int j = 0; j < k && empty; ++j) {
        const int q = loop[j];
        if (q == a || q == b || q == d || co[q] == co[a] || co[q] == co[b] || co[q] == co[d]) continue;
        empty = !(TurnSign(co[a], co[b], co[q]) != -1 && TurnSign(co[b], co[d], co[q]) != -1 &&
                  TurnSign(co[d], co[a], co[q]) != -1);
      }
      if (empty) {
        ear = c;
        break;
      }
    }
    triangles.push_back({loop[(ear + k - 1) % k], loop[ear], loop[(ear + 1) % k]});
    loop.erase(loop.begin() + ear);
  }
  triangles.push_back({loop[0], loop[1], loop[2]});
  return triangles;
}

}  // namespace

int DominantAxis(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  int axis;
  (b - a).cross(c - a).cwiseAbs().maxCoeff(&axis);
  return axis;
}

std::vector<TwoSidedEdge> TwoSidedEdges(const std::vector<std::array<int, 3>>& triangles, int num_vertices) {
  const HalfedgeTopology topology(triangles, num_vertices);
  std::vector<TwoSidedEdge> edges;
  for (int e = 0; e < topology.NumEdges(); ++e) {
    const auto [a, b] = topology.EdgeVertices(e);
    const int from = std::min(a, b), to = std::max(a, b);
    const int left = topology.EdgeFace(from, to), right = topology.EdgeFace(to, from);
    if (left >= 0 && right >= 0) edges.push_back({from, to, left, right});
  }
  std::sort(edges.begin(), edges.end(), [](const TwoSidedEdge& x, const TwoSidedEdge& y) {
    return x.from != y.from ? x.from < y.from : x.to < y.to;
  });
  return edges;
}

void DelaunayFlips(const Positions<double>& vertices, const std::vector<int>& group, const std::vector<int>& axis,
                   std::vector<std::array<int, 3>>* triangles) {
  if (vertices.empty() || std::all_of(group.begin(), group.end(), [](int g) { return g < 0; })) return;
  Vec3d lo = vertices[0], hi = vertices[0];
  for (const Vec3d& v : vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  const double tie = 1e-12 * std::pow((hi - lo).norm(), 4);
  for (int pass = 0; pass < 1000; ++pass) {
    std::vector<bool> touched(triangles->size(), false);
    bool flipped = false;
    for (const TwoSidedEdge& e : TwoSidedEdges(*triangles, static_cast<int>(vertices.size()))) {
      const int u = e.from, v = e.to, left = e.left, right = e.right;
      if (group[left] < 0 || group[left] != group[right] || touched[left] || touched[right]) continue;
      auto third = [&](int t) {
        for (int c : (*triangles)[t]) {
          if (c != u && c != v) return c;
        }
        return -1;
      };
      const int w = third(left), x = third(right);
      if (w < 0 || x < 0 || w == x) continue;  // a degenerate triangle (repeated corner) cannot flip
      auto project = [&](int vertex) {
        const Vec3d& q = vertices[vertex];
        return Eigen::Vector2d(q[(axis[left] + 1) % 3], q[(axis[left] + 2) % 3]);
      };
      const Eigen::Vector2d pu = project(u), pv = project(v), pw = project(w), px = project(x);
      const double orientation = (pv - pu).x() * (pw - pu).y() - (pv - pu).y() * (pw - pu).x();
      Eigen::Matrix3d in_circle;
      const Eigen::Vector2d rows[3] = {pu - px, pv - px, pw - px};
      for (int i = 0; i < 3; ++i) in_circle.row(i) << rows[i].x(), rows[i].y(), rows[i].squaredNorm();
      const double side = orientation > 0 ? 1 : -1;
      auto area = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
        return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
      };
      // Only a strictly convex quad can flip (guards against degenerate triangles).
      if (side * area(pu, px, pw) <= 0 || side * area(px, pv, pw) <= 0) continue;
      if (in_circle.determinant() * side <= tie) continue;
      // (u, v, w) and (v, u, x) become (u, x, w) and (x, v, w), same winding.
      (*triangles)[left] = {u, x, w};
      (*triangles)[right] = {x, v, w};
      touched[left] = touched[right] = flipped = true;
    }
    if (!flipped) return;
  }
}

// Blender's triangulation of the boolean's operands (mesh_boolean's triangulate_poly): quads
// along the 0-2 diagonal unless that splits them badly (then 1-3), larger polygons by PolyFill in
// the plane perpendicular to their normal; where that makes a degenerate triangle, Blender uses
// its exact constrained Delaunay triangulation, emulated here by flips (a cocircular tie left as
// the ear clipping made it, where Blender's choice follows its own insertion order).
std::vector<SourceTriangle> Triangulate(const Mesh& mesh) {
  std::vector<SourceTriangle> triangles;
  std::vector<int> group, axis;
  for (int f = 0; f < mesh.NumFaces(); ++f) {
    const Polygon& loop = mesh.faces[f];
    const int k = static_cast<int>(loop.size());
    const Vec3d normal = FaceAreaNormal(mesh.vertices, loop).normalized();
    int dominant;
    normal.cwiseAbs().maxCoeff(&dominant);
    std::vector<std::array<int, 3>> local;
    if (k == 3) {
      local = {{0, 1, 2}};
    } else if (k == 4) {
      const Vec3d& v0 = mesh.vertices[loop[0]];
      const Vec3d d02 = mesh.vertices[loop[2]] - v0;
      const bool flip = (mesh.vertices[loop[1]] - v0).cross(d02).dot((mesh.vertices[loop[3]] - v0).cross(d02)) > 0;
      local = flip ? std::vector<std::array<int, 3>>{{0, 1, 3}, {1, 2, 3}}
                   : std::vector<std::array<int, 3>>{{0, 1, 2}, {0, 2, 3}};
    } else {
      const Vec3d u = normal.unitOrthogonal(), v = normal.cross(u);
      std::vector<Eigen::Vector2d> co;
      for (int i : loop) co.emplace_back(u.dot(mesh.vertices[i]), v.dot(mesh.vertices[i]));
      local = PolyFill(co);
    }
    bool degenerate = false;
    for (const auto& t : local) {
      const Vec3d& a = mesh.vertices[loop[t[0]]];
      const Vec3d da = mesh.vertices[loop[t[2]]] - a, db = mesh.vertices[loop[t[2]]] - mesh.vertices[loop[t[1]]];
      degenerate = degenerate || da.cross(db).squaredNorm() < 1e-8 * da.squaredNorm() * db.squaredNorm();
    }
    if (degenerate) {
      const Vec3d u = normal.unitOrthogonal(), v = normal.cross(u);
      std::vector<Eigen::Vector2d> co;
      for (int i : loop) co.emplace_back(u.dot(mesh.vertices[i]), v.dot(mesh.vertices[i]));
      local = EarClip(co);
    }
    for (const auto& t : local) {
      triangles.push_back({{loop[t[0]], loop[t[1]], loop[t[2]]}, f});
      group.push_back(degenerate ? f : -1);
      axis.push_back(dominant);
    }
  }
  std::vector<std::array<int, 3>> corners;
  for (const SourceTriangle& t : triangles) corners.push_back(t.corners);
  DelaunayFlips(mesh.vertices, group, axis, &corners);
  for (size_t t = 0; t < triangles.size(); ++t) triangles[t].corners = corners[t];
  return triangles;
}

}  // namespace opgraph
