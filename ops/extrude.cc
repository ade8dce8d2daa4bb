#include "ops/extrude.h"

#include "core/geometry.h"

namespace opgraph {

ExtrudeOp::ExtrudeOp(const Json& params) : selector_(MemberOrNull(params, "faces"), "faces") {
  ParamReader reader(params);
  reader.Raw("faces");
  individual_ = reader.Word("mode", {"region", "individual"}, "region") == "individual";
  AddParam("height", -1e6, 1e6, 0, reader.Number("height", -1e6, 1e6));
  AddParam("width", 1e-3, 1e3, 1, reader.Number("width", 1e-3, 1e3, 1.0));
  Vec3d tilt(0, 0, 0);
  if (reader.Has("tilt_deg")) {
    const Json& t = reader.Raw("tilt_deg");
    if (!t.is_array() || t.size() != 2) throw FieldError("tilt_deg", "must be an array of 2 numbers");
    tilt[0] = CheckedNumber(t[0], "tilt_deg[0]", -180, 180);
    tilt[1] = CheckedNumber(t[1], "tilt_deg[1]", -180, 180);
  }
  AddParam("tilt_u", -kPi, kPi, 0, DegToRad(tilt[0]));
  AddParam("tilt_v", -kPi, kPi, 0, DegToRad(tilt[1]));
  reader.Finish();
}

void ExtrudeOp::Prepare(const Mesh& input) {
  const std::vector<int> selected = selector_.Resolve(input);
  std::vector<std::vector<int>> sets;
  if (individual_) {
    for (int f : selected) sets.push_back({f});
  } else {
    sets.push_back(selected);
  }
  input_faces_ = input.faces;
  regions_ = CopyRegions(input, sets, &output_faces_, &num_output_vertices_);
}

int ExtrudeOp::first_created_face() const {
  int selected = 0;
  for (const RegionCopy& group : regions_) selected += static_cast<int>(group.faces.size());
  return static_cast<int>(input_faces_.size()) - selected;
}

namespace {

// The tilt frame's helper axis is X, or Y where the normal is within acos(0.9) of X (BlenderCode
// writes the same rule in Python).
constexpr double kTiltFrameSwitch = 0.9;

template <typename T>
Vec3<T> TiltFrameHelper(const Vec3<T>& normal) {
  return std::abs(Scalar(normal.x())) < kTiltFrameSwitch ? Vec3<T>(T(1), T(0), T(0)) : Vec3<T>(T(0), T(1), T(0));
}

template <typename T>
Vec3<T> RegionNormal(const Positions<T>& in, const std::vector<Polygon>& input_faces, const RegionCopy& group) {
  Vec3<T> normal(T(0), T(0), T(0));
  for (int f : group.faces) normal += FaceAreaNormal(in, input_faces[f]);
  return SafeNormalized(normal);
}

}  // namespace

bool ExtrudeOp::NearGeometricBranch(double gate, const Positions<double>& in) const {
  // Blender's float32 normals differ from ours by about 1e-6; fits can settle on the switch
  // itself (the loss jumps there), 5e-9 from it in one seen case.
  constexpr double kMargin = 1e-4;
  if (gate * params_[2] == 0 && gate * params_[3] == 0) return false;
  for (const RegionCopy& group : regions_) {
    const Vec3d normal = RegionNormal(in, input_faces_, group);
    if (std::abs(std::abs(normal.x()) - kTiltFrameSwitch) < kMargin) return true;
  }
  return false;
}

template <typename T>
void ExtrudeOp::Apply(const T* p, const T& gate, const Positions<T>& in, Positions<T>* out) const {
  *out = in;
  out->resize(num_output_vertices_);
  const T height = gate * p[0];
  const T width = T(1) + gate * (p[1] - T(1));
  for (const RegionCopy& group : regions_) {
    const Vec3<T> normal = RegionNormal(in, input_faces_, group);
    Vec3<T> centre(T(0), T(0), T(0));
    for (const auto& [target, source] : group.caps) centre += in[source] + normal * height;
    centre /= T(static_cast<double>(group.caps.size()));
    const Vec3<T> u = SafeNormalized<T>(normal.cross(TiltFrameHelper(normal)));
    const Vec3<T> v = normal.cross(u);
    const Eigen::Matrix<T, 3, 3> r = AxisAngleToMatrix<T>(u, gate * p[2]) * AxisAngleToMatrix<T>(v, gate * p[3]);
    for (const auto& [target, source] : group.caps) {
      (*out)[target] = centre + r * ((in[source] + normal * height - centre) * width);
    }
  }
}

template void ExtrudeOp::Apply<double>(const double*, const double&, const Positions<double>&,
                                       Positions<double>*) const;
template void ExtrudeOp::Apply<JetT>(const JetT*, const JetT&, const Positions<JetT>&, Positions<JetT>*) const;

Json ExtrudeOp::ParamsToJson() const {
  return {{"faces", selector_.ToJson()},
          {"mode", individual_ ? "individual" : "region"},
          {"height", params_[0]},
          {"width", params_[1]},
          {"tilt_deg", {RadToDeg(params_[2]), RadToDeg(params_[3])}}};
}

std::string ExtrudeOp::BlenderCode() const {
  std::string code = "me, bm = open_bmesh(obj)\nfaces = " +
                     selector_.PythonExpr("bm") + "\n";
  if (individual_) {
    code +=
        "ret = bmesh.ops.extrude_discrete_faces(bm, faces=faces)\n"
        "groups = [(list(f.verts), f.normal.copy()) for f in ret['faces']]\n";
  } else {
    code +=
        "n = sum((f.normal * f.calc_area() for f in faces), Vector()).normalized()\n"
        "ret = bmesh.ops.extrude_face_region(bm, geom=faces)\n"
        "bmesh.ops.delete(bm, geom=faces, context='FACES')\n"
        "groups = [([g for g in ret['geom'] if isinstance(g, bmesh.types.BMVert)], n)]\n";
  }
  code += "height, width, tilt = " + Py(params_[0]) + ", " + Py(params_[1]) + ", (" + Py(params_[2]) + ", " +
          Py(params_[3]) + ")\n";
  code +=
      "for verts, n in groups:\n"
      "    for v in verts:\n"
      "        v.co += n * height\n"
      "    c = sum((v.co for v in verts), Vector()) / len(verts)\n"
      "    e = Vector((1, 0, 0)) if abs(n.x) < " +
      Py(kTiltFrameSwitch) +
      " else Vector((0, 1, 0))\n"
      "    u = n.cross(e).normalized()\n"
      "    r = Matrix.Rotation(tilt[0], 3, u) @ Matrix.Rotation(tilt[1], 3, n.cross(u))\n"
      "    for v in verts:\n"
      "        v.co = c + r @ ((v.co - c) * width)\n"
      "close_bmesh(me, bm)\n";
  return code;
}

}  // namespace opgraph
