#include "ops/boolean.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <numeric>

#include "core/geometry.h"
#include "ops/boolean_contact.h"
#include "ops/boolean_merge.h"
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

// Edge-plane crossing: the point of line (edge_from, edge_to) on the plane through a, b, c.
template <typename T>
Vec3<T> Crossing(const Vec3<T>& edge_from, const Vec3<T>& edge_to, const Vec3<T>& a, const Vec3<T>& b,
                 const Vec3<T>& c) {
  const Vec3<T> n = (b - a).cross(c - a);
  const T t = n.dot(a - edge_from) / n.dot(edge_to - edge_from);
  return edge_from + t * (edge_to - edge_from);
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
  const Mesh primitive = PlacedPrimitive();
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
  holed_faces_ = HoledInputFaces(input, result, source_face);
  std::vector<bool> whole;
  const std::vector<Polygon> merged = MergeTriangles(input, primitive, result, source_face, sources, &whole);
  const std::vector<bool> dissolve = StraightCrossings(merged, result, sources);

  // The output: the merged polygons without their dissolved crossings, vertices numbered in
  // order of first use.
  const int num_result = static_cast<int>(result.vertices.size());
  std::vector<int> output_index(num_result, -1);
  sources_.clear();
  output_faces_.clear();
  cut_faces_.clear();
  for (size_t i = 0; i < merged.size(); ++i) {
    Polygon f = merged[i];
    if (!whole[i]) cut_faces_.push_back(static_cast<int>(i));
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

Mesh BooleanOp::PlacedPrimitive() const {
  Mesh primitive = template_;
  const Eigen::Matrix3d rotation = EulerXYZToMatrix(params_[3], params_[4], params_[5]);
  for (int v = 0; v < primitive.NumVertices(); ++v) {
    primitive.vertices[v] = PrimitiveVertex(params_.data(), rotation, v);
  }
  return primitive;
}

bool BooleanOp::NearGeometricBranch(double gate, const Positions<double>& in) const {
  if (gate < kGateSwitch) return false;
  Mesh input;
  input.vertices = in;
  input.faces = input_faces_;
  return HasFoldedFace(input, Triangulate(input)) || CountOperandContacts(input, PlacedPrimitive()).near > 0;
}

std::vector<int> BooleanOp::FacesOfUnknownLoopStart(double gate) const {
  return gate < kGateSwitch ? std::vector<int>() : cut_faces_;
}

std::vector<int> BooleanOp::FacesWhoseLoopStartDecides(double gate) const {
  return gate < kGateSwitch ? std::vector<int>() : holed_faces_;
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
