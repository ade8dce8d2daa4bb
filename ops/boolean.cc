#include "ops/boolean.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <numeric>

#include "core/geometry.h"
#include "ops/boolean_cgal.h"
#include "ops/boolean_triangulation.h"
#include "ops/halfedge_topology.h"

namespace opgraph {
namespace {

using Source = BooleanOp::Source;

const std::vector<std::string> kOperations = {"UNION", "DIFFERENCE"};
const std::vector<std::string> kPrimitives = {"cube", "prism6", "prism8", "cylinder"};
constexpr double kGateSwitch = 0.5;

int Segments(const std::string& primitive) {
  if (primitive == "prism6") return 6;
  if (primitive == "prism8") return 8;
  return 32;
}

// bmesh create_cone(cap_ends=True, segments=n, radius1=radius2=0.5, depth=1) with Blender's
// vertex and face order.
Mesh MakePrism(int n) {
  Mesh mesh;
  for (int k = 0; k < n; ++k) {
    const double angle = 2 * kPi * k / n;
    mesh.vertices.emplace_back(0.5 * std::sin(angle), 0.5 * std::cos(angle), -0.5);
    mesh.vertices.emplace_back(0.5 * std::sin(angle), 0.5 * std::cos(angle), 0.5);
  }
  auto side = [n](int k) {
    const int next = (k + 1) % n;
    return Polygon{2 * k, 2 * k + 1, 2 * next + 1, 2 * next};
  };
  for (int k = 0; k + 2 < n; ++k) mesh.faces.push_back(side(k));
  Polygon top = {3, 1};
  for (int k = n - 1; k >= 2; --k) top.push_back(2 * k + 1);
  mesh.faces.push_back(top);
  mesh.faces.push_back(side(n - 2));
  mesh.faces.push_back(side(n - 1));
  Polygon bottom;
  for (int k = 0; k < n; ++k) bottom.push_back(2 * k);
  mesh.faces.push_back(bottom);
  return mesh;
}

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

// Edge-plane crossing: the point of line (edge_from, edge_to) on the plane through a, b, c.
template <typename T>
Vec3<T> Crossing(const Vec3<T>& edge_from, const Vec3<T>& edge_to, const Vec3<T>& a, const Vec3<T>& b,
                 const Vec3<T>& c) {
  const Vec3<T> n = (b - a).cross(c - a);
  const T t = n.dot(a - edge_from) / n.dot(edge_to - edge_from);
  return edge_from + t * (edge_to - edge_from);
}



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

// Both operands as CGAL takes them (input, then primitive), with what the provenance steps
// look up in them.
struct Operands {
  const TriangleSoup* soups[2];
  const std::vector<SourceTriangle>* triangles[2];
  double tolerance;              // of the geometric tests: 1e-9 of both operands' bounding box
  Eigen::AlignedBox3d boxes[2];  // each operand's bounding box, grown by the tolerance

  Operands(const TriangleSoup& a, const std::vector<SourceTriangle>& a_triangles, const TriangleSoup& b,
           const std::vector<SourceTriangle>& b_triangles)
      : soups{&a, &b}, triangles{&a_triangles, &b_triangles} {
    Vec3d lo = a.vertices[0], hi = a.vertices[0];
    for (const Vec3d& v : a.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    for (const Vec3d& v : b.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    tolerance = 1e-9 * std::max((hi - lo).norm(), 1e-12);
    for (int m = 0; m < 2; ++m) {
      for (const Vec3d& v : soups[m]->vertices) boxes[m].extend(v);
      boxes[m].extend(boxes[m].min() - Vec3d::Constant(tolerance)).extend(boxes[m].max() + Vec3d::Constant(tolerance));
    }
  }
  // Whether these corners of operand m come near the other operand (its box): only edges and
  // triangles that do can take part in crossings.
  bool NearOther(int m, std::initializer_list<int> corners) const {
    Eigen::AlignedBox3d box;
    for (int v : corners) box.extend(soups[m]->vertices[v]);
    return box.intersects(boxes[1 - m]);
  }
};

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
    // A grazing crossing (an edge within a few degrees of the plane it crosses) moves along the
    // edge by the plane's rounding error over the sine: Blender's float32 coordinates would put
    // it elsewhere, so the sequence would not rebuild the same mesh there.
    if (best < kMinCrossingSine) {
      throw FieldError("operation", "the primitive crosses the mesh at a grazing angle (" +
                                        std::to_string(std::asin(best) * 180 / kPi).substr(0, 4) +
                                        " degrees): the intersection is ill-conditioned");
    }
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

// The triangles of each source polygon merged back into polygons (see the header).
std::vector<Polygon> MergeTriangles(const Mesh& input, const Mesh& primitive, const TriangleSoup& result,
                                    const std::vector<int>& source_face, const std::vector<Source>& sources) {
  const int num_result_triangles = static_cast<int>(result.triangles.size());
  std::vector<Polygon> polygons(num_result_triangles);
  std::vector<int> parent(num_result_triangles);
  for (int r = 0; r < num_result_triangles; ++r) {
    polygons[r].assign(result.triangles[r].begin(), result.triangles[r].end());
    parent[r] = r;
  }
  auto find = [&parent](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
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
  for (int r = 0; r < num_result_triangles; ++r) {
    if (find(r) != r) continue;
    // A face the other operand left whole keeps its loop from its first corner, as in Blender
    // (which matters to a later boolean's triangulation of a non-planar polygon).
    Polygon& f = polygons[r];
    const bool on_input = source_face[r] < input.NumFaces();
    const Polygon& source = on_input ? input.faces[source_face[r]] : primitive.faces[source_face[r] - input.NumFaces()];
    const Source::Kind kind = on_input ? Source::kInput : Source::kPrimitive;
    if (f.size() == source.size()) {
      const auto first = std::find_if(f.begin(), f.end(), [&](int v) {
        return sources[v].kind == kind && sources[v].vertex == source[0];
      });
      if (first != f.end()) std::rotate(f.begin(), first, f.end());
    }
    merged.push_back(f);
  }
  return merged;
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

}  // namespace

std::string SolidProblem(const Mesh& mesh) {
  TriangleSoup soup;
  soup.vertices = mesh.vertices;
  for (const SourceTriangle& t : Triangulate(mesh)) soup.triangles.push_back(t.corners);
  return CgalSolidProblem(soup, "the mesh");
}

BooleanOp::BooleanOp(const Json& params) {
  ParamReader reader(params);
  difference_ = reader.Word("operation", kOperations) == "DIFFERENCE";
  primitive_ = reader.Word("primitive", kPrimitives);
  const Vec3d size = reader.Vector3("size", 1e-6, 1e6);
  const Vec3d rotation_deg = reader.Vector3("rotation_deg", -3600, 3600, Vec3d::Zero());
  const Vec3d location = reader.Vector3("location", -1e6, 1e6, Vec3d::Zero());
  reader.Finish();
  const char* axes[3] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) AddParam(std::string("size_") + axes[i], 1e-6, 1e6, size[i], size[i]);
  for (int i = 0; i < 3; ++i) {
    const double radians = DegToRad(rotation_deg[i]);
    AddParam(std::string("rotation_") + axes[i], -4 * kPi, 4 * kPi, radians, radians);
  }
  for (int i = 0; i < 3; ++i) AddParam(std::string("location_") + axes[i], -1e6, 1e6, location[i], location[i]);
  template_ = primitive_ == "cube" ? MakeCube(1.0) : MakePrism(Segments(primitive_));
}

template <typename T>
Vec3<T> BooleanOp::PrimitiveVertex(const T* p, const Eigen::Matrix<T, 3, 3>& rotation, int v) const {
  const Vec3<T> scaled = template_.vertices[v].cast<T>().cwiseProduct(Vec3<T>(p[0], p[1], p[2]));
  return rotation * scaled + Vec3<T>(p[6], p[7], p[8]);
}

void BooleanOp::Prepare(const Mesh& input) {
  input_faces_ = input.faces;
  if (input.faces.empty()) throw FieldError("operation", "the input mesh has no faces");
  if (!HalfedgeTopology::Of(input)->Closed()) {
    throw FieldError("operation", "the input mesh is not a closed, consistently oriented manifold");
  }

  // Both operands as triangle soups; the primitive's vertices follow the input's.
  Mesh primitive = template_;
  const Eigen::Matrix3d rotation = EulerXYZToMatrix(params_[3], params_[4], params_[5]);
  for (int v = 0; v < primitive.NumVertices(); ++v) {
    primitive.vertices[v] = PrimitiveVertex(params_.data(), rotation, v);
  }
  const std::vector<SourceTriangle> input_triangles = Triangulate(input);
  const std::vector<SourceTriangle> primitive_triangles = Triangulate(primitive);
  TriangleSoup a, b, result;
  a.vertices = input.vertices;
  for (const SourceTriangle& t : input_triangles) a.triangles.push_back(t.corners);
  b.vertices = primitive.vertices;
  for (const SourceTriangle& t : primitive_triangles) b.triangles.push_back(t.corners);
  const std::string problem =
      CgalBoolean(a, b, difference_ ? BooleanKind::kDifference : BooleanKind::kUnion, &result);
  if (!problem.empty()) throw FieldError("operation", problem);

  const Operands operands(a, input_triangles, b, primitive_triangles);
  const std::vector<Source> sources = VertexSources(operands, result);
  WeldCoincidentPoints(1e-3 * operands.tolerance, &result);
  std::vector<int> source_face, source_triangle;
  TriangleSources(operands, input.NumFaces(), result, sources, &source_face, &source_triangle);
  RefuseCutNonPlanarFaces(input, result, source_face, sources);
  MakeDelaunay(operands, source_triangle, &result);
  const std::vector<Polygon> merged = MergeTriangles(input, primitive, result, source_face, sources);
  const std::vector<bool> dissolve = StraightCrossings(merged, result, sources);

  // The output: the merged polygons without their dissolved crossings, vertices numbered in
  // order of first use.
  const int num_result = static_cast<int>(result.vertices.size());
  std::vector<int> output_index(num_result, -1);
  sources_.clear();
  output_faces_.clear();
  for (Polygon f : merged) {
    f.erase(std::remove_if(f.begin(), f.end(), [&dissolve](int v) { return dissolve[v]; }), f.end());
    for (int& v : f) {
      if (output_index[v] < 0) {
        output_index[v] = static_cast<int>(sources_.size());
        sources_.push_back(sources[v]);
      }
      v = output_index[v];
    }
    output_faces_.push_back(f);
  }
  num_output_vertices_ = static_cast<int>(sources_.size());
  if (output_faces_.empty()) {
    throw FieldError("operation", "the result is empty (the primitive contains the whole mesh)");
  }
}

const std::vector<Polygon>& BooleanOp::OutputFaces(double gate) const {
  return gate < kGateSwitch ? input_faces_ : output_faces_;
}

template <typename T>
void BooleanOp::Apply(const T* p, const T& gate, const Positions<T>& in, Positions<T>* out) const {
  if (Scalar(gate) < kGateSwitch) {
    *out = in;
    return;
  }
  const Eigen::Matrix<T, 3, 3> rotation = EulerXYZToMatrix<T>(p[3], p[4], p[5]);
  out->resize(sources_.size());
  for (size_t i = 0; i < sources_.size(); ++i) {
    const Source& s = sources_[i];
    if (s.kind == Source::kInput) {
      (*out)[i] = in[s.vertex];
    } else if (s.kind == Source::kPrimitive) {
      (*out)[i] = PrimitiveVertex(p, rotation, s.vertex);
    } else if (s.edge_on_primitive) {
      (*out)[i] = Crossing<T>(PrimitiveVertex(p, rotation, s.edge[0]), PrimitiveVertex(p, rotation, s.edge[1]),
                              in[s.plane[0]], in[s.plane[1]], in[s.plane[2]]);
    } else {
      (*out)[i] = Crossing<T>(in[s.edge[0]], in[s.edge[1]], PrimitiveVertex(p, rotation, s.plane[0]),
                              PrimitiveVertex(p, rotation, s.plane[1]), PrimitiveVertex(p, rotation, s.plane[2]));
    }
  }
}

template void BooleanOp::Apply<double>(const double*, const double&, const Positions<double>&,
                                       Positions<double>*) const;
template void BooleanOp::Apply<JetT>(const JetT*, const JetT&, const Positions<JetT>&, Positions<JetT>*) const;

Json BooleanOp::ParamsToJson() const {
  const Vec3d rotation(params_[3], params_[4], params_[5]);
  return {{"operation", kOperations[difference_ ? 1 : 0]},
          {"primitive", primitive_},
          {"size", ToJson(Vec3d(params_[0], params_[1], params_[2]))},
          {"rotation_deg", ToJson(rotation * (180.0 / kPi))},
          {"location", ToJson(Vec3d(params_[6], params_[7], params_[8]))}};
}

std::string BooleanOp::BlenderCode() const {
  const std::string create =
      primitive_ == "cube"
          ? "bmesh.ops.create_cube(bm, size=1.0)\n"
          : "bmesh.ops.create_cone(bm, cap_ends=True, cap_tris=False, segments=" +
                std::to_string(Segments(primitive_)) + ", radius1=0.5, radius2=0.5, depth=1.0)\n";
  return "cutter_mesh = bpy.data.meshes.new(obj.name + ' cutter')\n"
         "bm = bmesh.new()\n" + create +
         "bmesh.ops.transform(bm, verts=bm.verts, matrix=Matrix.Translation(" +
         PyVec(Vec3d(params_[6], params_[7], params_[8])) + ") @ Euler(" +
         PyVec(Vec3d(params_[3], params_[4], params_[5])) + ", 'XYZ').to_matrix().to_4x4() @ Matrix.Diagonal(" +
         PyVec(Vec3d(params_[0], params_[1], params_[2])) + ").to_4x4())\n"
         "bm.to_mesh(cutter_mesh)\n"
         "bm.free()\n"
         "cutter = bpy.data.objects.new(obj.name + ' cutter', cutter_mesh)\n"
         "collection.objects.link(cutter)\n"
         "cutter.parent = obj  # the cutter follows the object's transform\n"
         "cutter.hide_set(True)\n"
         "cutter.hide_render = True\n"
         "m = obj.modifiers.new(" + PyWord("Boolean") + ", " + PyWord("BOOLEAN") + ")\n"
         "m.operation = " + PyWord(kOperations[difference_ ? 1 : 0]) + "\n"
         "m.solver = " + PyWord("EXACT") + "\n"
         "m.use_self = False\n"
         "m.use_hole_tolerant = False\n"
         "m.object = cutter\n";
}

}  // namespace opgraph
