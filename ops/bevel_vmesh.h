// Geometry of Blender 3.4's bevel (bmesh_bevel.c), templated on the scalar type so Jets flow
// through it: edge profiles (superellipse r = 2, i.e. elliptical arcs with chords even in angle),
// and the vertex meshes ("VMesh") that fill the corner where three or more beveled edges meet:
// Blender's cubic subdivision of a 2-segment control mesh (adj_vmesh + cubic_subdiv +
// interp_vmesh) and the cube-corner special case (unit sphere octant mapped onto the corner).
// Thresholds and branch structure follow Blender; branch decisions use the value part only.
#pragma once

#include <cmath>
#include <functional>
#include <vector>

#include "core/geometry.h"
#include "ops/bevel_math.h"
#include "ops/bevel_profile.h"
#include "ops/op.h"

namespace opgraph {
namespace bevel {

// Vertex mesh grid: point (i, j, k) with i the boundary vertex, j the ring (0 <= j <= ns/2) and
// k the segment (0 <= k <= ns); neighbouring sectors overlap, and Canon() names the one
// stored copy (Blender's mesh_vert_canon).
struct GridIndex {
  int i, j, k;
};
inline GridIndex Canon(int n, int ns, int i, int j, int k) {
  const int ns2 = ns / 2, odd = ns % 2;
  if (!odd && j == ns2 && k == ns2) return {0, j, k};
  if (j <= ns2 - 1 + odd && k <= ns2) return {i, j, k};
  if (k <= ns2) return {(i + n - 1) % n, k, ns - j};
  return {(i + 1) % n, ns - k, j};
}
inline bool IsCanon(int ns, int i, int j, int k) {
  const int ns2 = ns / 2;
  if (ns % 2 == 1) return j <= ns2 && k <= ns2;
  return (j < ns2 && k <= ns2) || (j == ns2 && k == ns2 && i == 0);
}

template <typename T>
struct VGrid {
  int n = 0, ns = 0;
  std::vector<V3<T>> co;
  VGrid(int count, int segments) : n(count), ns(segments), co(count * (segments / 2 + 1) * (segments + 1), Zero3<T>()) {}
  V3<T>& at(int i, int j, int k) { return co[(i * (ns / 2 + 1) + j) * (ns + 1) + k]; }
  const V3<T>& at(int i, int j, int k) const { return co[(i * (ns / 2 + 1) + j) * (ns + 1) + k]; }
  V3<T>& canon(int i, int j, int k) {
    const GridIndex c = Canon(n, ns, i, j, k);
    return at(c.i, c.j, c.k);
  }
  const V3<T>& canon(int i, int j, int k) const {
    const GridIndex c = Canon(n, ns, i, j, k);
    return at(c.i, c.j, c.k);
  }
  void CopyEquiv() {
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j <= ns / 2; ++j) {
        for (int k = 0; k <= ns; ++k) {
          if (!IsCanon(ns, i, j, k)) at(i, j, k) = canon(i, j, k);
        }
      }
    }
  }
};

// Profile point k of nseg of boundary vertex i's profile (toward boundary vertex i + 1).
template <typename T>
using ProfilePointFn = std::function<V3<T>(int i, int k, int nseg)>;

template <typename T>
void Avg4(V3<T>* out, const V3<T>& a, const V3<T>& b, const V3<T>& c, const V3<T>& d) {
  *out = (a + b + c + d) * T(0.25);
}

// Gamma of the Sabin modification of Catmull-Clark at the centre of an n-sided patch.
double SabinGamma(int n);

// One step of Blender's cubic_subdiv (Catmull-Clark with smoothed profile boundary), ns -> 2 ns.
template <typename T>
VGrid<T> CubicSubdiv(VGrid<T>& in, const ProfilePointFn<T>& profile_point) {
  const int n = in.n, ns_in = in.ns, ns_in2 = ns_in / 2, ns_out = 2 * ns_in;
  VGrid<T> out(n, ns_out);
  const T sixth(1.0 / 6.0);
  for (int i = 0; i < n; ++i) {
    out.at(i, 0, 0) = in.at(i, 0, 0);
    for (int k = 1; k < ns_in; ++k) {
      V3<T> co = in.at(i, 0, k);
      const V3<T> acc = in.at(i, 0, k - 1) + in.at(i, 0, k + 1) - co * T(2);
      co -= acc * sixth;
      out.canon(i, 0, 2 * k) = co;
    }
  }
  for (int i = 0; i < n; ++i) {
    for (int k = 1; k < ns_out; k += 2) {
      V3<T> co = profile_point(i, k, ns_out);
      const V3<T> acc = out.canon(i, 0, k - 1) + out.canon(i, 0, k + 1) - co * T(2);
      co -= acc * sixth;
      out.canon(i, 0, k) = co;
    }
  }
  out.CopyEquiv();
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < ns_in; ++k) in.at(i, 0, k) = out.at(i, 0, 2 * k);
  }
  in.CopyEquiv();
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < ns_in2; ++j) {
      for (int k = 0; k < ns_in2; ++k) {
        Avg4(&out.at(i, 2 * j + 1, 2 * k + 1), in.at(i, j, k), in.at(i, j, k + 1), in.at(i, j + 1, k),
                in.at(i, j + 1, k + 1));
      }
    }
  }
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < ns_in2; ++j) {
      for (int k = 1; k <= ns_in2; ++k) {
        Avg4(&out.at(i, 2 * j + 1, 2 * k), in.at(i, j, k), in.at(i, j + 1, k), out.canon(i, 2 * j + 1, 2 * k - 1),
                out.canon(i, 2 * j + 1, 2 * k + 1));
      }
    }
  }
  for (int i = 0; i < n; ++i) {
    for (int j = 1; j < ns_in2; ++j) {
      for (int k = 0; k < ns_in2; ++k) {
        Avg4(&out.at(i, 2 * j, 2 * k + 1), in.at(i, j, k), in.at(i, j, k + 1), out.canon(i, 2 * j - 1, 2 * k + 1),
                out.canon(i, 2 * j + 1, 2 * k + 1));
      }
    }
  }
  const T gamma(0.25), beta(-0.25);
  for (int i = 0; i < n; ++i) {
    for (int j = 1; j < ns_in2; ++j) {
      for (int k = 1; k <= ns_in2; ++k) {
        V3<T> co1, co2;
        Avg4(&co1, out.canon(i, 2 * j, 2 * k - 1), out.canon(i, 2 * j, 2 * k + 1), out.canon(i, 2 * j - 1, 2 * k),
                out.canon(i, 2 * j + 1, 2 * k));
        Avg4(&co2, out.canon(i, 2 * j - 1, 2 * k - 1), out.canon(i, 2 * j + 1, 2 * k - 1),
                out.canon(i, 2 * j - 1, 2 * k + 1), out.canon(i, 2 * j + 1, 2 * k + 1));
        out.at(i, 2 * j, 2 * k) = co1 + co2 * beta + in.at(i, j, k) * gamma;
      }
    }
  }
  out.CopyEquiv();
  const T center_gamma(SabinGamma(n));
  V3<T> co1 = Zero3<T>(), co2 = Zero3<T>();
  for (int i = 0; i < n; ++i) {
    co1 += out.at(i, ns_in, ns_in - 1);
    co2 += out.at(i, ns_in - 1, ns_in - 1) + out.at(i, ns_in - 1, ns_in + 1);
  }
  const V3<T> center = co1 * T(1.0 / n) - co2 * (center_gamma / T(2.0 * n)) + in.at(0, ns_in2, ns_in2) * center_gamma;
  for (int i = 0; i < n; ++i) out.at(i, ns_in, ns_in) = center;
  for (int i = 0; i < n; ++i) {
    const int inext = (i + 1) % n;
    for (int k = 0; k <= ns_out; ++k) {
      const V3<T> co = profile_point(i, k, ns_out);
      out.at(i, 0, k) = co;
      if (k >= ns_in && k < ns_out) out.at(inext, ns_out - k, 0) = co;
    }
  }
  return out;
}

// Fractions of arc length along ring 0 of sector i.
template <typename T>
std::vector<T> VmeshFracs(const VGrid<T>& vm, int i) {
  std::vector<T> frac(vm.ns + 1, T(0));
  T total(0);
  for (int k = 0; k < vm.ns; ++k) {
    const V3<T> d = vm.at(i, 0, k) - vm.at(i, 0, k + 1);
    if (Scalar(d.squaredNorm()) > 0) total += Norm(d);
    frac[k + 1] = total;
  }
  if (Scalar(total) > 0) {
    for (int k = 1; k <= vm.ns; ++k) frac[k] /= total;
  } else {
    frac[vm.ns] = T(1);
  }
  return frac;
}

template <typename T>
std::vector<T> ProfileFracs(const ProfilePointFn<T>& profile_point, int i, int ns) {
  std::vector<T> frac(ns + 1, T(0));
  T total(0);
  V3<T> co = profile_point(i, 0, ns);
  for (int k = 0; k < ns; ++k) {
    const V3<T> next = profile_point(i, k + 1, ns);
    const V3<T> d = next - co;
    if (Scalar(d.squaredNorm()) > 0) total += Norm(d);
    frac[k + 1] = total;
    co = next;
  }
  if (Scalar(total) > 0) {
    for (int k = 1; k <= ns; ++k) frac[k] /= total;
  } else {
    frac[ns] = T(1);
  }
  return frac;
}

// Index i with frac[i] <= f <= frac[i + 1], and the rest of the way in *rest.
template <typename T>
int InterpRange(const std::vector<T>& frac, int n, const T& f, T* rest) {
  for (int i = 0; i < n; ++i) {
    if (Scalar(f) <= Scalar(frac[i + 1])) {
      const T r = f - frac[i];
      *rest = Scalar(r) == 0 ? T(0) : r / (frac[i + 1] - frac[i]);
      if (i == n - 1 && Scalar(*rest) == 1.0) {
        *rest = T(0);
        return n;
      }
      return i;
    }
  }
  *rest = T(0);
  return n;
}

// Blender's interp_vmesh: resample a vertex mesh to nseg segments by arc-length fractions.
template <typename T>
VGrid<T> InterpVmesh(const VGrid<T>& in, int nseg, const ProfilePointFn<T>& profile_point) {
  const int n = in.n, ns_in = in.ns, nseg2 = nseg / 2, odd = nseg % 2;
  VGrid<T> out(n, nseg);
  const VGrid<T>& src = in;
  std::vector<T> prev_frac = VmeshFracs(in, n - 1);
  std::vector<T> prev_new_frac = ProfileFracs(profile_point, n - 1, nseg);
  for (int i = 0; i < n; ++i) {
    const std::vector<T> frac = VmeshFracs(in, i);
    const std::vector<T> new_frac = ProfileFracs(profile_point, i, nseg);
    for (int j = 0; j <= nseg2 - 1 + odd; ++j) {
      for (int k = 0; k <= nseg2; ++k) {
        T restk, restkprev;
        const int k_in = InterpRange(frac, ns_in, new_frac[k], &restk);
        const int k_in_prev = InterpRange(prev_frac, ns_in, prev_new_frac[nseg - j], &restkprev);
        int j_in = ns_in - k_in_prev;
        T restj = -restkprev;
        if (Scalar(restj) > -kEpsilon) {
          restj = T(0);
        } else {
          j_in -= 1;
          restj = T(1) + restj;
        }
        V3<T> co;
        if (Scalar(restj) < kEpsilon && Scalar(restk) < kEpsilon) {
          co = src.canon(i, j_in, k_in);
        } else {
          const int j0inc = (Scalar(restj) < kEpsilon || j_in == ns_in) ? 0 : 1;
          const int k0inc = (Scalar(restk) < kEpsilon || k_in == ns_in) ? 0 : 1;
          const V3<T> q0 = src.canon(i, j_in, k_in), q1 = src.canon(i, j_in, k_in + k0inc);
          const V3<T> q2 = src.canon(i, j_in + j0inc, k_in + k0inc), q3 = src.canon(i, j_in + j0inc, k_in);
          const T u = restk, v = restj;
          co = q0 * ((T(1) - u) * (T(1) - v)) + q1 * (u * (T(1) - v)) + q2 * (u * v) + q3 * ((T(1) - u) * v);
        }
        out.at(i, j, k) = co;
      }
    }
    prev_frac = frac;
    prev_new_frac = new_frac;
  }
  if (!odd) {
    V3<T> center;
    if (ns_in % 2) {
      center = Zero3<T>();
      for (int i = 0; i < n; ++i) center += in.at(i, ns_in / 2, ns_in / 2);
      center /= T(static_cast<double>(n));
    } else {
      center = in.at(0, ns_in / 2, ns_in / 2);
    }
    out.at(0, nseg2, nseg2) = center;
  }
  out.CopyEquiv();
  return out;
}

// Subdivide a 2-segment control mesh up to nseg (Blender's loop in adj_vmesh).
template <typename T>
VGrid<T> SubdivideToSegments(VGrid<T> vm, int nseg, const ProfilePointFn<T>& profile_point, bool at_least_once) {
  while (vm.ns < nseg || (at_least_once && vm.ns == 2)) {
    vm = CubicSubdiv(vm, profile_point);
    at_least_once = false;
  }
  if (vm.ns != nseg) vm = InterpVmesh(vm, nseg, profile_point);
  return vm;
}

// The sphere octant vertex mesh of a cube corner (make_cube_corner_adj_vmesh, r = 2): bound
// verts (1,0,0), (0,1,0), (0,0,1). Depends only on the segment count.
VGrid<double> CubeCornerOctant(const ProfileSpacing& spacing);

}  // namespace bevel
}  // namespace opgraph
