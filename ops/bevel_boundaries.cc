// The boundary pass of Bevel (ops/bevel.h), templated on T: the width clamp (clamp_overlap)
// and the boundary vertices of every beveled vertex with the loop-slide width adjustment.
#include <Eigen/Dense>
#include <limits>

#include "ops/bevel.h"
#include "ops/bevel_offset_meet.h"

namespace opgraph {

using bevel::V3;

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
  const bevel::BevelGeometry<T> geo(in, input_faces_);
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

template double BevelOp::ClampLimit<double>(const Positions<double>&) const;
template JetT BevelOp::ClampLimit<JetT>(const Positions<JetT>&) const;
template void BevelOp::Boundaries<double>(const Positions<double>&, const double&, std::vector<std::vector<double>>*,
                                          std::vector<std::vector<Vec3<double>>>*) const;
template void BevelOp::Boundaries<JetT>(const Positions<JetT>&, const JetT&, std::vector<std::vector<JetT>>*,
                                        std::vector<std::vector<Vec3<JetT>>>*) const;

}  // namespace opgraph
