#include "core/surface_distance.h"

#include <cmath>

#include <algorithm>
#include <limits>
#include <random>

#include "core/nearest.h"

namespace opgraph {

namespace {

// Every fan triangulation of every polygon (from each of its corners), so a non-planar
// polygon's surface does not depend on which corner its loop starts at.
std::vector<MeshTriangle> AllFans(const Mesh& mesh) {
  std::vector<MeshTriangle> tris;
  for (int face = 0; face < mesh.NumFaces(); ++face) {
    const Polygon& f = mesh.faces[face];
    const size_t n = f.size();
    const size_t fans = n == 3 ? 1 : n;
    for (size_t s = 0; s < fans; ++s) {
      for (size_t i = 1; i + 1 < n; ++i) tris.push_back({face, {f[s], f[(s + i) % n], f[(s + i + 1) % n]}});
    }
  }
  return tris;
}

std::vector<Vec3d> SamplePoints(const Mesh& mesh) {
  std::vector<Vec3d> points = mesh.vertices;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (const Polygon& f : mesh.faces) {
    for (size_t i = 0; i < f.size(); ++i) {
      points.push_back(0.5 * (mesh.vertices[f[i]] + mesh.vertices[f[(i + 1) % f.size()]]));
    }
  }
  for (const MeshTriangle& t : AllFans(mesh)) {
    const Vec3d &a = mesh.vertices[t.v[0]], &b = mesh.vertices[t.v[1]], &c = mesh.vertices[t.v[2]];
    points.push_back((a + b + c) / 3);
    for (int k = 0; k < 4; ++k) {
      double r1 = u(rng), r2 = u(rng);
      if (r1 + r2 > 1) r1 = 1 - r1, r2 = 1 - r2;
      points.push_back(a + r1 * (b - a) + r2 * (c - a));
    }
  }
  return points;
}

}  // namespace

double BoundingBoxDiagonal(const Mesh& mesh) {
  Vec3d lo = Vec3d::Constant(std::numeric_limits<double>::max()), hi = -lo;
  for (const Vec3d& v : mesh.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  return (hi - lo).norm();
}

double MaxPointToSurfaceDistance(const Mesh& from, const Mesh& to) {
  const std::vector<MeshTriangle> triangles = AllFans(to);
  if (triangles.empty()) return std::numeric_limits<double>::infinity();
  const TriangleTree tree(to.vertices, triangles);
  double worst = 0;
  for (const Vec3d& p : SamplePoints(from)) worst = std::max(worst, tree.Closest(p).squared_distance);
  return std::sqrt(worst);
}

double SymmetricSurfaceDistanceRelative(const Mesh& a, const Mesh& b) {
  return std::max(MaxPointToSurfaceDistance(a, b), MaxPointToSurfaceDistance(b, a)) /
         BoundingBoxDiagonal(a);
}

}  // namespace opgraph
