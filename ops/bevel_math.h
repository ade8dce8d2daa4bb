// Blender 3.4 bevel's (bmesh_bevel.c) thresholds and small vector helpers, templated on the
// scalar type so Jets flow through them: angles accurate near 0 and pi, line-line and
// line-plane intersections. Branch decisions use the value part only.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/geometry.h"
#include "ops/op.h"  // Scalar
#include "ops/params.h"  // kPi

namespace opgraph {
namespace bevel {

constexpr double kEpsilon = 1e-6;
constexpr double kEpsilonBig = 1e-4;
constexpr double kEpsilonAng = 2.0 * kPi / 180.0;   // BEVEL_EPSILON_ANG
constexpr double kSmallAng = 10.0 * kPi / 180.0;    // BEVEL_SMALL_ANG
constexpr double kGoodAngle = 0.001;  // where real Blender 3.4 switches (measured; ops/bevel.h)

template <typename T>
using V3 = Vec3<T>;

template <typename T>
V3<T> Zero3() {
  return V3<T>(T(0), T(0), T(0));
}

template <typename T>
bool IsZero(const V3<T>& v) {
  return Scalar(v[0]) == 0 && Scalar(v[1]) == 0 && Scalar(v[2]) == 0;
}

// Angle between unit vectors, accurate near 0 and pi (Blender's angle_normalized_v3v3).
template <typename T>
T AngleNormalized(const V3<T>& a, const V3<T>& b) {
  using std::asin;
  if (Scalar(a.dot(b)) >= 0) {
    const V3<T> d = a - b;
    return Scalar(d.squaredNorm()) == 0 ? T(0) : T(2) * asin(Norm(d) / T(2));
  }
  const V3<T> s = a + b;
  return Scalar(s.squaredNorm()) == 0 ? T(kPi) : T(kPi) - T(2) * asin(Norm(s) / T(2));
}

template <typename T>
T Angle(const V3<T>& a, const V3<T>& b) {
  return AngleNormalized<T>(SafeNormalized(a), SafeNormalized(b));
}

// `margin` (when given) is lowered to how far the angle is from either switch.
template <typename T>
bool NearlyParallel(const V3<T>& d1, const V3<T>& d2, double* margin = nullptr) {
  const double ang = Scalar(Angle(d1, d2));
  if (margin != nullptr) {
    *margin = std::min({*margin, std::abs(std::abs(ang) - kEpsilonAng), std::abs(std::abs(ang - kPi) - kEpsilonAng)});
  }
  return std::abs(ang) < kEpsilonAng || std::abs(ang - kPi) < kEpsilonAng;
}

// Closest points of lines (v1, v2) and (v3, v4): 0 when parallel, 1 when they meet, 2 when
// skew (i1 on the first line, i2 on the second), as Blender's isect_line_line_v3.
template <typename T>
int IsectLineLine(const V3<T>& v1, const V3<T>& v2, const V3<T>& v3, const V3<T>& v4, V3<T>* i1,
                  V3<T>* i2) {
  const V3<T> a = v2 - v1, b = v4 - v3, c = v3 - v1;
  const V3<T> ab = a.cross(b);
  const T div = ab.dot(ab);
  if (Scalar(div) == 0) return 0;
  *i1 = v1 + a * (c.cross(b).dot(ab) / div);
  if (std::abs(Scalar(c.dot(ab))) <= 1e-6) {
    *i2 = *i1;
    return 1;
  }
  *i2 = v3 + b * (c.cross(a).dot(ab) / div);
  return 2;
}

// Intersection of line (l1, l2) with a plane; false when (nearly) parallel.
template <typename T>
bool IsectLinePlane(const V3<T>& l1, const V3<T>& l2, const V3<T>& plane_co, const V3<T>& plane_no,
                    V3<T>* out) {
  const V3<T> u = l2 - l1;
  const T dot = plane_no.dot(u);
  if (std::abs(Scalar(dot)) <= 1.1920929e-07) return false;
  *out = l1 + u * (-plane_no.dot(l1 - plane_co) / dot);
  return true;
}

}  // namespace bevel
}  // namespace opgraph
