#include "search/face_residuals.h"

#include <algorithm>
#include <limits>

#include "core/geometry.h"
#include "core/nearest.h"
#include "ops/sequence.h"

namespace opgraph {

FaceResiduals ComputeFaceResiduals(const Target& target, const Layout& layout) {
  Sequence sequence = ParseSequence(layout.Document());
  const std::vector<Mesh> steps = EvaluateSequence(&sequence);
  FaceResiduals r;
  r.cage = steps[layout.CageStep()];
  const Eigen::Matrix3d world_from_local = layout.PoseRotation();
  const Vec3d translation = layout.PoseTranslation();
  const int num_faces = r.cage.NumFaces();
  r.centroids.resize(num_faces), r.normals.resize(num_faces), r.areas.resize(num_faces);
  for (int f = 0; f < num_faces; ++f) {
    r.centroids[f] = FaceCentroid(r.cage.vertices, r.cage.faces[f]);
    const Vec3d area_normal = FaceAreaNormal(r.cage.vertices, r.cage.faces[f]);
    r.normals[f] = SafeNormalized(area_normal);
    r.areas[f] = area_normal.norm();
  }
  const double threshold = 0.04 * 2.0 * layout.half_extent.norm();
  r.outside.resize(num_faces), r.inside.resize(num_faces), r.outside_spread.assign(num_faces, 0.0);
  // Each sample belongs to the face holding its closest cage point (a centroid would hand the
  // rim of a wide face to its narrow neighbours).
  const std::vector<MeshTriangle> triangles = FanTriangulate(r.cage.faces);
  const TriangleTree tree(r.cage.vertices, triangles);
  const Positions<double>& points = target.points();
  const size_t stride = std::max<size_t>(1, points.size() / 4000);
  r.num_samples = points.size() / stride;
  for (size_t i = 0; i < points.size(); i += stride) {
    const Vec3d q = layout.LocalToCage(world_from_local.transpose() * (points[i] - translation));
    const ClosestPoint closest = tree.Closest(q);
    if (closest.triangle < 0) continue;
    const int nearest = triangles[closest.triangle].face;
    const double along = (q - r.centroids[nearest]).dot(r.normals[nearest]);
    if (along > threshold) {
      r.outside[nearest].push_back(along);
      r.outside_spread[nearest] += ((q - r.centroids[nearest]) - along * r.normals[nearest]).squaredNorm();
    }
    if (along < -threshold) r.inside[nearest].push_back(-along);
  }
  for (int f = 0; f < num_faces; ++f) {
    if (!r.outside[f].empty()) r.outside_spread[f] /= static_cast<double>(r.outside[f].size());
  }
  return r;
}

}  // namespace opgraph
