// Small geometric helpers templated on the scalar type (double or ceres::Jet).
#pragma once

#include <Eigen/Geometry>
#include <cmath>

#include "core/mesh.h"

namespace opgraph {

// Unnormalised Newell normal of a polygon: its length is twice the polygon's area.
template <typename T>
Vec3<T> FaceAreaNormal(const Positions<T>& positions, const Polygon& face) {
  Vec3<T> n(T(0), T(0), T(0));
  const size_t k = face.size();
  for (size_t i = 0; i < k; ++i) {
    const Vec3<T>& a = positions[face[i]];
    const Vec3<T>& b = positions[face[(i + 1) % k]];
    n += a.cross(b);
  }
  return n;
}

// Blender's face "median centre": the mean of the polygon's vertices.
template <typename T>
Vec3<T> FaceCentroid(const Positions<T>& positions, const Polygon& face) {
  Vec3<T> c(T(0), T(0), T(0));
  for (int v : face) c += positions[v];
  return c / T(static_cast<double>(face.size()));
}

template <typename T>
T Norm(const Vec3<T>& v) {
  using std::sqrt;
  return sqrt(v.squaredNorm());
}

// Normalises with a guard: a zero vector stays zero instead of NaN.
template <typename T>
Vec3<T> SafeNormalized(const Vec3<T>& v) {
  const T n = Norm(v);
  if (n <= T(1e-300)) return Vec3<T>(T(0), T(0), T(0));
  return v / n;
}

// Rotation matrix for XYZ Euler angles in radians (Blender's default rotation mode:
// X first, then Y, then Z, about fixed axes), i.e. R = Rz * Ry * Rx.
template <typename T>
Eigen::Matrix<T, 3, 3> EulerXYZToMatrix(const T& rx, const T& ry, const T& rz) {
  using std::cos;
  using std::sin;
  Eigen::Matrix<T, 3, 3> x, y, z;
  x << T(1), T(0), T(0), T(0), cos(rx), -sin(rx), T(0), sin(rx), cos(rx);
  y << cos(ry), T(0), sin(ry), T(0), T(1), T(0), -sin(ry), T(0), cos(ry);
  z << cos(rz), -sin(rz), T(0), sin(rz), cos(rz), T(0), T(0), T(0), T(1);
  return z * y * x;
}

// Rotation by `angle` radians about the unit `axis` (Rodrigues).
template <typename T>
Eigen::Matrix<T, 3, 3> AxisAngleToMatrix(const Vec3<T>& axis, const T& angle) {
  using std::cos;
  using std::sin;
  const T c = cos(angle), s = sin(angle), t = T(1) - c;
  const T x = axis.x(), y = axis.y(), z = axis.z();
  Eigen::Matrix<T, 3, 3> r;
  r << t * x * x + c, t * x * y - s * z, t * x * z + s * y,  //
      t * x * y + s * z, t * y * y + c, t * y * z - s * x,   //
      t * x * z - s * y, t * y * z + s * x, t * z * z + c;
  return r;
}

template <typename T>
Positions<T> CastPositions(const Positions<double>& positions) {
  Positions<T> out(positions.size());
  for (size_t i = 0; i < positions.size(); ++i) out[i] = positions[i].cast<T>();
  return out;
}

}  // namespace opgraph
