#include "search/face_residuals.h"

#include <algorithm>
#include <bitset>
#include <cmath>
#include <limits>

#include "core/geometry.h"
#include "core/nearest.h"
#include "ops/sequence.h"

namespace opgraph {
namespace {

// Openings: the samples of a thin-walled vessel's cavity lie nearer its side faces than its
// mouth, so no face collects them as `inside`; the mouth shows as a face whose middle (a disc
// of 0.3 sqrt(area) about the centroid) no target sample comes near, over a floor, inside a rim
// all round (a table's underside, seen through its box's bottom face, has legs at the corners
// only).
void FindOpenings(const std::vector<Vec3d>& samples, double threshold, FaceResiduals* r) {
  const int num_faces = static_cast<int>(r->centroids.size());
  r->opening_depth.assign(num_faces, 0.0), r->opening_rim.assign(num_faces, 0.0);
  for (int f = 0; f < num_faces; ++f) {
    const double side = std::sqrt(0.5 * r->areas[f]);
    if (side < 2 * threshold) continue;  // too small to hold a rim and an opening
    const double middle = 0.3 * side;
    int covering = 0, above = 0;
    const Vec3d u = r->normals[f].unitOrthogonal(), v = r->normals[f].cross(u);
    constexpr int kSectors = 12;
    std::bitset<kSectors> rim_sectors;
    // The floor under the face's centre (a narrower disc: a subdivided cavity is a bowl).
    double floor = std::numeric_limits<double>::infinity(), rim_radius = 0.5 * side;
    for (const Vec3d& q : samples) {
      const Vec3d offset = q - r->centroids[f];
      const double along = offset.dot(r->normals[f]);
      const double radius = (offset - along * r->normals[f]).norm();
      if (std::abs(along) <= threshold) {
        if (radius < middle) ++covering;
        if (radius < 0.5 * side) rim_radius = std::min(rim_radius, radius);
        if (radius >= middle && radius < 0.75 * side) {  // the face's corners lie at 0.71 side
          const double turn = (std::atan2(offset.dot(v), offset.dot(u)) + M_PI) / (2 * M_PI);
          rim_sectors.set(std::min(kSectors - 1, static_cast<int>(turn * kSectors)));
        }
      } else if (radius < middle) {
        if (along > 0) ++above;
        if (along < 0 && radius < 0.5 * middle) floor = std::min(floor, -along);
      }
    }
    // A few stray samples (a thin rod through the middle) do not cover a face. Nothing stands
    // on an opening (a boss wider than the middle is not one); a floor nearer than twice the
    // threshold is a face fitted off the surface, or a recess the `inside` samples show; and
    // with no floor at all it is a hole through the shape (a Boolean's, ProposeThroughHoles).
    // Four corner legs, each across a sector boundary, mark at most 8 of the 12 sectors.
    if (covering > 2 || above > 2 || !(floor > 2 * threshold) || !std::isfinite(floor) ||
        rim_sectors.count() < 10) {
      continue;
    }
    r->opening_depth[f] = floor;
    r->opening_rim[f] = std::clamp(0.5 * side - rim_radius, 0.03 * side, 0.4 * side);
  }
}

}  // namespace

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
  r.outside_middle.assign(num_faces, 0);
  // Each sample belongs to the face holding its closest cage point (a centroid would hand the
  // rim of a wide face to its narrow neighbours).
  const std::vector<MeshTriangle> triangles = FanTriangulate(r.cage.faces);
  const TriangleTree tree(r.cage.vertices, triangles);
  const Positions<double>& points = target.points();
  const size_t stride = std::max<size_t>(1, points.size() / 4000);
  r.num_samples = points.size() / stride;
  std::vector<Vec3d> samples;
  samples.reserve(r.num_samples + 1);
  for (size_t i = 0; i < points.size(); i += stride) {
    const Vec3d q = layout.LocalToCage(world_from_local.transpose() * (points[i] - translation));
    samples.push_back(q);
    const ClosestPoint closest = tree.Closest(q);
    if (closest.triangle < 0) continue;
    const int nearest = triangles[closest.triangle].face;
    const double along = (q - r.centroids[nearest]).dot(r.normals[nearest]);
    if (along > threshold) {
      r.outside[nearest].push_back(along);
      const double across = ((q - r.centroids[nearest]) - along * r.normals[nearest]).squaredNorm();
      r.outside_spread[nearest] += across;
      if (across < 0.09 * 0.5 * r.areas[nearest]) ++r.outside_middle[nearest];
    }
    if (along < -threshold) r.inside[nearest].push_back(-along);
  }
  for (int f = 0; f < num_faces; ++f) {
    if (!r.outside[f].empty()) r.outside_spread[f] /= static_cast<double>(r.outside[f].size());
  }
  FindOpenings(samples, threshold, &r);
  return r;
}

}  // namespace opgraph
