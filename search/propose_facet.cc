// Facets (search/proposals.h).
#include <algorithm>
#include <numeric>

#include "search/proposals.h"

namespace opgraph {

std::vector<Round> ProposeFacets(const Layout& best, const FaceResiduals& residuals) {
  std::vector<Round> rounds;
  if (best.HasDetail("Bevel")) return rounds;  // a modeller bevels last
  // A faceted waist or bulge: a bisecting knife across each axis through the cage's middle, its
  // new loop scaled. Priced as a special-purpose structure: a scaled loop also bends the cage
  // toward shapes it does not explain (in a tuning run it was accepted on 9 of 60 synthetic
  // models, none of which had a KnifeCut; a loop cut's profile is the modeller's waist).
  Round waist;
  waist.gain_per_op = kStructureGainPerOp;
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3d normal = Vec3d::Unit(axis);
    build::VertexTarget loop;
    loop.box.lo[axis] = -1e-3 * best.half_extent[axis];
    loop.box.hi[axis] = 1e-3 * best.half_extent[axis];
    const Json knife = build::KnifePlane(Vec3d::Zero(), normal);
    const Json scale = build::EdgeLoopScale(loop, Vec3d::Ones());
    const std::string what = "+KnifeCut across " + build::AxisName(static_cast<build::Axis>(axis)) + ", its loop scaled";
    waist.alternatives.push_back([knife, scale, what](Layout* l) -> std::string {
      if (l->HasDetail("KnifeCut")) return "";
      l->details.push_back(knife);
      l->details.push_back(scale);
      return what;
    });
  }
  rounds.push_back(waist);
  // A ridge across a quad face with samples beyond it: a knife between two opposite edge
  // midpoints, the two new vertices raised along the face's normal (both ways across the face).
  std::vector<int> faces(residuals.centroids.size());
  std::iota(faces.begin(), faces.end(), 0);
  std::stable_sort(faces.begin(), faces.end(),
                   [&](int a, int b) { return residuals.outside[a].size() > residuals.outside[b].size(); });
  const size_t min_support = std::max<size_t>(5, residuals.num_samples / 100);
  for (size_t i = 0; i < faces.size() && i < 2; ++i) {
    const int f = faces[i];
    const Polygon& face = residuals.cage.faces[f];
    if (face.size() != 4 || residuals.outside[f].size() < min_support) break;
    std::vector<double> heights = residuals.outside[f];
    std::nth_element(heights.begin(), heights.begin() + heights.size() / 2, heights.end());
    const double rise = heights[heights.size() / 2];
    build::FaceTarget target;
    target.centers = {residuals.centroids[f]};
    target.normals = {residuals.normals[f]};
    target.expect = 1;
    Round ridge;
    for (int first = 0; first < 2; ++first) {
      const Positions<double>& v = residuals.cage.vertices;
      const Vec3d a = 0.5 * (v[face[first]] + v[face[first + 1]]);
      const Vec3d b = 0.5 * (v[face[first + 2]] + v[face[(first + 3) % 4]]);
      const double reach = 0.05 * (a - b).norm();
      std::vector<build::DisplaceGroup> groups;
      for (const Vec3d& m : {a, b}) {
        build::DisplaceGroup group;
        for (int axis = 0; axis < 3; ++axis) group.verts.box.lo[axis] = m[axis] - reach, group.verts.box.hi[axis] = m[axis] + reach;
        group.verts.expect = 1;
        group.offset = rise * residuals.normals[f];
        groups.push_back(group);
      }
      const Json knife = build::KnifeEdges(target, a, b), raise = build::VertexDisplace(groups);
      ridge.alternatives.push_back([knife, raise](Layout* l) -> std::string {
        l->details.push_back(knife);
        l->details.push_back(raise);
        return "+KnifeCut across a face, its new vertices raised";
      });
    }
    rounds.push_back(ridge);
  }
  return rounds;
}

}  // namespace opgraph
