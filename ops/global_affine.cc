#include "ops/global_affine.h"

#include "core/geometry.h"

namespace opgraph {

GlobalAffineOp::GlobalAffineOp(Kind kind, const Json& params) : kind_(kind) {
  ParamReader reader(params);
  const char* axes[3] = {"x", "y", "z"};
  switch (kind_) {
    case Kind::kRotate: {
      const Vec3d deg = reader.Vector3("rotation_deg", -3600, 3600);
      for (int i = 0; i < 3; ++i) AddParam(std::string("rotation_") + axes[i], -4 * kPi, 4 * kPi, 0, DegToRad(deg[i]));
      break;
    }
    case Kind::kScale: {
      const Vec3d s = reader.Vector3("scale", -1e6, 1e6);
      for (int i = 0; i < 3; ++i) {
        if (std::abs(s[i]) < 1e-9) throw FieldError("scale[" + std::to_string(i) + "]", "must not be zero");
        AddParam(std::string("scale_") + axes[i], -1e6, 1e6, 1, s[i]);
      }
      break;
    }
    case Kind::kTranslate: {
      const Vec3d t = reader.Vector3("offset", -1e6, 1e6);
      for (int i = 0; i < 3; ++i) AddParam(std::string("offset_") + axes[i], -1e6, 1e6, 0, t[i]);
      break;
    }
  }
  reader.Finish();
}

std::string GlobalAffineOp::Name() const {
  switch (kind_) {
    case Kind::kRotate: return "GlobalAffineRotate";
    case Kind::kScale: return "GlobalAffineScale";
    default: return "GlobalAffineTranslate";
  }
}

template <typename T>
void GlobalAffineOp::Apply(const T* p, const T& gate, const Positions<T>& in, Positions<T>* out) const {
  out->resize(in.size());
  switch (kind_) {
    case Kind::kRotate: {
      const Eigen::Matrix<T, 3, 3> r = EulerXYZToMatrix<T>(gate * p[0], gate * p[1], gate * p[2]);
      for (size_t i = 0; i < in.size(); ++i) (*out)[i] = r * in[i];
      break;
    }
    case Kind::kScale: {
      Vec3<T> s;
      for (int k = 0; k < 3; ++k) s[k] = T(1) + gate * (p[k] - T(1));
      for (size_t i = 0; i < in.size(); ++i) (*out)[i] = in[i].cwiseProduct(s);
      break;
    }
    case Kind::kTranslate: {
      const Vec3<T> t(gate * p[0], gate * p[1], gate * p[2]);
      for (size_t i = 0; i < in.size(); ++i) (*out)[i] = in[i] + t;
      break;
    }
  }
}

template void GlobalAffineOp::Apply<double>(const double*, const double&, const Positions<double>&,
                                            Positions<double>*) const;
template void GlobalAffineOp::Apply<JetT>(const JetT*, const JetT&, const Positions<JetT>&,
                                          Positions<JetT>*) const;

Json GlobalAffineOp::ParamsToJson() const {
  const Vec3d v(params_[0], params_[1], params_[2]);
  switch (kind_) {
    case Kind::kRotate: return {{"rotation_deg", ToJson(v * (180.0 / kPi))}};
    case Kind::kScale: return {{"scale", ToJson(v)}};
    default: return {{"offset", ToJson(v)}};
  }
}

std::string GlobalAffineOp::PyMatrix() const {
  const Vec3d v(params_[0], params_[1], params_[2]);
  switch (kind_) {
    case Kind::kRotate: return "Euler(" + PyVec(v) + ", 'XYZ').to_matrix().to_4x4()";
    case Kind::kScale: return "Matrix.Diagonal(" + PyVec(v) + ").to_4x4()";
    default: return "Matrix.Translation(" + PyVec(v) + ")";
  }
}

std::string GlobalAffineOp::BlenderCode() const { return "edit_mesh(obj).transform(" + PyMatrix() + ")\n"; }

}  // namespace opgraph
