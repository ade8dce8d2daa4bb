#include "ops/simple_deform.h"

#include <cmath>

namespace opgraph {

namespace {
const std::vector<std::string> kAxes = {"X", "Y", "Z"};
}  // namespace

SimpleDeformOp::SimpleDeformOp(Mode mode, const Json& params) : mode_(mode) {
  ParamReader reader(params);
  const std::string axis = reader.Word("axis", kAxes);
  axis_ = axis[0] - 'X';
  if (UsesAngle()) {
    AddParam("angle", -8 * kPi, 8 * kPi, 0, DegToRad(reader.Number("angle_deg", -1440, 1440)));
  } else {
    AddParam("factor", -10, 10, 0, reader.Number("factor", -10, 10));
  }
  if (reader.Has("limits")) {
    const Json& limits = reader.Raw("limits");
    if (!limits.is_array() || limits.size() != 2) throw FieldError("limits", "must be an array of 2 numbers");
    limits_[0] = CheckedNumber(limits[0], "limits[0]", 0, 1);
    limits_[1] = CheckedNumber(limits[1], "limits[1]", limits_[0], 1);
  }
  reader.Finish();
}

std::string SimpleDeformOp::Name() const {
  switch (mode_) {
    case Mode::kTwist: return "SimpleDeformTwist";
    case Mode::kBend: return "SimpleDeformBend";
    case Mode::kTaper: return "SimpleDeformTaper";
    default: return "SimpleDeformStretch";
  }
}

template <typename T>
void SimpleDeformOp::Apply(const T* p, const T& gate, const Positions<T>& in, Positions<T>* out) const {
  using std::cos;
  using std::sin;
  out->resize(in.size());
  int limit_axis = axis_;
  if (mode_ == Mode::kBend) limit_axis = axis_ == 2 ? 0 : 2;
  T lower = in.empty() ? T(0) : in[0][limit_axis], upper = lower;
  for (const Vec3<T>& v : in) {
    if (v[limit_axis] < lower) lower = v[limit_axis];
    if (v[limit_axis] > upper) upper = v[limit_axis];
  }
  const T limit0 = lower + (upper - lower) * limits_[0];
  const T limit1 = lower + (upper - lower) * limits_[1];
  T extent = limit1 - limit0;
  if (extent < T(1.1920929e-07)) extent = T(1.1920929e-07);  // Blender's FLT_EPSILON guard
  const T k = gate * p[0] / extent;
  // Blender skips the bend below BEND_EPS; the same keeps the identity exact at gate 0.
  if (mode_ == Mode::kBend && std::abs(Scalar(k)) < 1e-6) {
    *out = in;
    return;
  }
  // Twist/Taper/Stretch work in coordinates permuted so the deform axis is z.
  static const int kAxisMap[3][3] = {{1, 2, 0}, {2, 0, 1}, {0, 1, 2}};
  const int* map = kAxisMap[mode_ == Mode::kBend ? 2 : axis_];
  for (size_t i = 0; i < in.size(); ++i) {
    Vec3<T> co = in[i];
    Vec3<T> dcut(T(0), T(0), T(0));
    if (co[limit_axis] < limit0) {
      dcut[limit_axis] = co[limit_axis] - limit0;
      co[limit_axis] = limit0;
    }
    if (co[limit_axis] > limit1) {
      dcut[limit_axis] = co[limit_axis] - limit1;
      co[limit_axis] = limit1;
    }
    const Vec3<T> c(co[map[0]], co[map[1]], co[map[2]]);
    const Vec3<T> d(dcut[map[0]], dcut[map[1]], dcut[map[2]]);
    const T x = c[0], y = c[1], z = c[2];
    Vec3<T> r;
    switch (mode_) {
      case Mode::kTwist: {
        const T theta = z * k;
        r = Vec3<T>(x * cos(theta) - y * sin(theta), x * sin(theta) + y * cos(theta), z) + d;
        break;
      }
      case Mode::kTaper: {
        const T scale = z * k;
        r = Vec3<T>(x + x * scale, y + y * scale, z) + d;
        break;
      }
      case Mode::kStretch: {
        const T scale = z * z * k - k + T(1);
        r = Vec3<T>(x * scale, y * scale, z * (T(1) + k)) + d;
        break;
      }
      case Mode::kBend: {
        const T theta = (axis_ == 2 ? x : z) * k;
        const T s = sin(theta), cs = cos(theta);
        if (axis_ == 0) {
          r = Vec3<T>(x + d[0], y * cs + (T(1) - cs) / k + s * d[2], -(y - T(1) / k) * s + cs * d[2]);
        } else if (axis_ == 1) {
          r = Vec3<T>(x * cs + (T(1) - cs) / k + s * d[2], y + d[1], -(x - T(1) / k) * s + cs * d[2]);
        } else {
          r = Vec3<T>(-(y - T(1) / k) * s + cs * d[0], y * cs + (T(1) - cs) / k + s * d[0], z + d[2]);
        }
        break;
      }
    }
    Vec3<T> unmapped;
    for (int a = 0; a < 3; ++a) unmapped[map[a]] = r[a];
    (*out)[i] = unmapped;
  }
}

template void SimpleDeformOp::Apply<double>(const double*, const double&, const Positions<double>&,
                                            Positions<double>*) const;
template void SimpleDeformOp::Apply<JetT>(const JetT*, const JetT&, const Positions<JetT>&,
                                          Positions<JetT>*) const;

Json SimpleDeformOp::ParamsToJson() const {
  Json j = {{"axis", kAxes[axis_]}, {"limits", {limits_[0], limits_[1]}}};
  if (UsesAngle()) {
    j["angle_deg"] = RadToDeg(params_[0]);
  } else {
    j["factor"] = params_[0];
  }
  return j;
}

std::string SimpleDeformOp::BlenderCode() const {
  static const char* kMethods[] = {"TWIST", "BEND", "TAPER", "STRETCH"};
  std::string code = "m = obj.modifiers.new('" + Name() + "', 'SIMPLE_DEFORM')\n";
  code += "m.deform_method = " + PyWord(kMethods[static_cast<int>(mode_)]) + "\n";
  code += "m.deform_axis = " + PyWord(kAxes[axis_]) + "\n";
  code += std::string(UsesAngle() ? "m.angle" : "m.factor") + " = " + Py(params_[0]) + "\n";
  code += "m.limits = (" + Py(limits_[0]) + ", " + Py(limits_[1]) + ")\n";
  code += "m.lock_x = m.lock_y = m.lock_z = False\n";
  return code;
}

}  // namespace opgraph
