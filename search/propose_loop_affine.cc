// Loop moves and tilts (search/proposals.h).
#include <algorithm>
#include <cmath>

#include "search/proposals.h"

namespace opgraph {
namespace {

// The residual samples (outside and inside) on faces whose centroid lies within `reach` of
// `position` along `axis`.
size_t ResidualNear(const FaceResiduals& residuals, int axis, double position, double reach) {
  size_t count = 0;
  for (size_t f = 0; f < residuals.centroids.size(); ++f) {
    if (std::abs(residuals.centroids[f][axis] - position) <= reach) {
      count += residuals.outside[f].size() + residuals.inside[f].size();
    }
  }
  return count;
}

}  // namespace

std::vector<Round> ProposeLoopMoves(const Layout& best, const FaceResiduals& residuals) {
  struct Loop {
    build::VertexTarget verts;
    int axis;
    size_t residual;
  };
  // The profile's loop groups: the boxes of its loop scales, along the profile's cut axis.
  std::vector<Loop> loops;
  const Json* cut = nullptr;
  for (const Json& op : best.profile) {
    if (op["op"] == "LoopCut") cut = &op;
    if (op["op"] != "EdgeLoopAffineScale" || cut == nullptr) continue;
    const Json& box = op["params"]["verts"]["box"];
    int axis = -1;
    for (int a = 0; a < 3; ++a) {
      if (!box[0][a].is_null()) axis = a;
    }
    if (axis < 0) continue;
    Loop loop{{Box::Parse(box, "box"), op["params"]["verts"].value("expect", -1)}, axis, 0};
    // The cage is scaled after the profile: the loop's position in the cage's frame.
    const double scale = best.scale["params"]["scale"][axis].get<double>();
    const double lo = box[0][axis].get<double>() * scale, hi = box[1][axis].get<double>() * scale;
    loop.residual = ResidualNear(residuals, axis, 0.5 * (lo + hi), 0.5 * (hi - lo) + 0.25 * std::abs(scale));
    loops.push_back(loop);
  }
  std::stable_sort(loops.begin(), loops.end(), [](const Loop& a, const Loop& b) { return a.residual > b.residual; });
  std::vector<Round> rounds;
  for (size_t i = 0; i < loops.size() && i < 2; ++i) {
    if (loops[i].residual == 0) break;
    const build::VertexTarget verts = loops[i].verts;
    // Appended to the profile, so they act on the loops before the cage is scaled.
    const Json translate = build::EdgeLoopTranslate(verts, Vec3d::Zero());
    const Json rotate = build::EdgeLoopRotate(verts, Vec3d::Zero());
    const std::string which = " on the loop group " + std::to_string(i + 1) + " nearest the residual";
    rounds.push_back(Round{{[translate, which](Layout* l) -> std::string {
                              if (l->profile.empty()) return "";
                              l->profile.push_back(translate);
                              return "+EdgeLoopAffineTranslate" + which;
                            },
                            [rotate, which](Layout* l) -> std::string {
                              if (l->profile.empty()) return "";
                              l->profile.push_back(rotate);
                              return "+EdgeLoopAffineRotate" + which;
                            }}});
  }
  return rounds;
}

}  // namespace opgraph
