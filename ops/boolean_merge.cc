#include "ops/boolean_merge.h"

#include <algorithm>
#include <map>
#include <numeric>

#include "core/geometry.h"
#include "ops/halfedge_topology.h"

namespace opgraph {
namespace {

using Source = BooleanOp::Source;

// Largest distance of a polygon's corners from its plane (through the centroid, normal to the
// area vector); 0 for a triangle.
double OffPlane(const Positions<double>& vertices, const Polygon& face) {
  const Vec3d normal = FaceAreaNormal(vertices, face).normalized();
  Vec3d centroid = Vec3d::Zero();
  for (int v : face) centroid += vertices[v];
  centroid /= static_cast<double>(face.size());
  double off = 0;
  for (int v : face) off = std::max(off, std::abs(normal.dot(vertices[v] - centroid)));
  return off;
}

// The root of x in the union-find forest `parent`, halving the path on the way.
int FindRoot(std::vector<int>* parent, int x) {
  std::vector<int>& p = *parent;
  while (p[x] != x) x = p[x] = p[p[x]];
  return x;
}

}  // namespace

// A cut non-planar input polygon: which diagonal Blender's triangulation takes follows its
// loop start, which the ops before need not reproduce, and the two diagonals are different
// surfaces there (the cut's vertices, and their count, move with it).
void RefuseCutNonPlanarFaces(const Mesh& input, const TriangleSoup& result, const std::vector<int>& source_face,
                             const std::vector<Source>& sources) {
  const int num_result_triangles = static_cast<int>(result.triangles.size());
  std::vector<bool> cut(input.NumFaces(), false);
  for (int r = 0; r < num_result_triangles; ++r) {
    if (source_face[r] >= input.NumFaces()) continue;
    for (int v : result.triangles[r]) cut[source_face[r]] = cut[source_face[r]] || sources[v].kind == Source::kCrossing;
  }
  Vec3d input_lo = input.vertices[0], input_hi = input.vertices[0];
  for (const Vec3d& v : input.vertices) input_lo = input_lo.cwiseMin(v), input_hi = input_hi.cwiseMax(v);
  const double input_diagonal = std::max((input_hi - input_lo).norm(), 1e-300);
  for (int f = 0; f < input.NumFaces(); ++f) {
    if (!cut[f]) continue;
    const double off_plane = OffPlane(input.vertices, input.faces[f]) / input_diagonal;
    if (off_plane > kMaxCutFaceNonPlanarity) {
      char off[16];
      std::snprintf(off, sizeof(off), "%.1e", off_plane);
      throw FieldError("operation", std::string("the primitive cuts a non-planar face (off its plane by ") + off +
                                        " of the diagonal): Blender's exact boolean may triangulate it differently");
    }
  }
}

bool HasFoldedFace(const Mesh& input, const std::vector<SourceTriangle>& input_triangles) {
  auto normal = [&input](int a, int b, int c) {
    const Vec3d& p = input.vertices[a];
    return (input.vertices[b] - p).cross(input.vertices[c] - p).normalized();
  };
  auto folded = [](const Vec3d& n1, const Vec3d& n2) { return n1.dot(n2) <= 1e-6; };  // false on NaN
  // A quad along either diagonal (which one Blender takes follows its loop start).
  for (const Polygon& f : input.faces) {
    if (f.size() != 4) continue;
    if (folded(normal(f[0], f[1], f[2]), normal(f[0], f[2], f[3])) ||
        folded(normal(f[1], f[2], f[3]), normal(f[1], f[3], f[0]))) {
      return true;
    }
  }
  std::vector<Vec3d> first_normal(input.NumFaces(), Vec3d::Zero());
  for (const SourceTriangle& t : input_triangles) {
    if (input.faces[t.face].size() == 4) continue;
    const Vec3d n = normal(t.corners[0], t.corners[1], t.corners[2]);
    if (first_normal[t.face].isZero()) {
      first_normal[t.face] = n;
    } else if (folded(first_normal[t.face], n)) {
      return true;
    }
  }
  return false;
}

// Blender retriangulates each operand triangle with a constrained Delaunay triangulation; CGAL's
// retriangulation need not be Delaunay, and the merge depends on the triangles.
void MakeDelaunay(const Operands& ops, const std::vector<int>& source_triangle, TriangleSoup* result) {
  const int num_input_triangles = static_cast<int>(ops.triangles[0]->size());
  std::vector<int> dominant_axis(result->triangles.size());
  for (size_t r = 0; r < result->triangles.size(); ++r) {
    const int k = source_triangle[r];
    const int m = k < num_input_triangles ? 0 : 1;
    const TriangleSoup& operand = *ops.soups[m];
    const auto& c = (*ops.triangles[m])[m == 0 ? k : k - num_input_triangles].corners;
    dominant_axis[r] = DominantAxis(operand.vertices[c[0]], operand.vertices[c[1]], operand.vertices[c[2]]);
  }
  DelaunayFlips(result->vertices, source_triangle, dominant_axis, &result->triangles);
}

// The triangles of each source polygon merged back into polygons (ops/boolean.h).
std::vector<Polygon> MergeTriangles(const Mesh& input, const Mesh& primitive, const TriangleSoup& result,
                                    const std::vector<int>& source_face, const std::vector<Source>& sources,
                                    std::vector<bool>* whole) {
  const int num_result_triangles = static_cast<int>(result.triangles.size());
  std::vector<Polygon> polygons(num_result_triangles);
  std::vector<int> parent(num_result_triangles);
  for (int r = 0; r < num_result_triangles; ++r) {
    polygons[r].assign(result.triangles[r].begin(), result.triangles[r].end());
    parent[r] = r;
  }
  auto find = [&parent](int x) { return FindRoot(&parent, x); };
  struct Candidate {
    double length_squared;
    int from, to;  // directed edge of triangle `left`
    int left, right;
  };
  std::vector<Candidate> candidates;
  for (const TwoSidedEdge& e : TwoSidedEdges(result.triangles, static_cast<int>(result.vertices.size()))) {
    if (source_face[e.left] != source_face[e.right]) continue;
    const double length_squared = (result.vertices[e.from] - result.vertices[e.to]).squaredNorm();
    candidates.push_back({length_squared, e.from, e.to, e.left, e.right});
  }
  std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
    return x.length_squared > y.length_squared;
  });
  for (const Candidate& c : candidates) {
    const int left = find(c.left), right = find(c.right);
    if (left == right) continue;
    Polygon& l = polygons[left];
    Polygon& r = polygons[right];
    int shared = 0;
    for (int v : l) shared += std::count(r.begin(), r.end(), v);
    if (shared != 2) continue;  // the merge would enclose a hole or pinch a vertex
    // l runs ... from -> to ..., r runs ... to -> from ...: join them along the edge.
    std::rotate(l.begin(), std::find(l.begin(), l.end(), c.to), l.end());      // to ... from
    std::rotate(r.begin(), std::find(r.begin(), r.end(), c.from), r.end());    // from ... to
    l.insert(l.end(), r.begin() + 1, r.end() - 1);
    r.clear();
    parent[right] = left;
  }
  std::vector<Polygon> merged;
  whole->clear();
  for (int r = 0; r < num_result_triangles; ++r) {
    if (find(r) != r) continue;
    // A face the other operand left whole keeps its loop from its first corner, as in Blender
    // (which matters to a later boolean's triangulation of a non-planar polygon).
    Polygon& f = polygons[r];
    const bool on_input = source_face[r] < input.NumFaces();
    const Polygon& source = on_input ? input.faces[source_face[r]] : primitive.faces[source_face[r] - input.NumFaces()];
    const Source::Kind kind = on_input ? Source::kInput : Source::kPrimitive;
    const bool all_corners_kept = std::all_of(f.begin(), f.end(), [&](int v) {
      return sources[v].kind == kind && std::count(source.begin(), source.end(), sources[v].vertex) == 1;
    });
    if (f.size() == source.size()) {
      const auto first = std::find_if(f.begin(), f.end(), [&](int v) {
        return sources[v].kind == kind && sources[v].vertex == source[0];
      });
      if (first != f.end()) std::rotate(f.begin(), first, f.end());
    }
    merged.push_back(f);
    whole->push_back(f.size() == source.size() && all_corners_kept);
  }
  return merged;
}

std::vector<int> HoledInputFaces(const Mesh& input, const TriangleSoup& result, const std::vector<int>& source_face) {
  const int num_vertices = static_cast<int>(result.vertices.size());
  std::vector<std::vector<int>> triangles_of(input.NumFaces());
  for (size_t r = 0; r < result.triangles.size(); ++r) {
    if (source_face[r] < input.NumFaces()) triangles_of[source_face[r]].push_back(static_cast<int>(r));
  }
  std::vector<int> parent(num_vertices);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&parent](int x) { return FindRoot(&parent, x); };
  std::vector<int> holed;
  for (int f = 0; f < input.NumFaces(); ++f) {
    if (input.faces[f].size() < 4 || triangles_of[f].size() < 2) continue;
    std::vector<int> vertices;
    std::vector<long long> edges;
    for (int r : triangles_of[f]) {
      const auto& t = result.triangles[r];
      for (int i = 0; i < 3; ++i) {
        vertices.push_back(t[i]);
        edges.push_back(EdgeKey(t[i], t[(i + 1) % 3]));
        parent[find(t[i])] = find(t[(i + 1) % 3]);
      }
    }
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    std::sort(edges.begin(), edges.end());
    const long long num_edges = std::unique(edges.begin(), edges.end()) - edges.begin();
    long long pieces = 0;
    for (int v : vertices) pieces += find(v) == v;
    const long long euler = static_cast<long long>(vertices.size()) - num_edges + static_cast<long long>(triangles_of[f].size());
    if (euler < pieces) holed.push_back(f);
    for (int v : vertices) parent[v] = v;
  }
  return holed;
}

// The crossings to dissolve: those that only continue a straight chain between the same two
// polygons.
std::vector<bool> StraightCrossings(const std::vector<Polygon>& merged, const TriangleSoup& result,
                                    const std::vector<Source>& sources) {
  const int num_result = static_cast<int>(result.vertices.size());
  const HalfedgeTopology merged_topology(merged, num_result);
  std::vector<bool> dissolve(num_result, false);
  for (int v = 0; v < num_result; ++v) {
    if (sources[v].kind != Source::kCrossing) continue;
    // The same two neighbours in every polygon around v (at least one).
    std::pair<int, int> neighbours = {-1, -1};
    bool same = true;
    for (const HalfedgeTopology::Corner& corner : merged_topology.VertexCorners(v)) {
      const Polygon& f = merged[corner.face];
      const int k = static_cast<int>(f.size());
      const std::pair<int, int> around = std::minmax(f[(corner.corner + k - 1) % k], f[(corner.corner + 1) % k]);
      if (neighbours.first < 0) neighbours = around;
      else same = same && around == neighbours;
    }
    if (!same || neighbours.first < 0) continue;
    // Only a straight continuation (Blender's test: the turn's cosine within 1e-4 of 1); a
    // crossing where the chain bends, as across the diagonal of a non-planar quad, is kept.
    const Vec3d& p = result.vertices[v];
    const Vec3d in = p - result.vertices[neighbours.first];
    const Vec3d out = result.vertices[neighbours.second] - p;
    const double cosine = in.dot(out) / std::max(in.norm() * out.norm(), 1e-300);
    dissolve[v] = cosine > 1 - 1e-4;
  }
  return dissolve;
}

}  // namespace opgraph
