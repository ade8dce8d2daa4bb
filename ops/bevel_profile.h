// A Blender 3.4 bevel edge profile (superellipse r = 2: an elliptical arc with chords even in
// angle), templated on the scalar type.
#pragma once

#include <vector>

#include "ops/bevel_math.h"

namespace opgraph {
namespace bevel {

// Evenly spaced (in angle) points of the unit quarter circle, from (0, 1) to (1, 0).
struct ProfileSpacing {
  int seg = 1;
  int seg_2 = 4;  // power of 2 >= seg, at least 4: resolution used while building vertex meshes
  std::vector<double> x, y, x2, y2;
  double fullness = 0;
  explicit ProfileSpacing(int segments);
};

// One boundary profile: an arc from `start` to `end` inside the parallelogram spanned at
// `middle`, then projected along `proj_dir` onto the plane (plane_co, plane_no).
template <typename T>
struct Profile {
  V3<T> start, middle, end;
  V3<T> plane_no = Zero3<T>(), plane_co = Zero3<T>(), proj_dir = Zero3<T>();
  bool line = true;        // super_r == 1: straight segment
  std::vector<V3<T>> co;   // seg + 1 points
  std::vector<V3<T>> co2;  // seg_2 + 1 points

  // Blender's make_unit_square_map: (0,1) -> start, (1,1) -> middle, (1,0) -> end.
  bool UnitSquareMap(V3<T>* c0, V3<T>* c1, V3<T>* c3) const {
    const V3<T> va_vmid = middle - start, vb_vmid = middle - end;
    if (IsZero(va_vmid) || IsZero(vb_vmid)) return false;
    if (std::abs(Scalar(Angle(va_vmid, vb_vmid)) - kPi) <= kEpsilonAng) return false;
    *c0 = middle - start;
    *c1 = middle - end;
    *c3 = start + end - middle;
    return true;
  }

  void Calculate(const ProfileSpacing& spacing) {
    if (spacing.seg == 1) return;
    V3<T> c0, c1, c3;
    const bool map_ok = !line && UnitSquareMap(&c0, &c1, &c3);
    for (int pass = 0; pass < 2; ++pass) {
      const int ns = pass == 0 ? spacing.seg : spacing.seg_2;
      const std::vector<double>& xs = pass == 0 ? spacing.x : spacing.x2;
      const std::vector<double>& ys = pass == 0 ? spacing.y : spacing.y2;
      std::vector<V3<T>>& out = pass == 0 ? co : co2;
      out.assign(ns + 1, Zero3<T>());
      for (int k = 0; k <= ns; ++k) {
        V3<T> p;
        if (k == 0) {
          p = start;
        } else if (k == ns) {
          p = end;
        } else if (map_ok) {
          p = c0 * T(xs[k]) + c1 * T(ys[k]) + c3;
        } else {
          p = start + (end - start) * T(static_cast<double>(k) / ns);
        }
        if (!IsZero(proj_dir)) {
          V3<T> projected;
          out[k] = IsectLinePlane<T>(p, p + proj_dir, plane_co, plane_no, &projected) ? projected : p;
        } else {
          out[k] = p;
        }
      }
    }
  }

  // Point i of nseg along the profile (nseg == seg, or a power of 2 <= seg_2).
  V3<T> Point(const ProfileSpacing& spacing, int i, int nseg) const {
    if (spacing.seg == 1) return i == 0 ? start : end;
    if (nseg == spacing.seg) return co[i];
    return co2[i * (spacing.seg_2 / nseg)];
  }
};

}  // namespace bevel
}  // namespace opgraph
