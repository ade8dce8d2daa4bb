#include "core/surface_distance.h"

#include <algorithm>
#include <limits>
#include <random>

namespace opgraph {

namespace {

struct Triangle {
  Vec3d a, b, c;
};

// Every fan triangulation of every polygon (from each of its corners), so a non-planar
// polygon's surface does not depend on which corner its loop starts at.
std::vector<Triangle> Triangulate(const Mesh& mesh) {
  std::vector<Triangle> tris;
  for (const Polygon& f : mesh.faces) {
    const size_t n = f.size();
    const size_t fans = n == 3 ? 1 : n;
    for (size_t s = 0; s < fans; ++s) {
      for (size_t i = 1; i + 1 < n; ++i) {
        tris.push_back({mesh.vertices[f[s]], mesh.vertices[f[(s + i) % n]], mesh.vertices[f[(s + i + 1) % n]]});
      }
    }
  }
  return tris;
}

// Closest point on triangle (Ericson, Real-Time Collision Detection, 5.1.5).
Vec3d ClosestPointOnTriangle(const Vec3d& p, const Triangle& t) {
  const Vec3d ab = t.b - t.a, ac = t.c - t.a, ap = p - t.a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return t.a;
  const Vec3d bp = p - t.b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return t.b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return t.a + ab * (d1 / (d1 - d3));
  const Vec3d cp = p - t.c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return t.c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return t.a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return t.b + (t.c - t.b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  }
  const double denom = 1.0 / (va + vb + vc);
  return t.a + ab * (vb * denom) + ac * (vc * denom);
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
  for (const Triangle& t : Triangulate(mesh)) {
    points.push_back((t.a + t.b + t.c) / 3);
    for (int k = 0; k < 4; ++k) {
      double r1 = u(rng), r2 = u(rng);
      if (r1 + r2 > 1) r1 = 1 - r1, r2 = 1 - r2;
      points.push_back(t.a + r1 * (t.b - t.a) + r2 * (t.c - t.a));
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
  const std::vector<Triangle> tris = Triangulate(to);
  double worst = 0;
  for (const Vec3d& p : SamplePoints(from)) {
    double best = std::numeric_limits<double>::max();
    for (const Triangle& t : tris) best = std::min(best, (ClosestPointOnTriangle(p, t) - p).squaredNorm());
    worst = std::max(worst, best);
  }
  return std::sqrt(worst);
}

double SymmetricSurfaceDistanceRelative(const Mesh& a, const Mesh& b) {
  return std::max(MaxPointToSurfaceDistance(a, b), MaxPointToSurfaceDistance(b, a)) /
         BoundingBoxDiagonal(a);
}

}  // namespace opgraph
