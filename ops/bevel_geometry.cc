// The geometry pass of Bevel (ops/bevel.h), templated on T: the vertex meshes of every beveled
// vertex on the boundaries ops/bevel_boundaries.cc places, from the topology ops/bevel.cc prepared.
#include "ops/bevel.h"

#include <Eigen/Dense>
#include <algorithm>
#include <limits>

#include "core/geometry.h"

namespace opgraph {

using bevel::V3;

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
