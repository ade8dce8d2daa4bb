// The geometry pass of Bevel (ops/bevel.h), templated on T: the offsets, the width clamp and
// the vertex meshes of every beveled vertex, from the topology ops/bevel.cc prepared.
#include "ops/bevel.h"

#include <Eigen/Dense>
#include <algorithm>
#include <deque>
#include <limits>
#include <unordered_map>

#include "core/geometry.h"

namespace opgraph {

using bevel::V3;


namespace {

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

}  // namespace

// clamp_overlap (bevel_limit_offset / geometry_collide_offset): the smallest width at which the
// clone of an edge collapses (the offset lines of it and its two neighbours in a face meet), or
// a boundary vertex slides past the far end of an un-beveled edge.
template <typename T>
T BevelOp::ClampLimit(const Positions<T>& in) const {
  using std::sin;
  T limit(std::numeric_limits<double>::max());
  for (const BevVert& bv : bev_verts_) {
    const int n = static_cast<int>(bv.edges.size());
    const V3<T>& vb = in[bv.vertex];
    for (int h = 0; h < n; ++h) {
      const EdgeHalf& eb = bv.edges[h];
      const EdgeHalf& ea = bv.edges[(h + 1) % n];
      const int c = eb.other;
      const double kb = eb.beveled, ka = ea.beveled;
      double kc = 0;
      int d = -1;
      if (vertex_to_bev_[c] >= 0) {
        const BevVert& bvc = bev_verts_[vertex_to_bev_[c]];
        const int nc = static_cast<int>(bvc.edges.size());
        int hc = 0;
        while (bvc.edges[hc].other != bv.vertex) ++hc;
        const EdgeHalf& ec = bvc.edges[(hc + nc - 1) % nc];
        kc = ec.beveled;
        d = ec.other;
      } else {
        const Polygon& face = input_faces_[eb.fnext];
        const int k = static_cast<int>(face.size());
        for (int i = 0; i < k; ++i) {
          if (face[i] == c) d = face[(i + 1) % k] == bv.vertex ? face[(i + k - 1) % k] : face[(i + 1) % k];
        }
      }
      if (d < 0 || ea.other == c || d == bv.vertex) continue;
      const V3<T>& va = in[ea.other];
      const V3<T>& vc = in[c];
      const V3<T>& vd = in[d];
      const T th1 = bevel::Angle<T>(va - vb, vc - vb), th2 = bevel::Angle<T>(vb - vc, vd - vc);
      const T sin1 = sin(th1), sin2 = sin(th2);
      if ((ka > 0) + (kb > 0) + (kc > 0) >= 2) {
        // Blender's len * g h / (g (ka sin2 + kc sin1) + kb h (tan1 + tan2)), g = tan1 tan2,
        // h = sin1 sin2, divided through by g (stable at right angles, where tan is huge).
        const double g = std::tan(Scalar(th1)) * std::tan(Scalar(th2));
        const T den = ka * sin2 + kc * sin1 + kb * sin(th1 + th2);
        if (g != 0 && Scalar(den) != 0) {
          const T t = Norm<T>(vc - vb) * sin1 * sin2 / den;
          if (Scalar(t) >= 0 && Scalar(t) < Scalar(limit)) limit = t;
        }
      }
      if (kb > 0 && ka == 0) {
        const T t = Norm<T>(va - vb) * sin1 / kb;
        if (Scalar(t) >= 0 && Scalar(t) < Scalar(limit)) limit = t;
      }
      if (kb > 0 && kc == 0) {
        const T t = Norm<T>(vd - vc) * sin2 / kb;
        if (Scalar(t) >= 0 && Scalar(t) < Scalar(limit)) limit = t;
      }
    }
  }
  return limit;
}

// Boundary vertices of every beveled vertex (build_boundary), with the loop-slide width
// adjustment (adjust_offsets); *off_l gets the final left offsets of every edge half.
template <typename T>
void BevelOp::Boundaries(const Positions<T>& in, const T& width, std::vector<std::vector<T>>* off_l_out,
                         std::vector<std::vector<V3<T>>>* bounds_out) const {
  const BevelGeometry<T> geo(in, input_faces_);
  // Offsets: per bev vert and edge half, left and right (un-beveled edges: 0).
  off_l_out->assign(bev_verts_.size(), {});
  std::vector<std::vector<T>>& off_l = *off_l_out;
  std::vector<std::vector<T>> off_r(bev_verts_.size());
  for (size_t b = 0; b < bev_verts_.size(); ++b) {
    for (const EdgeHalf& e : bev_verts_[b].edges) {
      off_l[b].push_back(e.beveled ? width : T(0));
      off_r[b].push_back(e.beveled ? width : T(0));
    }
  }
  std::vector<V3<T>> vertex_normals;
  for (const BevVert& bv : bev_verts_) vertex_normals.push_back(geo.VertexNormal(bv));

  // Boundary vertices.
  auto bound_position = [&](size_t b, int i, T* sinratio) {
    const BevVert& bv = bev_verts_[b];
    const BoundVert& bnd = bv.bounds[i];
    const int e = bnd.efirst, e2 = bnd.elast;
    const V3<T>& vno = vertex_normals[b];
    *sinratio = T(1);
    switch (bnd.meet) {
      case Meet::kAdjacent:
        return geo.OffsetMeet(bv, e, e2, bv.edges[e].fnext, false, -1, off_r[b][e], off_l[b][e2], vno);
      case Meet::kBetweenNoFace:
        return geo.OffsetMeet(bv, e, e2, -1, true, bnd.e_in_plane, off_r[b][e], off_l[b][e2], vno);
      case Meet::kBetweenFace:
        // All the edges between lie in one plane: Blender 3.4 meets the offsets as if there
        // were none (no drop onto a face), which on slightly bent faces is another point.
        return geo.OffsetMeet(bv, e, e2, bv.edges[e].fnext, false, -1, off_r[b][e], off_l[b][e2], vno);
      case Meet::kSlide:
        return geo.SlideDist(bv, e, width);
      case Meet::kOnEdgeBetween:
      default: {
        V3<T> meet1, meet2;
        T ang1, ang2;
        const int mid = bnd.eon;
        const bool ok1 = geo.OffsetMeetEdge(bv, e, mid, off_r[b][e], off_l[b][mid], vno, &meet1, &ang1);
        const bool ok2 = geo.OffsetMeetEdge(bv, mid, e2, off_r[b][mid], off_l[b][e2], vno, &meet2, &ang2);
        using std::sin;
        if (ok1 && ok2) {
          *sinratio = Scalar(ang1) == 0 ? T(1) : sin(ang2) / sin(ang1);
          return V3<T>((meet1 + meet2) * T(0.5));
        }
        if (ok1) return meet1;
        if (ok2) return meet2;
        return geo.SlideDist(bv, mid, off_r[b][e]);
      }
    }
  };

  bounds_out->assign(bev_verts_.size(), {});
  std::vector<std::vector<V3<T>>>& bounds = *bounds_out;
  std::vector<std::vector<T>> sinratios(bev_verts_.size());
  for (size_t b = 0; b < bev_verts_.size(); ++b) {
    for (size_t i = 0; i < bev_verts_[b].bounds.size(); ++i) {
      T r;
      bounds[b].push_back(bound_position(b, static_cast<int>(i), &r));
      sinratios[b].push_back(r);
    }
  }
  // Loop slide: make the widths at both ends of the beveled edges agree (adjust_offsets).
  if (!chains_.empty()) {
    for (const Chain& chain : chains_) {
      const int np = static_cast<int>(chain.links.size());
      const int nrows = chain.cycle ? 3 * np : 3 * np - 3;
      using Matrix = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
      using Vector = Eigen::Matrix<T, Eigen::Dynamic, 1>;
      Matrix a = Matrix::Constant(nrows, np, T(0));
      Vector rhs = Vector::Constant(nrows, T(0));
      const T weight(0.2);
      for (int i = 0; i < np; ++i) {
        const ChainLink& link = chain.links[i];
        const BoundVert& v = bev_verts_[link.bv].bounds[link.bnd];
        const T& sinratio = sinratios[link.bv][link.bnd];
        if (chain.cycle || i < np - 1) {
          const ChainLink& next = chain.links[(i + 1) % np];
          const BoundVert& vnext = bev_verts_[next.bv].bounds[next.bnd];
          a(i, i) += T(1);
          if (chain.cycle) {
            a(i > 0 ? i - 1 : np - 1, i) -= sinratio;
          } else if (i > 0) {
            a(i - 1, i) -= sinratio;
          }
          const int row = chain.cycle ? np + 2 * i : np - 1 + 2 * i;
          a(row, i) += weight;
          rhs(row) += weight * off_r[link.bv][v.efirst];
          a(row + 1, i == np - 1 ? 0 : i + 1) += weight * sinratios[next.bv][next.bnd];
          rhs(row + 1) += weight * off_l[next.bv][vnext.elast];
        } else {
          a(i - 1, i) -= T(1);
        }
      }
      const Vector x = (a.transpose() * a).ldlt().solve(a.transpose() * rhs);
      for (int i = 0; i < np; ++i) {
        const ChainLink& link = chain.links[i];
        const BoundVert& v = bev_verts_[link.bv].bounds[link.bnd];
        if (chain.cycle || i < np - 1) {
          off_r[link.bv][v.efirst] = x(i);
          if (chain.cycle || i > 0) off_l[link.bv][v.elast] = sinratios[link.bv][link.bnd] * x(i);
        } else {
          off_l[link.bv][v.elast] = x(i);
        }
      }
    }
    // Rebuild the boundaries with the adjusted widths.
    for (size_t b = 0; b < bev_verts_.size(); ++b) {
      for (size_t i = 0; i < bev_verts_[b].bounds.size(); ++i) {
        T r;
        bounds[b][i] = bound_position(b, static_cast<int>(i), &r);
      }
    }
  }
}

bool BevelOp::NearGeometricBranch(double gate, const Positions<double>& in) const {
  // Blender's float32 coordinates move these angles by about 1e-5 radians between vertices a
  // bevel width apart (measured: a switch 5e-6 from ours held), normals' dot products by 1e-7.
  constexpr double kAngleMargin = 1e-4, kDotMargin = 1e-6;
  if (prepare_angle_margin_ < kAngleMargin || prepare_dot_margin_ < kDotMargin) return true;
  if (order_dependent_corner_ && segments_ >= 2) return true;
  double margin = 1e300;
  Positions<double> out;
  ApplyNoting(params_.data(), gate, in, &out, &margin);
  return margin < kAngleMargin;
}

template <typename T>
void BevelOp::ApplyNoting(const T* p, const T& gate, const Positions<T>& in, Positions<T>* out, double* margin) const {
  out->assign(num_output_vertices_, bevel::Zero3<T>());
  for (size_t v = 0; v < in.size(); ++v) {
    if (kept_vertex_id_[v] >= 0) (*out)[kept_vertex_id_[v]] = in[v];
  }
  T width = gate * p[0];
  const T limit = ClampLimit(in);
  if (Scalar(limit) < Scalar(width)) width = limit;
  const int ns = segments_;

  std::vector<std::vector<T>> off_l;
  std::vector<std::vector<V3<T>>> bounds;
  Boundaries(in, width, &off_l, &bounds);

  for (size_t b = 0; b < bev_verts_.size(); ++b) {
    const BevVert& bv = bev_verts_[b];
    const int n = static_cast<int>(bv.bounds.size());
    const V3<T>& v = in[bv.vertex];
    // Profiles (set_profile_params + calculate_profile).
    std::vector<bevel::Profile<T>> profiles(n);
    for (int i = 0; i < n; ++i) {
      bevel::Profile<T>& pro = profiles[i];
      const V3<T>& start = bounds[b][i];
      const V3<T>& end = bounds[b][(i + 1) % n];
      const int h = bv.bounds[i].ebev;
      const int ne = static_cast<int>(bv.edges.size());
      bool linear = false;
      pro.start = start;
      pro.end = end;
      if (h < 0) {  // no beveled edge starts here: a straight segment
        pro.line = true;
        pro.middle = (start + end) * T(0.5);
        continue;
      }
      pro.proj_dir = SafeNormalized<T>(v - in[bv.edges[h].other]);
      V3<T> other_point;
      if (bevel::IsectLineLine(v, in[bv.edges[h].other], start, end, &pro.middle, &other_point) == 0) pro.middle = v;
      V3<T> d1 = SafeNormalized<T>(pro.middle - start), d2 = SafeNormalized<T>(pro.middle - end);
      pro.plane_no = SafeNormalized<T>(d1.cross(d2));
      if (bevel::NearlyParallel(d1, d2, margin)) {
        pro.middle = v;
        const EdgeHalf& eprev = bv.edges[(h + ne - 1) % ne];
        const EdgeHalf& enext = bv.edges[(h + 1) % ne];
        if (eprev.beveled && enext.beveled && bv.selcount >= 3) {
          const V3<T> d3 = SafeNormalized<T>(in[eprev.other] - v), d4 = SafeNormalized<T>(in[enext.other] - v);
          V3<T> meet, meet2;
          if (bevel::NearlyParallel(d3, d4, margin) || bevel::IsectLineLine<T>(start, start + d3, end, end + d4, &meet, &meet2) == 0) {
            linear = true;
          } else {
            pro.middle = meet;
          }
        }
        d1 = SafeNormalized<T>(pro.middle - start);
        d2 = SafeNormalized<T>(pro.middle - end);
        pro.plane_no = SafeNormalized<T>(d1.cross(d2));
        if (bevel::NearlyParallel(d1, d2, margin)) {
          linear = true;
        } else {
          pro.proj_dir = pro.plane_no;
        }
      }
      pro.plane_co = start;
      if (linear) {
        pro.line = true;
        pro.middle = (start + end) * T(0.5);
        pro.plane_co = pro.plane_no = pro.proj_dir = bevel::Zero3<T>();
      } else {
        pro.line = false;
      }
    }
    if (bv.selcount == 1 && !profiles[0].line) {
      // move_profile_plane: the terminal profile onto the plane through v and its two ends.
      bevel::Profile<T>& pro = profiles[0];
      const V3<T> d1 = SafeNormalized<T>(v - pro.start), d2 = SafeNormalized<T>(v - pro.end);
      V3<T> no = d1.cross(d2), no2 = d1.cross(pro.proj_dir), no3 = d2.cross(pro.proj_dir);
      const double eps = bevel::kEpsilonBig;
      if (Scalar(Norm(no)) > eps && Scalar(Norm(no2)) > eps && Scalar(Norm(no3)) > eps) {
        no = SafeNormalized(no);
        no2 = SafeNormalized(no2);
        no3 = SafeNormalized(no3);
        if (std::abs(Scalar(no.dot(no2))) < 1 - eps && std::abs(Scalar(no.dot(no3))) < 1 - eps) pro.plane_no = no;
      }
    }
    if (bv.kind == Kind::kWeld) {
      // move_weld_profile_planes: both profiles onto the plane through v and the two bound verts.
      bevel::Profile<T>& p1 = profiles[bv.weld1];
      bevel::Profile<T>& p2 = profiles[bv.weld2];
      if (!bevel::IsZero(p1.proj_dir) && !bevel::IsZero(p2.proj_dir)) {
        const V3<T> d1 = v - bounds[b][bv.weld1], d2 = v - bounds[b][bv.weld2];
        V3<T> no = d1.cross(d2), no2 = d1.cross(p1.proj_dir), no3 = d2.cross(p2.proj_dir);
        const double l1 = Scalar(no.squaredNorm()), l2 = Scalar(no2.squaredNorm()), l3 = Scalar(no3.squaredNorm());
        no = SafeNormalized(no);
        no2 = SafeNormalized(no2);
        no3 = SafeNormalized(no3);
        const double eps2 = bevel::kEpsilon * bevel::kEpsilon;
        if (l1 > eps2 && (l2 > eps2 || l3 > eps2)) {
          if (std::abs(std::abs(Scalar(no.dot(no2))) - 1) > bevel::kEpsilon) p1.plane_no = no;
          if (std::abs(std::abs(Scalar(no.dot(no3))) - 1) > bevel::kEpsilon) p2.plane_no = no;
        }
      }
    }
    for (bevel::Profile<T>& pro : profiles) pro.Calculate(spacing_);

    // The vertex mesh.
    bevel::VGrid<T> grid(n, ns);
    for (int i = 0; i < n; ++i) grid.at(i, 0, 0) = bounds[b][i];
    if (bv.kind == Kind::kWeld) {
      const bevel::Profile<T>& p1 = profiles[bv.weld1];
      const bevel::Profile<T>& p2 = profiles[bv.weld2];
      for (int k = 1; k < ns; ++k) {
        const V3<T> va = p1.Point(spacing_, k, ns), vb = p2.Point(spacing_, ns - k, ns);
        if (p1.line && !p2.line) {
          grid.at(bv.weld1, 0, k) = vb;
        } else if (p2.line && !p1.line) {
          grid.at(bv.weld1, 0, k) = va;
        } else {
          grid.at(bv.weld1, 0, k) = (va + vb) * T(0.5);
        }
      }
    } else if (bv.selcount == 1) {
      for (int k = 1; k < ns; ++k) grid.at(0, 0, k) = profiles[0].Point(spacing_, k, ns);
    } else if (bv.kind == Kind::kCubeCorner) {
      // make_unit_cube_map: (1,0,0), (0,1,0), (0,0,1), (1,1,1) -> bound verts 0, 1, 2 and v.
      const V3<T>& va = bounds[b][0];
      const V3<T>& vb = bounds[b][1];
      const V3<T>& vc = bounds[b][2];
      const V3<T> c0 = (va - vb - vc + v) * T(0.5), c1 = (vb - va - vc + v) * T(0.5);
      const V3<T> c2 = (vc - va - vb + v) * T(0.5), c3 = (va + vb + vc - v) * T(0.5);
      for (size_t s = 0; s < grid.co.size(); ++s) {
        const Vec3d& q = octant_.co[s];
        grid.co[s] = c0 * T(q[0]) + c1 * T(q[1]) + c2 * T(q[2]) + c3;
      }
      for (int i = 0; i < n; ++i) grid.at(i, 0, 0) = bounds[b][i];
    } else if (bv.kind == Kind::kAdjacent || bv.kind == Kind::kPipe) {
      // adj_vmesh: a 2-segment control mesh with its centre pulled toward v by the profile's
      // fullness, refined by cubic subdivision and resampled to the segment count.
      bevel::VGrid<T> vm0(n, 2);
      V3<T> center = bevel::Zero3<T>();
      for (int i = 0; i < n; ++i) {
        vm0.at(i, 0, 0) = bounds[b][i];
        vm0.at(i, 0, 1) = profiles[i].Point(spacing_, 1, 2);
        center += bounds[b][i];
      }
      center /= T(static_cast<double>(n));
      const V3<T> direction = v - center;
      vm0.at(0, 1, 1) = Scalar(direction.squaredNorm()) > 1e-12 ? V3<T>(center + direction * T(spacing_.fullness)) : center;
      vm0.CopyEquiv();
      const bevel::ProfilePointFn<T> profile_point = [&](int i, int k, int nseg) {
        return profiles[i].Point(spacing_, k, nseg);
      };
      grid = bevel::SubdivideToSegments(vm0, ns, profile_point, true);
      if (bv.kind == Kind::kPipe) {
        // pipe_adj_vmesh: snap the interior onto the pipe's profile, in the plane through each
        // point perpendicular to the pipe (snap_to_pipe_profile, r = 2).
        const bevel::Profile<T>& pro = profiles[bv.pipe];
        const V3<T> edir = SafeNormalized<T>(v - in[bv.edges[bv.bounds[bv.pipe].ebev].other]);
        for (int i = 0; i < n; ++i) {
          for (int j = 1; j <= ns / 2; ++j) {
            for (int k = 0; k <= ns / 2; ++k) {
              if (!bevel::IsCanon(ns, i, j, k)) continue;
              V3<T>& co = grid.at(i, j, k);
              if (Scalar((pro.start - pro.end).cwiseAbs().maxCoeff()) <= bevel::kEpsilon) {
                co = pro.start;
                continue;
              }
              auto to_plane = [&](const V3<T>& q) { return V3<T>(q - edir * edir.dot(q - co)); };
              bevel::Profile<T> flat;
              flat.start = to_plane(pro.start);
              flat.middle = to_plane(pro.middle);
              flat.end = to_plane(pro.end);
              V3<T> c0, c1, c3;
              if (flat.UnitSquareMap(&c0, &c1, &c3)) {
                Eigen::Matrix<T, 3, 3> m;
                m.col(0) = c0;
                m.col(1) = c1;
                m.col(2) = SafeNormalized<T>(c1.cross(c0));
                const V3<T> q = SafeNormalized<T>(V3<T>(m.inverse() * (co - c3)));
                co = m * q + c3;
              } else {
                const V3<T> ab = flat.end - flat.start;
                T t = ab.dot(co - flat.start) / ab.dot(ab);
                if (Scalar(t) < 0) t = T(0);
                if (Scalar(t) > 1) t = T(1);
                co = flat.start + ab * t;
              }
            }
          }
        }
        grid.CopyEquiv();
      }
      for (int i = 0; i < n; ++i) grid.at(i, 0, 0) = bounds[b][i];
    }
    for (size_t s = 0; s < bv.ids.size(); ++s) {
      if (bv.ids[s] >= 0) (*out)[bv.ids[s]] = grid.co[s];
    }
  }
}

template void BevelOp::ApplyNoting<double>(const double*, const double&, const Positions<double>&,
                                           Positions<double>*, double*) const;
template void BevelOp::ApplyNoting<JetT>(const JetT*, const JetT&, const Positions<JetT>&, Positions<JetT>*,
                                         double*) const;

}  // namespace opgraph
