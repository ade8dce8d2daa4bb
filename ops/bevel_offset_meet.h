// Blender's per-vertex bevel constructions (offset_meet, offset_meet_edge, the slide along an
// edge) on scalar T, for the boundary pass of ops/bevel_boundaries.cc. Private to ops/bevel*.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <vector>

#include "core/geometry.h"
#include "ops/bevel.h"

namespace opgraph {
namespace bevel {

// The geometry pass of one bevel: all of Blender's per-vertex constructions on scalar T.
template <typename T>
class BevelGeometry {
 public:
  using BevVert = BevelOp::BevVert;
  using EdgeHalf = BevelOp::EdgeHalf;

  BevelGeometry(const Positions<T>& in, const std::vector<Polygon>& faces) : p_(in) {
    face_normals_.reserve(faces.size());
    for (const Polygon& f : faces) face_normals_.push_back(SafeNormalized(FaceAreaNormal(in, f)));
  }

  V3<T> VertexNormal(const BevVert& bv) const {
    const int n = static_cast<int>(bv.edges.size());
    V3<T> sum = bevel::Zero3<T>();
    for (int h = 0; h < n; ++h) {
      const V3<T>& v = p_[bv.vertex];
      sum += face_normals_[bv.edges[h].fnext] *
             bevel::Angle<T>(p_[bv.edges[h].other] - v, p_[bv.edges[(h + 1) % n].other] - v);
    }
    return SafeNormalized(sum);
  }

  V3<T> SlideDist(const BevVert& bv, int h, T d) const {
    const V3<T> dir = p_[bv.edges[h].other] - p_[bv.vertex];
    const T len = Norm(dir);
    if (Scalar(d) > Scalar(len)) d = len - T(50 * bevel::kEpsilon);
    return p_[bv.vertex] + dir * (d / len);
  }

  // Is co between edges h1 and h2 (CCW) in face f? (point_between_edges)
  bool PointBetweenEdges(const V3<T>& co, const BevVert& bv, int f, int h1, int h2) const {
    const V3<T>& v = p_[bv.vertex];
    const V3<T> dir1 = SafeNormalized<T>(v - p_[bv.edges[h1].other]);
    const V3<T> dir2 = SafeNormalized<T>(v - p_[bv.edges[h2].other]);
    const V3<T> dirco = SafeNormalized<T>(v - co);
    double ang11 = Scalar(bevel::AngleNormalized(dir1, dir2));
    double ang1co = Scalar(bevel::AngleNormalized(dir1, dirco));
    if (Scalar(dir1.cross(dir2).dot(face_normals_[f])) < 0) ang11 = 2 * kPi - ang11;
    if (Scalar(dir1.cross(dirco).dot(face_normals_[f])) < 0) ang1co = 2 * kPi - ang1co;
    return ang11 - ang1co > -bevel::kEpsilonAng;
  }

  // Meeting point of the offset lines of h1 (its right side) and h2 (its left side) (offset_meet).
  V3<T> OffsetMeet(const BevVert& bv, int h1, int h2, int f, bool edges_between, int e_in_plane, const T& off1,
                   const T& off2, const V3<T>& vno) const {
    const int n = static_cast<int>(bv.edges.size());
    const V3<T>& v = p_[bv.vertex];
    V3<T> dir1 = v - p_[bv.edges[h1].other];
    const V3<T> dir2 = p_[bv.edges[h2].other] - v;
    V3<T> dir1n = bevel::Zero3<T>(), dir2p = bevel::Zero3<T>();
    if (edges_between) {
      dir1n = p_[bv.edges[(h1 + 1) % n].other] - v;
      dir2p = v - p_[bv.edges[(h2 + n - 1) % n].other];
    }
    using std::cos;
    const T ang = bevel::Angle(dir1, dir2);
    if (Scalar(ang) < bevel::kEpsilonAng) {
      const V3<T> norm_v = f >= 0 ? face_normals_[f] : vno;
      dir1 += dir2;
      const V3<T> perp = SafeNormalized<T>(dir1.cross(norm_v));
      const T d = (Scalar(off1) >= Scalar(off2) ? off1 : off2) / cos(ang / T(2));
      return v + perp * d;
    }
    if (std::abs(Scalar(ang) - kPi) < bevel::kEpsilonAng) {
      return SlideDist(bv, h2, Scalar(off1) >= Scalar(off2) ? off1 : off2);
    }
    V3<T> norm_v1, norm_v2;
    if (f >= 0 && Scalar(ang) < bevel::kSmallAng) {
      norm_v1 = norm_v2 = face_normals_[f];
    } else if (!edges_between) {
      norm_v1 = SafeNormalized<T>(dir2.cross(dir1));
      if (Scalar(norm_v1.dot(f >= 0 ? face_normals_[f] : vno)) < 0) norm_v1 = -norm_v1;
      norm_v2 = norm_v1;
    } else {
      norm_v1 = SafeNormalized<T>(dir1n.cross(dir1));
      const int f1 = bv.edges[h1].fnext;
      if (Scalar(norm_v1.dot(f1 >= 0 ? face_normals_[f1] : vno)) < 0) norm_v1 = -norm_v1;
      norm_v2 = SafeNormalized<T>(dir2.cross(dir2p));
      const int f2 = bv.edges[h2].fprev;
      if (Scalar(norm_v2.dot(f2 >= 0 ? face_normals_[f2] : vno)) < 0) norm_v2 = -norm_v2;
    }
    const V3<T> perp1 = SafeNormalized<T>(dir1.cross(norm_v1));
    const V3<T> perp2 = SafeNormalized<T>(dir2.cross(norm_v2));
    const V3<T> off1a = v + perp1 * off1, off1b = off1a + dir1;
    const V3<T> off2a = v + perp2 * off2, off2b = off2a + dir2;
    V3<T> meet, isect2;
    const int kind = bevel::IsectLineLine(off1a, off1b, off2a, off2b, &meet, &isect2);
    if (kind == 0) return off1a;
    if (edges_between && Scalar(off1) > 0 && Scalar(off2) > 0) {
      if (kind == 2) meet = (meet + isect2) * T(0.5);
      for (int h = h1; h != h2; h = (h + 1) % n) {
        const int fn = bv.edges[h].fnext;
        const V3<T>& no = face_normals_[fn];
        const V3<T> drop = meet - no * no.dot(meet - v);
        if (e_in_plane >= 0) {
          const double a = Scalar(bevel::Angle(no, face_normals_[bv.edges[e_in_plane].fnext]));
          if (std::abs(a) < bevel::kSmallAng || std::abs(a - kPi) < bevel::kSmallAng) continue;
        }
        if (PointBetweenEdges(drop, bv, fn, h, (h + 1) % n)) {
          meet = drop;
          break;
        }
      }
    }
    return meet;
  }

  // offset_meet_edge: where the offset line of the beveled one of (h1, h2) meets the other.
  bool OffsetMeetEdge(const BevVert& bv, int h1, int h2, const T& off1_r, const T& off2_l, const V3<T>& vno,
                      V3<T>* meet, T* angle) const {
    const V3<T>& v = p_[bv.vertex];
    const V3<T> dir1 = SafeNormalized<T>(p_[bv.edges[h1].other] - v);
    const V3<T> dir2 = SafeNormalized<T>(p_[bv.edges[h2].other] - v);
    T ang = bevel::AngleNormalized(dir1, dir2);
    *angle = T(0);
    if (std::abs(Scalar(ang)) < bevel::kGoodAngle) return false;
    if (Scalar(dir1.cross(dir2).dot(vno)) < 0) {
      *angle = T(2 * kPi) - ang;
      return false;
    }
    *angle = ang;
    if (std::abs(Scalar(ang) - kPi) < bevel::kGoodAngle) return false;
    using std::sin;
    const T s = sin(ang);
    *meet = Scalar(off1_r) == 0 ? v + dir1 * (off2_l / s) : v + dir2 * (off1_r / s);
    return true;
  }

  const Positions<T>& p_;
  std::vector<V3<T>> face_normals_;
};

}  // namespace bevel
}  // namespace opgraph
