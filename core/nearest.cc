#include "core/nearest.h"

#include <algorithm>
#include <limits>
#include <nanoflann.hpp>
#include <random>

namespace opgraph {

std::vector<MeshTriangle> FanTriangulate(const std::vector<Polygon>& faces) {
  std::vector<MeshTriangle> triangles;
  for (size_t f = 0; f < faces.size(); ++f) {
    const Polygon& face = faces[f];
    for (size_t i = 1; i + 1 < face.size(); ++i) {
      triangles.push_back({static_cast<int>(f), {face[0], face[i], face[i + 1]}});
    }
  }
  return triangles;
}

double UnitRandom(uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1.0p-53; }

SurfaceSamples SampleSurface(const Positions<double>& positions, const std::vector<MeshTriangle>& triangles,
                             int count, uint64_t seed) {
  SurfaceSamples samples;
  std::vector<double> cumulative(triangles.size());
  double total = 0;
  for (size_t t = 0; t < triangles.size(); ++t) {
    const MeshTriangle& tri = triangles[t];
    const Vec3d& a = positions[tri.v[0]];
    total += 0.5 * (positions[tri.v[1]] - a).cross(positions[tri.v[2]] - a).norm();
    cumulative[t] = total;
  }
  if (!(total > 0) || count <= 0) return samples;
  std::mt19937_64 rng(seed);
  samples.points.resize(count);
  samples.normals.resize(count);
  samples.triangles.resize(count);
  samples.barycentrics.resize(count);
  for (int i = 0; i < count; ++i) {
    const double pick = UnitRandom(rng()) * total;
    const int t = std::min<int>(std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin(),
                                static_cast<int>(triangles.size()) - 1);
    // Uniform on the triangle: (1 - sqrt(r1), sqrt(r1) (1 - r2), sqrt(r1) r2).
    const double s = std::sqrt(UnitRandom(rng())), r2 = UnitRandom(rng());
    const Vec3d w(1 - s, s * (1 - r2), s * r2);
    const MeshTriangle& tri = triangles[t];
    const Vec3d& a = positions[tri.v[0]];
    const Vec3d& b = positions[tri.v[1]];
    const Vec3d& c = positions[tri.v[2]];
    samples.points[i] = w[0] * a + w[1] * b + w[2] * c;
    const Vec3d n = (b - a).cross(c - a);
    samples.normals[i] = n.norm() > 0 ? Vec3d(n.normalized()) : Vec3d::Zero();
    samples.triangles[i] = t;
    samples.barycentrics[i] = w;
  }
  return samples;
}

// Ericson, Real-Time Collision Detection, 5.1.5, keeping the barycentric weights.
ClosestPoint ClosestPointOnTriangle(const Vec3d& p, const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  ClosestPoint result;
  auto finish = [&](double u, double v, double w) {
    result.barycentric = Vec3d(u, v, w);
    result.point = u * a + v * b + w * c;
    result.squared_distance = (p - result.point).squaredNorm();
    return result;
  };
  const Vec3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return finish(1, 0, 0);
  const Vec3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return finish(0, 1, 0);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return finish(1 - v, v, 0);
  }
  const Vec3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return finish(0, 0, 1);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return finish(1 - w, 0, w);
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return finish(0, 1 - w, w);
  }
  const double denom = va + vb + vc;
  if (!(std::abs(denom) > 0)) return finish(1, 0, 0);  // degenerate triangle
  const double v = vb / denom, w = vc / denom;
  return finish(1 - v - w, v, w);
}

TriangleTree::TriangleTree(const Positions<double>& positions, const std::vector<MeshTriangle>& triangles)
    : positions_(positions), triangles_(triangles) {
  order_.resize(triangles.size());
  centroids_.resize(triangles.size());
  for (size_t t = 0; t < triangles.size(); ++t) {
    order_[t] = static_cast<int>(t);
    centroids_[t] = (positions[triangles[t].v[0]] + positions[triangles[t].v[1]] + positions[triangles[t].v[2]]) / 3;
  }
  nodes_.reserve(2 * triangles.size() + 1);
  if (!triangles.empty()) Build(0, static_cast<int>(triangles.size()));
}

int TriangleTree::Build(int first, int count) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.push_back({});
  Eigen::AlignedBox3d box, centre_box;
  for (int i = first; i < first + count; ++i) {
    for (int k = 0; k < 3; ++k) box.extend(positions_[triangles_[order_[i]].v[k]]);
    centre_box.extend(centroids_[order_[i]]);
  }
  nodes_[index].box = box;
  constexpr int kLeafSize = 4;
  if (count <= kLeafSize) {
    nodes_[index].first = first;
    nodes_[index].count = count;
    return index;
  }
  int axis;
  centre_box.sizes().maxCoeff(&axis);
  const int half = count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count,
                   [&](int a, int b) { return centroids_[a][axis] < centroids_[b][axis]; });
  const int left = Build(first, half);
  const int right = Build(first + half, count - half);
  nodes_[index].first = first;
  nodes_[index].count = -1;
  nodes_[index].left = left;
  nodes_[index].right = right;
  return index;
}

ClosestPoint TriangleTree::Closest(const Vec3d& query) const {
  ClosestPoint best;
  best.squared_distance = std::numeric_limits<double>::infinity();
  if (nodes_.empty()) return best;
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (node.box.squaredExteriorDistance(query) >= best.squared_distance) continue;
    if (node.count >= 0) {
      for (int i = node.first; i < node.first + node.count; ++i) {
        const MeshTriangle& tri = triangles_[order_[i]];
        ClosestPoint c = ClosestPointOnTriangle(query, positions_[tri.v[0]], positions_[tri.v[1]], positions_[tri.v[2]]);
        if (c.squared_distance < best.squared_distance) {
          best = c;
          best.triangle = order_[i];
        }
      }
      continue;
    }
    // Visit the nearer child first.
    const double dl = nodes_[node.left].box.squaredExteriorDistance(query);
    const double dr = nodes_[node.right].box.squaredExteriorDistance(query);
    if (dl < dr) {
      stack[top++] = node.right;
      stack[top++] = node.left;
    } else {
      stack[top++] = node.left;
      stack[top++] = node.right;
    }
  }
  return best;
}

Vec3d TriangleTree::Normal(int t) const {
  const MeshTriangle& tri = triangles_[t];
  const Vec3d n = (positions_[tri.v[1]] - positions_[tri.v[0]]).cross(positions_[tri.v[2]] - positions_[tri.v[0]]);
  return n.norm() > 0 ? Vec3d(n.normalized()) : Vec3d::Zero();
}

namespace {

struct PointCloudAdaptor {
  const Positions<double>& points;
  size_t kdtree_get_point_count() const { return points.size(); }
  double kdtree_get_pt(size_t i, size_t dim) const { return points[i][dim]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const { return false; }
};

using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointCloudAdaptor>,
                                                   PointCloudAdaptor, 3, size_t>;

}  // namespace

struct PointTree::Index {
  explicit Index(const Positions<double>& points)
      : adaptor{points}, tree(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(10)) {
    tree.buildIndex();
  }
  PointCloudAdaptor adaptor;
  KdTree tree;
};

PointTree::PointTree(const Positions<double>& points) : index_(new Index(points)) {}
PointTree::~PointTree() = default;

int PointTree::Nearest(const Vec3d& query, double* squared_distance) const {
  size_t index = 0;
  double squared = std::numeric_limits<double>::infinity();
  nanoflann::KNNResultSet<double, size_t> result(1);
  result.init(&index, &squared);
  index_->tree.findNeighbors(result, query.data(), nanoflann::SearchParams(10));
  if (squared_distance) *squared_distance = squared;
  return static_cast<int>(index);
}

void PointTree::KNearest(const Vec3d& query, int k, std::vector<size_t>* indices,
                         std::vector<double>* squared) const {
  indices->resize(k);
  squared->resize(k);
  const size_t found = index_->tree.knnSearch(query.data(), k, indices->data(), squared->data());
  indices->resize(found);
  squared->resize(found);
}

}  // namespace opgraph
