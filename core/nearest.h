// Nearest-neighbour structures shared by the metrics and the fitter: fan triangulation of
// polygon meshes, seeded area-weighted surface sampling, closest points on a triangle mesh
// (bounding-volume hierarchy) and nearest points of a point set (nanoflann kd-tree).
#pragma once

#include <cstdint>
#include <Eigen/Geometry>
#include <memory>
#include <vector>

#include "core/mesh.h"

namespace opgraph {

// One triangle of a polygon's fan triangulation from its first corner.
struct MeshTriangle {
  int face;
  int v[3];
};

// #T triangles: each polygon of `faces` fanned from its first corner.
std::vector<MeshTriangle> FanTriangulate(const std::vector<Polygon>& faces);

// Points on a triangulated surface: sample i lies in triangles[i] at barycentric weights
// barycentrics[i] (of the triangle's corners v[0], v[1], v[2]).
struct SurfaceSamples {
  Positions<double> points;         // #N
  Positions<double> normals;        // #N unit normals (zero on degenerate triangles)
  std::vector<int> triangles;       // #N indices into the triangulation
  std::vector<Vec3d> barycentrics;  // #N
};

// `count` area-weighted random samples of the triangulated surface, from `seed` only (the same
// seed gives the same samples on every platform). Empty when the surface has no area.
SurfaceSamples SampleSurface(const Positions<double>& positions, const std::vector<MeshTriangle>& triangles,
                             int count, uint64_t seed);

// A uniform double in [0, 1) from 53 random bits (portable, unlike std::uniform_real_distribution).
double UnitRandom(uint64_t bits);

struct ClosestPoint {
  double squared_distance = 0;
  int triangle = -1;
  Vec3d barycentric = Vec3d::Zero();
  Vec3d point = Vec3d::Zero();
};

// Closest point of triangle (a, b, c) to p, with its barycentric weights.
ClosestPoint ClosestPointOnTriangle(const Vec3d& p, const Vec3d& a, const Vec3d& b, const Vec3d& c);

// Exact closest-point queries on a triangle mesh (median-split bounding-volume hierarchy).
class TriangleTree {
 public:
  TriangleTree(const Positions<double>& positions, const std::vector<MeshTriangle>& triangles);
  ClosestPoint Closest(const Vec3d& query) const;
  // Unit normal of triangle t (zero if degenerate).
  Vec3d Normal(int t) const;

 private:
  struct Node {
    Eigen::AlignedBox3d box;
    int first, count;  // leaf: triangles order_[first, first + count); inner: count = -1
    int left, right;
  };
  int Build(int first, int count);
  const Positions<double>& positions_;
  const std::vector<MeshTriangle>& triangles_;
  std::vector<int> order_;
  std::vector<Vec3d> centroids_;
  std::vector<Node> nodes_;
};

// Nearest point of a fixed point set (kd-tree; keeps a reference to `points`).
class PointTree {
 public:
  explicit PointTree(const Positions<double>& points);
  ~PointTree();
  // Index of the nearest point and its squared distance.
  int Nearest(const Vec3d& query, double* squared_distance) const;
  // Indices of the k nearest points (k <= size).
  void KNearest(const Vec3d& query, int k, std::vector<size_t>* indices, std::vector<double>* squared) const;

 private:
  struct Index;
  std::unique_ptr<Index> index_;
};

}  // namespace opgraph
