#include "ops/boolean.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <set>

#include "core/geometry.h"
#include "ops/boolean_cgal.h"

namespace opgraph {
namespace {

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

// One triangle of a mesh's triangulation and the polygon it belongs to.
struct SourceTriangle {
  std::array<int, 3> corners;
  int face;
};

// Blender's triangulation of the boolean's operands: quads along the 0-2 diagonal, other
// polygons by ear clipping that tries ears from vertex 1 on (a fan from vertex 0 when convex).
std::vector<SourceTriangle> Triangulate(const Mesh& mesh) {
  std::vector<SourceTriangle> triangles;
  for (int f = 0; f < mesh.NumFaces(); ++f) {
    std::vector<int> loop = mesh.faces[f];
    const Vec3d normal = FaceAreaNormal(mesh.vertices, loop);
    while (loop.size() > 3) {
      const int k = static_cast<int>(loop.size());
      int ear = 1;
      for (int i = 1; i <= k; ++i) {
        const int c = i % k;
        const Vec3d& a = mesh.vertices[loop[(c + k - 1) % k]];
        const Vec3d& b = mesh.vertices[loop[c]];
        const Vec3d& d = mesh.vertices[loop[(c + 1) % k]];
        if ((b - a).cross(d - b).dot(normal) <= 0) continue;  // reflex corner
        bool empty = true;
        for (int j = 0; j < k && empty; ++j) {
          if (j == c || j == (c + 1) % k || j == (c + k - 1) % k) continue;
          const Vec3d& q = mesh.vertices[loop[j]];
          empty = !((b - a).cross(q - a).dot(normal) > 0 && (d - b).cross(q - b).dot(normal) > 0 &&
                    (a - d).cross(q - d).dot(normal) > 0);
        }
        if (empty) {
          ear = c;
          break;
        }
      }
      triangles.push_back({{loop[(ear + k - 1) % k], loop[ear], loop[(ear + 1) % k]}, f});
      loop.erase(loop.begin() + ear);
    }
    triangles.push_back({{loop[0], loop[1], loop[2]}, f});
  }
  return triangles;
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

// Edge-plane crossing: the point of line (edge_from, edge_to) on the plane through a, b, c.
template <typename T>
Vec3<T> Crossing(const Vec3<T>& edge_from, const Vec3<T>& edge_to, const Vec3<T>& a, const Vec3<T>& b,
                 const Vec3<T>& c) {
  const Vec3<T> n = (b - a).cross(c - a);
  const T t = n.dot(a - edge_from) / n.dot(edge_to - edge_from);
  return edge_from + t * (edge_to - edge_from);
}

}  // namespace

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
    AddParam(std::string("rotation_") + axes[i], -4 * kPi, 4 * kPi, DegToRad(rotation_deg[i]), DegToRad(rotation_deg[i]));
  }
  for (int i = 0; i < 3; ++i) AddParam(std::string("location_") + axes[i], -1e6, 1e6, location[i], location[i]);
  template_ = primitive_ == "cube" ? MakeCube(1.0) : MakePrism(Segments(primitive_));
}

template <typename T>
Vec3<T> BooleanOp::PrimitiveVertex(const T* p, int v) const {
  const Vec3<T> scaled = template_.vertices[v].cast<T>().cwiseProduct(Vec3<T>(p[0], p[1], p[2]));
  return EulerXYZToMatrix<T>(p[3], p[4], p[5]) * scaled + Vec3<T>(p[6], p[7], p[8]);
}

void BooleanOp::Prepare(const Mesh& input) {
  input_faces_ = input.faces;
  if (input.faces.empty()) throw FieldError("operation", "the input mesh has no faces");
  // A closed manifold has each directed edge once and its reverse once.
  std::map<std::pair<int, int>, int> directed;
  for (const Polygon& f : input.faces) {
    for (size_t i = 0; i < f.size(); ++i) ++directed[{f[i], f[(i + 1) % f.size()]}];
  }
  for (const auto& e : directed) {
    const auto reverse = directed.find({e.first.second, e.first.first});
    if (e.second != 1 || reverse == directed.end() || reverse->second != 1) {
      throw FieldError("operation", "the input mesh is not a closed, consistently oriented manifold");
    }
  }

  // Both operands as triangle soups; the primitive's vertices follow the input's.
  Mesh primitive = template_;
  for (int v = 0; v < primitive.NumVertices(); ++v) primitive.vertices[v] = PrimitiveVertex(params_.data(), v);
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

  // Provenance of CGAL's vertices, recovered geometrically (CGAL's points are its exact ones
  // rounded to double).
  Vec3d lo = input.vertices[0], hi = input.vertices[0];
  for (const Vec3d& v : a.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  for (const Vec3d& v : b.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  const double tolerance = 1e-9 * std::max((hi - lo).norm(), 1e-12);
  const TriangleSoup* operands[2] = {&a, &b};
  std::vector<std::pair<int, int>> edges[2];  // unique triangulation edges of each operand
  for (int m = 0; m < 2; ++m) {
    std::set<std::pair<int, int>> seen;
    for (const auto& t : operands[m]->triangles) {
      for (int i = 0; i < 3; ++i) {
        const std::pair<int, int> e = std::minmax(t[i], t[(i + 1) % 3]);
        if (seen.insert(e).second) edges[m].push_back(e);
      }
    }
  }
  std::vector<Source> sources(result.vertices.size());
  for (size_t r = 0; r < result.vertices.size(); ++r) {
    const Vec3d& p = result.vertices[r];
    Source& s = sources[r];
    s.vertex = -1;
    for (int m = 0; m < 2 && s.vertex < 0; ++m) {
      for (size_t v = 0; v < operands[m]->vertices.size(); ++v) {
        if ((operands[m]->vertices[v] - p).norm() <= tolerance) {
          s.kind = m == 0 ? Source::kInput : Source::kPrimitive;
          s.vertex = static_cast<int>(v);
          break;
        }
      }
    }
    if (s.vertex >= 0) continue;
    // A crossing: the best conditioned (edge of one operand, triangle of the other) through p.
    double best = 1e-6;
    for (int m = 0; m < 2; ++m) {
      const TriangleSoup& mine = *operands[m];
      const TriangleSoup& other = *operands[1 - m];
      for (const auto& e : edges[m]) {
        const Vec3d& from = mine.vertices[e.first];
        const Vec3d& to = mine.vertices[e.second];
        if (SegmentDistance(p, from, to) > tolerance) continue;
        const Vec3d direction = (to - from).normalized();
        for (const auto& t : other.triangles) {
          Vec3d n;
          if (!OnTriangle(p, other.vertices[t[0]], other.vertices[t[1]], other.vertices[t[2]], tolerance, &n)) continue;
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
  }

  // Source triangle (and so polygon) of each result triangle: the operand triangle its centroid
  // lies on, parallel to it; the input mesh wins where both operands overlap.
  const int num_result_triangles = static_cast<int>(result.triangles.size());
  std::vector<int> source_triangle(num_result_triangles, -1);  // input's, then primitive's
  std::vector<int> source_face(num_result_triangles, -1);      // input's, then primitive's
  for (int r = 0; r < num_result_triangles; ++r) {
    const auto& t = result.triangles[r];
    const Vec3d& p0 = result.vertices[t[0]];
    const Vec3d& p1 = result.vertices[t[1]];
    const Vec3d& p2 = result.vertices[t[2]];
    const Vec3d centroid = (p0 + p1 + p2) / 3;
    const Vec3d normal = (p1 - p0).cross(p2 - p0).normalized();
    double best = 1 - 1e-6;
    int offset = 0;
    for (int m = 0; m < 2 && source_triangle[r] < 0; ++m) {
      const TriangleSoup& operand = *operands[m];
      const std::vector<SourceTriangle>& triangles = m == 0 ? input_triangles : primitive_triangles;
      for (size_t k = 0; k < triangles.size(); ++k) {
        const auto& c = triangles[k].corners;
        Vec3d n;
        if (!OnTriangle(centroid, operand.vertices[c[0]], operand.vertices[c[1]], operand.vertices[c[2]], tolerance, &n)) continue;
        if (std::abs(n.dot(normal)) > best) {
          best = std::abs(n.dot(normal));
          source_triangle[r] = offset + static_cast<int>(k);
          source_face[r] = (m == 0 ? 0 : input.NumFaces()) + triangles[k].face;
        }
      }
      offset += static_cast<int>(triangles.size());
    }
    if (source_triangle[r] < 0) throw FieldError("operation", "internal: a face of the boolean has no source");
  }

  // Merge the triangles of each source polygon (see the header), then dissolve new vertices
  // that only continue a straight chain between the same two polygons.
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
  std::map<std::pair<int, int>, int> triangle_of_edge;  // directed edge -> result triangle
  for (int r = 0; r < num_result_triangles; ++r) {
    for (int i = 0; i < 3; ++i) triangle_of_edge[{result.triangles[r][i], result.triangles[r][(i + 1) % 3]}] = r;
  }
  struct Candidate {
    int stage;  // 0: inside one operand triangle, 1: along a diagonal of the triangulation
    double length_squared;
    int from, to;  // directed edge of triangle `left`
    int left, right;
  };
  std::vector<Candidate> candidates;
  for (const auto& e : triangle_of_edge) {
    const auto twin = triangle_of_edge.find({e.first.second, e.first.first});
    if (e.first.first > e.first.second || twin == triangle_of_edge.end()) continue;
    const int left = e.second, right = twin->second;
    if (source_face[left] != source_face[right]) continue;
    const double length_squared = (result.vertices[e.first.first] - result.vertices[e.first.second]).squaredNorm();
    candidates.push_back({source_triangle[left] == source_triangle[right] ? 0 : 1, length_squared,
                          e.first.first, e.first.second, left, right});
  }
  std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
    return x.stage != y.stage ? x.stage < y.stage : x.length_squared > y.length_squared;
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
    if (find(r) == r) merged.push_back(polygons[r]);
  }
  const int num_result = static_cast<int>(result.vertices.size());
  std::vector<std::pair<int, int>> neighbours(num_result, {-1, -1});
  std::vector<bool> dissolve(num_result);
  for (int v = 0; v < num_result; ++v) dissolve[v] = sources[v].kind == Source::kCrossing;
  for (const Polygon& f : merged) {
    const int k = static_cast<int>(f.size());
    for (int i = 0; i < k; ++i) {
      const int v = f[i];
      const std::pair<int, int> around = std::minmax(f[(i + k - 1) % k], f[(i + 1) % k]);
      if (neighbours[v].first < 0) neighbours[v] = around;
      else if (neighbours[v] != around) dissolve[v] = false;
    }
  }
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
  out->resize(sources_.size());
  for (size_t i = 0; i < sources_.size(); ++i) {
    const Source& s = sources_[i];
    if (s.kind == Source::kInput) {
      (*out)[i] = in[s.vertex];
    } else if (s.kind == Source::kPrimitive) {
      (*out)[i] = PrimitiveVertex(p, s.vertex);
    } else if (s.edge_on_primitive) {
      (*out)[i] = Crossing<T>(PrimitiveVertex(p, s.edge[0]), PrimitiveVertex(p, s.edge[1]), in[s.plane[0]],
                              in[s.plane[1]], in[s.plane[2]]);
    } else {
      (*out)[i] = Crossing<T>(in[s.edge[0]], in[s.edge[1]], PrimitiveVertex(p, s.plane[0]),
                              PrimitiveVertex(p, s.plane[1]), PrimitiveVertex(p, s.plane[2]));
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
  return "cutter_mesh = bpy.data.meshes.new(" + PyWord("cutter") + ")\n"
         "bm = bmesh.new()\n" + create +
         "bmesh.ops.transform(bm, verts=bm.verts, matrix=Matrix.Translation(" +
         PyVec(Vec3d(params_[6], params_[7], params_[8])) + ") @ Euler(" +
         PyVec(Vec3d(params_[3], params_[4], params_[5])) + ", 'XYZ').to_matrix().to_4x4() @ Matrix.Diagonal(" +
         PyVec(Vec3d(params_[0], params_[1], params_[2])) + ").to_4x4())\n"
         "bm.to_mesh(cutter_mesh)\n"
         "bm.free()\n"
         "cutter = bpy.data.objects.new(" + PyWord("cutter") + ", cutter_mesh)\n"
         "bpy.context.scene.collection.objects.link(cutter)\n"
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
