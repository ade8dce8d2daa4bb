#include "ops/edge_loop_affine.h"

#include "core/geometry.h"

namespace opgraph {

namespace {
const char* kKeys[3] = {"rotation_deg", "scale", "offset"};
}  // namespace

EdgeLoopAffineOp::EdgeLoopAffineOp(Kind kind, const Json& params)
    : kind_(kind), selector_(MemberOrNull(params, "verts"), "verts") {
  ParamReader reader(params);
  reader.Raw("verts");
  const char* axes[3] = {"x", "y", "z"};
  const Vec3d v = reader.Vector3(kKeys[static_cast<int>(kind_)], -1e6, 1e6);
  for (int k = 0; k < 3; ++k) {
    if (kind_ == Kind::kRotate) {
      AddParam(std::string("rotation_") + axes[k], -4 * kPi, 4 * kPi, 0, DegToRad(v[k]));
    } else if (kind_ == Kind::kScale) {
      AddParam(std::string("scale_") + axes[k], -1e6, 1e6, 1, v[k]);
    } else {
      AddParam(std::string("offset_") + axes[k], -1e6, 1e6, 0, v[k]);
    }
  }
  reader.Finish();
}

std::string EdgeLoopAffineOp::Name() const {
  switch (kind_) {
    case Kind::kRotate: return "EdgeLoopAffineRotate";
    case Kind::kScale: return "EdgeLoopAffineScale";
    default: return "EdgeLoopAffineTranslate";
  }
}

void EdgeLoopAffineOp::Prepare(const Mesh& input) {
  KeepTopology(input);
  resolved_ = selector_.Resolve(input);
}

template <typename T>
void EdgeLoopAffineOp::Apply(const T* p, const T& gate, const Positions<T>& in, Positions<T>* out) const {
  *out = in;
  Vec3<T> pivot(T(0), T(0), T(0));
  for (int v : resolved_) pivot += in[v];
  pivot /= T(static_cast<double>(resolved_.size()));
  Eigen::Matrix<T, 3, 3> m = Eigen::Matrix<T, 3, 3>::Identity();
  Vec3<T> shift(T(0), T(0), T(0));
  if (kind_ == Kind::kRotate) {
    m = EulerXYZToMatrix<T>(gate * p[0], gate * p[1], gate * p[2]);
  } else if (kind_ == Kind::kScale) {
    for (int k = 0; k < 3; ++k) m(k, k) = T(1) + gate * (p[k] - T(1));
  } else {
    shift = Vec3<T>(gate * p[0], gate * p[1], gate * p[2]);
  }
  for (int v : resolved_) (*out)[v] = pivot + m * (in[v] - pivot) + shift;
}

template void EdgeLoopAffineOp::Apply<double>(const double*, const double&, const Positions<double>&,
                                              Positions<double>*) const;
template void EdgeLoopAffineOp::Apply<JetT>(const JetT*, const JetT&, const Positions<JetT>&,
                                            Positions<JetT>*) const;

Json EdgeLoopAffineOp::ParamsToJson() const {
  Vec3d v(params_[0], params_[1], params_[2]);
  if (kind_ == Kind::kRotate) v *= 180.0 / kPi;
  return {{"verts", selector_.ToJson()}, {kKeys[static_cast<int>(kind_)], ToJson(v)}};
}

std::string EdgeLoopAffineOp::BlenderCode() const {
  const Vec3d v(params_[0], params_[1], params_[2]);
  std::string matrix;
  if (kind_ == Kind::kRotate) matrix = "Euler(" + PyVec(v) + ", 'XYZ').to_matrix().to_4x4()";
  if (kind_ == Kind::kScale) matrix = "Matrix.Diagonal(" + PyVec(v) + ").to_4x4()";
  if (kind_ == Kind::kTranslate) matrix = "Matrix.Translation(" + PyVec(v) + ")";
  return "me = edit_mesh(obj)\nverts = " + selector_.PythonExpr("me") +
         "\npivot = sum((me.vertices[i].co for i in verts), Vector()) / len(verts)\n"
         "m = Matrix.Translation(pivot) @ " + matrix + " @ Matrix.Translation(-pivot)\n"
         "for i in verts:\n    me.vertices[i].co = m @ me.vertices[i].co\nme.update()\n";
}

}  // namespace opgraph
