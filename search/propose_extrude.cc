// Extrusions from the per-face residuals (search/proposals.h).
#include <algorithm>
#include <cmath>

#include "search/proposals.h"

namespace opgraph {
namespace {

struct FaceCandidate {
  int face;
  double height;  // signed: out > 0, in < 0
  size_t support;
  double width = 1;  // of the cap (out) or of the inset region (in)
  bool opening = false;
};

// Openings (a mouth over a floor), then faces with many samples far outside (protrusion) or
// inside (cavity), by support x height.
std::vector<FaceCandidate> FaceCandidates(const FaceResiduals& r) {
  const size_t min_support = std::max<size_t>(5, r.num_samples / 100);
  std::vector<FaceCandidate> candidates;
  for (int f = 0; f < static_cast<int>(r.centroids.size()); ++f) {
    if (r.opening_depth[f] > 0) {
      // Inset to the rim, then down to the floor (`width` as ExtrusionRound reads it).
      const double width = 1 - 2 * r.opening_rim[f] / std::sqrt(r.areas[f]);
      candidates.push_back({f, -r.opening_depth[f], std::max(min_support, r.inside[f].size()), width, true});
    }
    for (int sign : {1, -1}) {
      std::vector<double> d = sign > 0 ? r.outside[f] : r.inside[f];
      if (d.size() < min_support || (sign < 0 && r.opening_depth[f] > 0)) continue;
      std::nth_element(d.begin(), d.begin() + d.size() * 3 / 4, d.end());
      FaceCandidate candidate{f, sign * d[d.size() * 3 / 4], d.size(), 0.7};
      if (sign > 0) {
        // A narrow protrusion starts from a narrowed cap (the Extrude's width). Uniform samples
        // over a square of side L lie sqrt(1/6) L from its centre (RMS).
        const double face_spread = std::sqrt(r.areas[f] / 6.0);
        candidate.width = std::clamp(std::sqrt(r.outside_spread[f]) / std::max(face_spread, 1e-12), 0.1, 1.0);
      }
      candidates.push_back(candidate);
    }
  }
  std::sort(candidates.begin(), candidates.end(), [](const FaceCandidate& a, const FaceCandidate& b) {
    if (a.opening != b.opening) return a.opening;
    return a.support * std::abs(a.height) > b.support * std::abs(b.height);
  });
  return candidates;
}

// Faces wanting the same growth together, then the six strongest single faces. Faces facing
// one way first (a table's four legs, a chair's backrest row), then with the faces of a
// symmetric pattern on other sides (a cross's arms): a chair's legs and backrest of about the
// same height are two groups, not one.
std::vector<std::vector<FaceCandidate>> Groups(const std::vector<FaceCandidate>& candidates, const FaceResiduals& r) {
  std::vector<std::vector<FaceCandidate>> groups, patterns;
  // Each face in at most one group of either kind.
  std::vector<bool> in_facing(candidates.size(), false), in_pattern(candidates.size(), false);
  for (size_t i = 0; i < candidates.size(); ++i) {
    const FaceCandidate& a = candidates[i];
    std::vector<FaceCandidate> facing = {a}, pattern = {a};
    for (size_t j = i + 1; j < candidates.size(); ++j) {
      const FaceCandidate& b = candidates[j];
      if ((a.height > 0) != (b.height > 0) || a.opening != b.opening) continue;
      if (!(std::abs(a.height - b.height) < 0.3 * std::abs(a.height))) continue;
      const bool same_direction = r.normals[a.face].dot(r.normals[b.face]) > 0.9;
      const bool same_size =
          std::abs(static_cast<double>(b.support) - static_cast<double>(a.support)) < 0.5 * a.support;
      if (same_direction && !in_facing[i] && !in_facing[j]) facing.push_back(b), in_facing[j] = true;
      if ((same_direction || same_size) && !in_pattern[i] && !in_pattern[j]) pattern.push_back(b), in_pattern[j] = true;
    }
    if (facing.size() > 1) groups.push_back(facing);
    if (pattern.size() > facing.size()) patterns.push_back(pattern);
  }
  groups.insert(groups.end(), patterns.begin(), patterns.end());
  for (size_t i = 0; i < candidates.size() && i < 6; ++i) groups.push_back({candidates[i]});
  return groups;
}

// The faces of a group with outside samples over their middle: a protrusion that stands on the
// face (FaceResiduals::outside_middle).
std::vector<FaceCandidate> StandingOn(const std::vector<FaceCandidate>& group, const FaceResiduals& r) {
  std::vector<FaceCandidate> standing;
  for (const FaceCandidate& c : group) {
    if (r.outside_middle[c.face] > 0) standing.push_back(c);
  }
  return standing;
}

// Extrude out (a narrowed cap for a tapered wall), or Inset then Extrude in or out (a straight
// wall with a rim, as a modeller does), on one group of faces.
Round ExtrusionRound(const std::vector<FaceCandidate>& group, const FaceResiduals& r) {
  build::FaceTarget faces;
  double height = 0, width = 0, side = 0;
  const double n = static_cast<double>(group.size());
  for (const FaceCandidate& c : group) {
    faces.centers.push_back(r.centroids[c.face]);
    height += c.height / n, width += c.width / n, side += std::sqrt(r.areas[c.face]) / n;
  }
  faces.expect = static_cast<int>(group.size());
  // A shared normal keeps the selector on the same faces when an edit moves their centres.
  bool shared_normal = true, coplanar_normals = true;
  for (const FaceCandidate& c : group) {
    const double dot = r.normals[c.face].dot(r.normals[group[0].face]);
    shared_normal = shared_normal && dot > 0.99;
    coplanar_normals = coplanar_normals && dot > 1 - 1e-9;
  }
  if (shared_normal) faces.normals = {r.normals[group[0].face]}, faces.min_dot = 0.9;
  const std::string count = group.size() > 1 ? " x" + std::to_string(group.size()) : "";
  Round round;
  if (height > 0) {
    build::ExtrudeArgs extrude{faces, true, height, width};
    round.alternatives.push_back([extrude, count](Layout* l) -> std::string {
      l->details.push_back(build::Extrude(extrude));
      return "+Extrude out" + count + " " + std::to_string(extrude.height) + " width " + std::to_string(extrude.width);
    });
  }
  // Only on faces sharing one plane's normal: an inset region that folds between faces at a
  // boundary corner can differ from Blender's (ops/inset.h). A cavity always has its rim.
  if ((width < 0.8 || height < 0) && coplanar_normals) {
    const double thickness = 0.5 * (1 - width) * side;
    build::ExtrudeArgs extrude{faces, true, height};
    // A vessel's cavity is usually smoothed with the rest: its mouth also with Subdivision.
    const bool opening = std::all_of(group.begin(), group.end(), [](const FaceCandidate& c) { return c.opening; });
    for (bool subdivide : {false, true}) {
      if (subdivide && !opening) continue;
      round.alternatives.push_back([faces, extrude, thickness, count, subdivide](Layout* l) -> std::string {
        if (subdivide && l->subdivide) return "";
        l->details.push_back(build::Inset(faces, thickness));
        l->details.push_back(build::Extrude(extrude));
        l->subdivide = l->subdivide || subdivide;
        return "+Inset " + std::to_string(thickness) + ", Extrude " + (extrude.height > 0 ? "out" : "in") + count +
               " " + std::to_string(extrude.height) + (subdivide ? " + Subdivision(2)" : "");
      });
    }
  }
  return round;
}

}  // namespace

std::vector<Round> ProposeExtrusions(const Layout& /*best*/, const FaceResiduals& residuals) {
  std::vector<std::vector<FaceCandidate>> groups = Groups(FaceCandidates(residuals), residuals);
  // Openings first: a mouth over a floor is plain evidence of its cavity.
  std::stable_partition(groups.begin(), groups.end(),
                        [](const std::vector<FaceCandidate>& group) { return group[0].opening; });
  std::vector<Round> rounds;
  for (const std::vector<FaceCandidate>& group : groups) {
    rounds.push_back(ExtrusionRound(group, residuals));
    // The same round also offers the group's faces that a protrusion stands on: samples on a
    // protrusion's side wall project onto a face's edge and go to either face of the edge, so
    // the faces beside a table's four legs (the grid's edge faces, sharing an edge with each
    // leg's section) collect a share of the legs' samples at the legs' height and join their
    // group, with no sample over their middle.
    if (group[0].height <= 0) continue;
    const std::vector<FaceCandidate> standing = StandingOn(group, residuals);
    if (standing.size() > 1 && standing.size() < group.size()) {
      for (auto& alternative : ExtrusionRound(standing, residuals).alternatives) {
        rounds.back().alternatives.push_back(std::move(alternative));
      }
    }
  }
  return rounds;
}

}  // namespace opgraph
